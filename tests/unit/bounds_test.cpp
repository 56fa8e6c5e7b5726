// Room bounds (§3.6): the volume I, greedy meshing, closure, orientation.
#include "roomsense/bounds.h"
#include "roomsense/synthetic.h"
#include "synthetic_fixture.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <random>

namespace roomsense {
namespace {

// Signed volume by the divergence theorem: positive when the faces point out of the solid.
double signed_volume(const BoundsMesh& m) {
  double v = 0.0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::dvec3 a = m.vertices[m.indices[t]], b = m.vertices[m.indices[t + 1]], c = m.vertices[m.indices[t + 2]];
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

std::size_t solid_count(const std::vector<std::uint8_t>& v) { return std::size_t(std::count(v.begin(), v.end(), 1)); }

TEST(GreedyMesh, OneVoxelIsACube) {
  const GridSpec s = make_grid_spec({0, 0, 0}, {0.25f, 0.25f, 0.25f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  volume[s.index(1, 1, 1)] = 1;
  const BoundsMesh m = greedy_mesh(s, volume);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.indices.size(), 36u);
  EXPECT_TRUE(check_closure(m).closed());
  EXPECT_NEAR(signed_volume(m), 0.001, 1e-7);
}

TEST(GreedyMesh, RandomVolumesGiveClosedOutwardSurfacesOfTheRightVolume) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 30; ++trial) {
    const GridSpec s = make_grid_spec({0, 0, 0}, {0.75f, 0.55f, 0.65f}, 0.1f);
    std::vector<std::uint8_t> volume(s.voxel_count());
    std::bernoulli_distribution solid(trial % 2 ? 0.3 : 0.7);
    for (auto& v : volume) v = solid(rng) ? 1 : 0;
    fill_edge_contacts(s, volume);
    const BoundsMesh m = greedy_mesh(s, volume);
    const MeshClosure c = check_closure(m);
    EXPECT_EQ(c.boundary_or_nonmanifold_edges, 0u) << "trial " << trial;
    EXPECT_EQ(c.misoriented_edges, 0u) << "trial " << trial;
    EXPECT_NEAR(signed_volume(m), double(solid_count(volume)) * 0.001, 1e-5) << "trial " << trial;
    // Each position once.
    std::vector<glm::vec3> sorted = m.vertices;
    std::sort(sorted.begin(), sorted.end(), [](auto a, auto b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  }
}

TEST(GreedyMesh, EdgeContactsAreFilled) {
  const GridSpec s = make_grid_spec({0, 0, 0}, {0.25f, 0.15f, 0.25f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  volume[s.index(0, 0, 0)] = 1;
  volume[s.index(1, 0, 1)] = 1;  // touches the first along one edge only
  fill_edge_contacts(s, volume);
  EXPECT_EQ(volume[s.index(1, 0, 0)], 1);
  EXPECT_EQ(volume[s.index(0, 0, 1)], 1);
  EXPECT_TRUE(check_closure(greedy_mesh(s, volume)).closed());
}

TEST(Bounds, SyntheticRoomsGiveClosedMeshesFacingFreeSpace) {
  for (const std::string& name : synth::builtin_names()) {
    const test::AnalysedRoom& room = test::analysed(*synth::builtin(name));
    const AnalysisResult& r = room.result;
    ASSERT_TRUE(r.ok()) << name;
    const MeshClosure c = check_closure(r.bounds);
    EXPECT_TRUE(c.closed()) << name << ": " << c.boundary_or_nonmanifold_edges << " open, "
                            << c.misoriented_edges << " misoriented edges";
    std::vector<std::uint8_t> volume =
        bounds_volume(r.voxels.grid, *r.voxels.levels, r.features->y_end, r.features->room);
    fill_edge_contacts(r.voxels.grid.spec, volume);
    const double s = r.voxels.grid.spec.voxel_size;
    EXPECT_NEAR(signed_volume(r.bounds), double(solid_count(volume)) * s * s * s, 1e-3) << name;
    if (r.input.triangles > 10000) {
      EXPECT_LT(r.bounds.indices.size() / 3, r.input.triangles / 15) << name;
    }
  }
}

TEST(Bounds, TheRoomIsHollowAndTheFloorIsSolid) {
  const test::AnalysedRoom& room = test::analysed(synth::default_room());
  const AnalysisResult& r = room.result;
  const GridSpec& s = r.voxels.grid.spec;
  const std::vector<std::uint8_t> volume =
      bounds_volume(r.voxels.grid, *r.voxels.levels, r.features->y_end, r.features->room);
  const int cx = int((1.5f - s.origin.x) / s.voxel_size), cz = int((-0.5f - s.origin.z) / s.voxel_size);
  const FloorCeiling& l = *r.voxels.levels;
  EXPECT_EQ(volume[s.index(cx, l.floor, cz)], 1);
  EXPECT_EQ(volume[s.index(cx, l.ceiling, cz)], 1);
  for (int y = l.floor + 1; y < l.ceiling; ++y) EXPECT_EQ(volume[s.index(cx, y, cz)], 0) << "level " << y;
  // Under the table: filled up to its top (unreachable space, §3.6).
  const int tx = int((0.6f - s.origin.x) / s.voxel_size), tz = int((0.4f - s.origin.z) / s.voxel_size);
  EXPECT_EQ(volume[s.index(tx, l.floor + 3, tz)], 1);
}

}  // namespace
}  // namespace roomsense
