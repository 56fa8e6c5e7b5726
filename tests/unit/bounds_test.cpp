// Room bounds (§3.6): the volume I, its mesh, closure, orientation.
#include "roomsense/analysis.h"
#include "roomsense/bounds.h"
#include "roomsense/error.h"
#include "roomsense/queries.h"
#include "roomsense/surfaces.h"
#include "roomsense/synthetic.h"
#include "mesh_checks.h"
#include "same_features.h"
#include "synthetic_fixture.h"
#include "../../core/src/bounds/mesh_memo.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <string>
#include <tuple>

namespace roomsense {
namespace {

using test::signed_volume;

std::size_t solid_count(const std::vector<std::uint8_t>& v) { return std::size_t(std::count(v.begin(), v.end(), 1)); }

// A storey's grid on `levels`: solid at and below the floor and at and above the ceiling, with random furniture
// heights and ceiling clutter, which leave plane holes to fill everywhere (three of four neighbours solid).
VoxelGrid cluttered_storey(const GridSpec& s, const FloorCeiling& levels, std::mt19937& rng) {
  VoxelGrid grid;
  grid.spec = s;
  grid.cells.assign(s.voxel_count(), 0);
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      for (int y = 0; y <= levels.floor; ++y) grid.cells[s.index(x, y, z)] = 1;
      for (int y = levels.ceiling; y < s.ny; ++y) grid.cells[s.index(x, y, z)] = 1;
      if (pick(rng) % 3 == 0) grid.cells[s.index(x, levels.floor + 1 + pick(rng) % 6, z)] = 1;   // below y_end
      if (pick(rng) % 4 == 0) grid.cells[s.index(x, levels.ceiling - 1 - pick(rng) % 5, z)] = 1;  // and above it
    }
  return grid;
}

// A random box of 1-4 x 1-5 x 1-4 voxels between the floor and the ceiling, its columns in [lo, hi], set to `value`.
void edit_box(VoxelGrid& grid, const FloorCeiling& levels, glm::ivec2 lo, glm::ivec2 hi, std::uint8_t value,
              std::mt19937& rng) {
  const GridSpec& s = grid.spec;
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  const int w = 1 + pick(rng) % 4, d = 1 + pick(rng) % 4, h = 1 + pick(rng) % 5;
  const int x0 = lo.x + pick(rng) % (hi.x - lo.x + 1 - w + 1), z0 = lo.y + pick(rng) % (hi.y - lo.y + 1 - d + 1);
  const int y0 = levels.floor + 1 + pick(rng) % (levels.ceiling - levels.floor - h);
  for (int z = z0; z < z0 + d; ++z)
    for (int x = x0; x < x0 + w; ++x)
      for (int y = y0; y < y0 + h; ++y) grid.cells[s.index(x, y, z)] = value;
}

// The mesh of `volume` is closed, encloses its solid voxels, covers each voxel face exactly once with whole
// triangles, and has no vertex inside a flat patch.
void expect_exact_mesh(const GridSpec& s, const std::vector<std::uint8_t>& volume, const BoundsMesh& m,
                       double volume_tolerance, double area_tolerance, const std::string& what = {}) {
  const MeshClosure c = check_closure(m);
  EXPECT_EQ(c.boundary_or_nonmanifold_edges, 0u) << what;
  EXPECT_EQ(c.misoriented_edges, 0u) << what;
  const double cell = double(s.voxel_size) * s.voxel_size * s.voxel_size;
  EXPECT_NEAR(signed_volume(m), double(solid_count(volume)) * cell, volume_tolerance) << what;
  const test::TriangleStats st = test::triangle_stats(m, s.voxel_size);
  EXPECT_NEAR(st.area, test::voxel_face_area(s, volume), area_tolerance) << what;
  EXPECT_EQ(st.degenerate, 0u) << what;
  EXPECT_EQ(st.flat_vertices, 0u) << what;
}

TEST(MeshVolume, OneVoxelIsACube) {
  const GridSpec s = make_grid_spec({0, 0, 0}, {0.25f, 0.25f, 0.25f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  volume[s.index(1, 1, 1)] = 1;
  const BoundsMesh m = mesh_volume(s, volume);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.indices.size(), 36u);
  EXPECT_TRUE(check_closure(m).closed());
  EXPECT_NEAR(signed_volume(m), 0.001, 1e-7);
}

TEST(MeshVolume, RandomVolumesGiveClosedOutwardSurfacesOfTheRightVolume) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 30; ++trial) {
    const GridSpec s = make_grid_spec({0, 0, 0}, {0.75f, 0.55f, 0.65f}, 0.1f);
    std::vector<std::uint8_t> volume(s.voxel_count());
    std::bernoulli_distribution solid(trial % 2 ? 0.3 : 0.7);
    for (auto& v : volume) v = solid(rng) ? 1 : 0;
    fill_edge_contacts(s, volume);
    const BoundsMesh m = mesh_volume(s, volume);
    expect_exact_mesh(s, volume, m, 1e-5, 1e-6, "trial " + std::to_string(trial));
    // Each position once.
    std::vector<glm::vec3> sorted = m.vertices;
    std::sort(sorted.begin(), sorted.end(), [](auto a, auto b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  }
}

// The mesh does not depend on the threads: each axis is meshed in parts of its slices on the pool and the parts are
// appended in order. Every fourth grid is one voxel thick along an axis, so one part of that axis has no slice.
TEST(MeshVolume, AnyNumberOfThreadsGivesTheSameMesh) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    const float thin = 0.05f;
    glm::vec3 extent{1.15f, 0.85f, 0.95f};
    if (trial % 4 == 3) extent[trial / 4 % 3] = thin;
    const GridSpec s = make_grid_spec({0, 0, 0}, extent, 0.1f);
    std::vector<std::uint8_t> volume(s.voxel_count());
    std::bernoulli_distribution solid(0.2 + 0.6 * (trial % 3) / 2.0);
    for (auto& v : volume) v = solid(rng) ? 1 : 0;
    fill_edge_contacts(s, volume, 1);
    const BoundsMesh one = mesh_volume(s, volume, 1);
    for (const unsigned threads : {2u, 3u, 5u}) {
      const BoundsMesh many = mesh_volume(s, volume, threads);
      ASSERT_EQ(many.vertices, one.vertices) << "trial " << trial << ", " << threads << " threads";
      ASSERT_EQ(many.indices, one.indices) << "trial " << trial << ", " << threads << " threads";
    }
    expect_exact_mesh(s, volume, one, 1e-5, 1e-5, "trial " + std::to_string(trial));
  }
}

// An IncrementalAnalysis's edge contacts (mesh_memo.h's EdgeContactMemo): a volume filled with the memo of the
// volume before it, which asks again only the blocks beside a changed column, is filled as without it; the box and
// the columns it tells mesh_volume (FilledVolume) are the filled volume's, and the mesh made with them and the mesh
// memo is the mesh made afresh. Edits add and clear boxes of diagonal voxels (contacts to fill, and fills that
// reach past the edit or go), raise and lower the solid box's levels (all asked again) and change nothing at all;
// the memo's grid changes once.
TEST(FillEdgeContacts, AMemoFillsEachEditedVolumeAsFillingItAfresh) {
  std::mt19937 rng(5);
  GridSpec s = make_grid_spec({0, 0, 0}, {3.0f, 1.2f, 2.6f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  detail::MeshMemo memo;
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  std::size_t filled_some = 0;
  for (int edit = 0; edit < 80; ++edit) {
    if (edit == 40) {  // another grid: the memo starts again
      s = make_grid_spec({0, 0, 0}, {2.2f, 1.0f, 3.1f}, 0.1f);
      volume.assign(s.voxel_count(), 0);
    }
    if (edit % 9 != 8) {  // every ninth edit changes nothing
      const int w = 1 + pick(rng) % 5, d = 1 + pick(rng) % 5, h = 1 + pick(rng) % 4;
      const int x0 = pick(rng) % (s.nx - w + 1), z0 = pick(rng) % (s.nz - d + 1);
      // Mostly in the middle levels; every fifth edit at the grid's top or bottom, moving the solid box's levels.
      const int y0 = edit % 5 == 4 ? (edit % 10 == 4 ? 0 : s.ny - h) : 2 + pick(rng) % (s.ny - h - 3);
      const bool clear = edit % 4 == 3;
      for (int z = z0; z < z0 + d; ++z)
        for (int x = x0; x < x0 + w; ++x)
          for (int y = y0; y < y0 + h; ++y)
            volume[s.index(x, y, z)] = clear ? 0 : std::uint8_t((x + y + z) % 2 == 0 || pick(rng) % 3 == 0);
    }
    std::vector<std::uint8_t> afresh = volume, with_memo = volume;
    fill_edge_contacts(s, afresh);
    const detail::FilledVolume filled = detail::fill_edge_contacts(s, with_memo, 2, &memo.contacts);
    ASSERT_EQ(with_memo, afresh) << "edit " << edit;
    EXPECT_EQ(filled.box, detail::solid_box(s, afresh, 1)) << "edit " << edit;
    const BoundsMesh meshed = detail::mesh_volume(s, with_memo, 2, {}, &memo, &filled), fresh = mesh_volume(s, afresh);
    ASSERT_EQ(meshed.vertices, fresh.vertices) << "edit " << edit;
    ASSERT_EQ(meshed.indices, fresh.indices) << "edit " << edit;
    filled_some += afresh != volume ? 1 : 0;
  }
  EXPECT_GT(filled_some, 40u);  // the edits leave contacts to fill
}

// An IncrementalAnalysis's bounds (mesh_memo.h): a volume meshed with the memo of the volume before it, which
// replays the slices and keeps the surface corners where nothing changed, gives the mesh meshing it afresh gives,
// point for point, also after a cancelled one. Boxes are added and cleared, small (the corners beside them found
// again) and large (all found again), next to each other, at the solid box's faces and over a previous edit.
TEST(MeshVolume, AMemoMeshesEachEditedVolumeAsMeshingItAfresh) {
  std::mt19937 rng(7);
  const GridSpec s = make_grid_spec({0, 0, 0}, {4.0f, 1.6f, 3.6f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  // A floor and a ceiling over the whole grid keep the solid box, so the memo is taken.
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) volume[s.index(x, 0, z)] = volume[s.index(x, s.ny - 1, z)] = 1;
  detail::MeshMemo memo;
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  for (int edit = 0; edit < 60; ++edit) {
    const int w = edit % 10 == 9 ? 14 : 1 + pick(rng) % 4, d = 1 + pick(rng) % 4, h = 1 + pick(rng) % 6;
    const int x0 = pick(rng) % (s.nx - w + 1), z0 = pick(rng) % (s.nz - d + 1), y0 = pick(rng) % (s.ny - h + 1);
    const std::uint8_t value = edit % 3 == 2 ? 0 : 1;
    for (int z = z0; z < z0 + d; ++z)
      for (int x = x0; x < x0 + w; ++x)
        for (int y = y0; y < y0 + h; ++y) volume[s.index(x, y, z)] = value;
    std::vector<std::uint8_t> filled = volume;
    fill_edge_contacts(s, filled);
    const BoundsMesh afresh = mesh_volume(s, filled);
    if (edit % 7 == 6) {  // a cancelled mesh leaves a memo the next one can use
      std::stop_source cancel;
      cancel.request_stop();
      try {
        detail::mesh_volume(s, filled, 2, cancel.get_token(), &memo);
        ADD_FAILURE() << "edit " << edit << ": not cancelled";
      } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Cancelled);
      }
    }
    const BoundsMesh memoized = detail::mesh_volume(s, filled, 2, {}, &memo);
    ASSERT_EQ(memoized.vertices, afresh.vertices) << "edit " << edit;
    ASSERT_EQ(memoized.indices, afresh.indices) << "edit " << edit;
  }
}

// An IncrementalAnalysis's bounds volume (mesh_memo.h's StoreyVolumeMemo): a grid's volume derived with the memo
// of the grid before it, G and H found again only in the columns that changed and the volume written again only
// where they changed and beside them, equals the volume derived afresh, byte for byte. A cluttered storey; boxes
// are added and cleared; a cancelled derivation and a changed storey (y_end, the room's columns) in between.
TEST(BoundsVolume, AMemoDerivesEachEditedVolumeAsDerivingItAfresh) {
  std::mt19937 rng(11);
  const GridSpec s = make_grid_spec({0, 0, 0}, {3.0f, 1.9f, 2.6f}, 0.1f);
  const FloorCeiling levels{1, s.ny - 2, 1, s.ny - 2};
  VoxelGrid grid = cluttered_storey(s, levels, rng);
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  std::vector<std::uint8_t> room(s.column_count(), 1);
  for (int k = 0; k < 20; ++k) room[std::size_t(pick(rng)) % room.size()] = 0;
  BoundsStorey storey{levels, levels.floor + 7, &room, nullptr};
  detail::MeshMemo memo;
  for (int edit = 0; edit < 80; ++edit) {
    edit_box(grid, levels, {0, 0}, {s.nx - 1, s.nz - 1}, edit % 3 == 2 ? 0 : 1, rng);
    if (edit % 20 == 10) storey.y_end += 1;                      // a storey read otherwise: derived whole
    if (edit % 20 == 15) room[std::size_t(pick(rng)) % room.size()] ^= 1;
    const std::vector<std::uint8_t> afresh = bounds_volume(grid, std::span(&storey, 1));
    if (edit % 9 == 8) {  // a cancelled derivation leaves a memo the next one can use
      std::stop_source cancel;
      cancel.request_stop();
      EXPECT_THROW(detail::bounds_volume(grid, std::span(&storey, 1), {}, 2, cancel.get_token(), &memo), Error);
    }
    const std::vector<std::uint8_t> memoized = detail::bounds_volume(grid, std::span(&storey, 1), {}, 2, {}, &memo);
    ASSERT_EQ(memoized, afresh) << "edit " << edit;
  }
}

// A room's bounds through its memo (mesh_memo.h): the room's volume derived again only in the columns of its crop
// whose cells changed, its mesh meshed again only through the slices that changed, equal the room's bounds built
// afresh. Edits inside the room and in the margin around it; a cancelled build and a changed room in between.
TEST(BoundsVolume, ARoomsMemoBuildsEachEditedRoomAsBuildingItAfresh) {
  std::mt19937 rng(13);
  const GridSpec s = make_grid_spec({0, 0, 0}, {4.0f, 1.9f, 3.0f}, 0.1f);
  const FloorCeiling levels{1, s.ny - 2, 1, s.ny - 2};
  VoxelGrid grid = cluttered_storey(s, levels, rng);
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  // The storey's columns, and a room of them: x in [8, 30), z in [5, 25).
  std::vector<std::uint8_t> storey_room(s.column_count(), 1), room(s.column_count(), 0);
  for (int z = 5; z < 25; ++z)
    for (int x = 8; x < 30; ++x) room[s.column(x, z)] = 1;
  const BoundsStorey storey{levels, levels.floor + 7, &storey_room, nullptr};
  detail::MeshMemo memo;
  for (int edit = 0; edit < 60; ++edit) {
    edit_box(grid, levels, {6, 3}, {31, 26}, edit % 3 == 2 ? 0 : 1, rng);  // in the room and its margin
    if (edit % 20 == 15) room[s.column(8 + pick(rng) % 22, 5 + pick(rng) % 20)] ^= 1;  // built whole
    const BoundsMesh afresh = build_room_bounds(grid, storey, room);
    if (edit % 9 == 8) {  // a cancelled build leaves a memo the next one can use (an unchanged room is the memo's)
      std::stop_source cancel;
      cancel.request_stop();
      try {
        detail::build_room_bounds(grid, storey, room, {}, 2, cancel.get_token(), &memo);
      } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Cancelled);
      }
    }
    const BoundsMesh memoized = detail::build_room_bounds(grid, storey, room, {}, 2, {}, &memo);
    ASSERT_EQ(memoized.vertices, afresh.vertices) << "edit " << edit;
    ASSERT_EQ(memoized.indices, afresh.indices) << "edit " << edit;
  }
}

TEST(MeshVolume, RandomBoxStacksGiveExactSurfaces) {
  // Unions and cuts of boxes: large face regions with holes, notches and touching corners, the shapes of
  // furniture on a floor, where the hole bridges and T-junctions matter. Every third grid is 3 m high, its boxes
  // at any height (the surface corners are found eight levels at a time where four columns are alike).
  std::mt19937 rng(7);
  for (int trial = 0; trial < 90; ++trial) {
    const bool tall = trial % 3 == 2;
    const GridSpec s = make_grid_spec({0, 0, 0}, {2.35f, tall ? 2.95f : 0.95f, 2.05f}, 0.1f);
    std::vector<std::uint8_t> volume(s.voxel_count(), 0);
    std::uniform_int_distribution<int> x(0, s.nx - 1), y(0, s.ny - 1), z(0, s.nz - 1), len(1, 8);
    for (int box = 0; box < 25; ++box) {
      const int x0 = x(rng), y0 = tall ? y(rng) : y(rng) / 2, z0 = z(rng);
      const int w = len(rng), h = len(rng) / 2 + 1, d = len(rng);
      const std::uint8_t value = box % 4 == 3 ? 0 : 1;  // every fourth box carves
      for (int k = z0; k < std::min(s.nz, z0 + d); ++k)
        for (int i = x0; i < std::min(s.nx, x0 + w); ++i)
          for (int j = y0; j < std::min(s.ny, y0 + h); ++j) volume[s.index(i, j, k)] = value;
    }
    fill_edge_contacts(s, volume);
    expect_exact_mesh(s, volume, mesh_volume(s, volume), 1e-5, 1e-5, "trial " + std::to_string(trial));
  }
}

TEST(MeshVolume, AFloorAmongHundredsOfPillarsIsOneRegionWithHundredsOfHoles) {
  // The top of a slab pierced by 676 pillars: one polygon with 676 holes, every one bridged.
  const GridSpec s = make_grid_spec({0, 0, 0}, {7.95f, 0.35f, 7.95f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      volume[s.index(x, 0, z)] = 1;
      if (x % 3 == 1 && z % 3 == 1)
        for (int y = 1; y < 3; ++y) volume[s.index(x, y, z)] = 1;
    }
  expect_exact_mesh(s, volume, mesh_volume(s, volume), 1e-5, 1e-5);
}

TEST(MeshVolume, EdgeContactsAreFilled) {
  const GridSpec s = make_grid_spec({0, 0, 0}, {0.25f, 0.15f, 0.25f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  volume[s.index(0, 0, 0)] = 1;
  volume[s.index(1, 0, 1)] = 1;  // touches the first along one edge only
  fill_edge_contacts(s, volume);
  EXPECT_EQ(volume[s.index(1, 0, 0)], 1);
  EXPECT_EQ(volume[s.index(0, 0, 1)], 1);
  EXPECT_TRUE(check_closure(mesh_volume(s, volume)).closed());
}

// fill_edge_contacts as defined: every 2x2 block around every edge, in order, whole passes until one fills
// nothing. The library skips blocks that cannot fill; it must fill exactly these voxels.
std::vector<std::uint8_t> edge_contacts_by_full_passes(const GridSpec& s, std::vector<std::uint8_t> v) {
  const auto settle = [](std::uint8_t& p, std::uint8_t& q, std::uint8_t& r, std::uint8_t& t) {
    if (p && q && !r && !t) return r = t = 1, true;
    if (r && t && !p && !q) return p = q = 1, true;
    return false;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x)
        for (int y = 0; y < s.ny; ++y) {
          const auto at = [&](int dx, int dy, int dz) -> std::uint8_t& { return v[s.index(x + dx, y + dy, z + dz)]; };
          if (x + 1 < s.nx && z + 1 < s.nz) changed |= settle(at(0, 0, 0), at(1, 0, 1), at(1, 0, 0), at(0, 0, 1));
          if (y + 1 < s.ny && x + 1 < s.nx) changed |= settle(at(0, 0, 0), at(1, 1, 0), at(1, 0, 0), at(0, 1, 0));
          if (y + 1 < s.ny && z + 1 < s.nz) changed |= settle(at(0, 0, 0), at(0, 1, 1), at(0, 0, 1), at(0, 1, 0));
        }
  }
  return v;
}

TEST(MeshVolume, EdgeContactsFillWhatWholePassesFill) {
  // Columns mostly copied from a neighbour (a room's volume is), with random specks: blocks of equal
  // columns, contacts that take several passes, and fills that make a settled block fillable again. Grids
  // of 8, 21 and 70 levels (the library tests eight levels at a time, the last few one by one), and solid
  // voxels that are not 1 (any non-zero byte is solid).
  std::mt19937 rng(7);
  for (int trial = 0; trial < 240; ++trial) {
    const float height = trial % 3 == 0 ? 0.75f : trial % 3 == 1 ? 2.05f : 6.95f;
    const GridSpec s = make_grid_spec({0, 0, 0}, {0.95f, height, 0.85f}, 0.1f);
    std::vector<std::uint8_t> volume(s.voxel_count(), 0);
    std::bernoulli_distribution solid(0.15 + 0.05 * (trial % 8)), copy(trial % 4 == 0 ? 0.0 : 0.8);
    const std::uint8_t one = trial % 5 == 0 ? 0x80 : trial % 5 == 1 ? 2 : 1;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x)
        for (int y = 0; y < s.ny; ++y)
          volume[s.index(x, y, z)] = x > 0 && copy(rng) ? volume[s.index(x - 1, y, z)] : solid(rng) ? one : 0;
    const std::vector<std::uint8_t> expected = edge_contacts_by_full_passes(s, volume);
    // On two threads the blocks that may fill are found side by side (slices of at least 4 rows of columns: these
    // grids' 9 rows are two), then filled in order.
    std::vector<std::uint8_t> on_two = volume;
    fill_edge_contacts(s, volume);
    ASSERT_EQ(volume, expected) << "trial " << trial;
    fill_edge_contacts(s, on_two, 2);
    ASSERT_EQ(on_two, expected) << "trial " << trial << ", two threads";
  }
}

TEST(Bounds, SyntheticRoomsGiveClosedMeshesFacingFreeSpace) {
  for (const std::string& name : synth::builtin_names()) {
    const test::AnalysedRoom& room = test::analysed(*synth::builtin(name));
    const AnalysisResult& r = room.result;
    ASSERT_TRUE(r.ok()) << name;
    std::vector<std::uint8_t> volume = bounds_volume(r.voxels.grid, bounds_storeys(r));
    fill_edge_contacts(r.voxels.grid.spec, volume);
    expect_exact_mesh(r.voxels.grid.spec, volume, r.bounds, 1e-3, 1e-3, name);
    if (r.input.triangles > 10000) {
      EXPECT_LT(r.bounds.indices.size() / 3, r.input.triangles / 15) << name;
    }
  }
}

TEST(MeshVolume, ARegionWithAHoleTouchingItsBorderAndTJunctions) {
  // A slab with a notch and a hole in its top, a hole touching the slab's edge at a corner, and a post on
  // it whose corners split the top's border: the cases the region tracing and hole bridges must get right.
  const GridSpec s = make_grid_spec({0, 0, 0}, {0.95f, 0.45f, 0.95f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  for (int z = 1; z < 9; ++z)
    for (int x = 1; x < 9; ++x) volume[s.index(x, 0, z)] = volume[s.index(x, 1, z)] = 1;
  for (int z = 3; z < 5; ++z)
    for (int x = 3; x < 5; ++x) volume[s.index(x, 1, z)] = 0;  // hole in the top layer
  volume[s.index(1, 1, 1)] = 0;                                // notch at a corner
  volume[s.index(2, 2, 2)] = 1;  // a stub: a hole in the top face touching the notch at one point
  for (int y = 2; y < 4; ++y) volume[s.index(6, y, 6)] = 1;      // a post
  std::vector<std::uint8_t> settled = volume;
  fill_edge_contacts(s, settled);
  ASSERT_EQ(settled, volume) << "no edge contact to fill: the touching point stays";
  expect_exact_mesh(s, volume, mesh_volume(s, volume), 1e-6, 1e-6);
}

TEST(MeshVolume, AFlatSlabHasEightCornersAndTwelveTriangles) {
  // Whatever its size, a solid slab is a box: its corners and nothing else.
  const GridSpec s = make_grid_spec({0, 0, 0}, {2.05f, 0.25f, 1.05f}, 0.1f);
  std::vector<std::uint8_t> volume(s.voxel_count(), 1);
  const BoundsMesh m = mesh_volume(s, volume);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.indices.size() / 3, 12u);
}

TEST(Bounds, SmallPlateausAreFlattenedAndLargerOnesKept) {
  // A post of one column and a block of 4 x 4 columns in the default room: by default the post's plateau
  // (0.01 m²) is below 0.04 m² and goes, the block (0.16 m²) stays; with the step off both stay.
  synth::RoomSpec spec = synth::default_room();
  spec.name = "default+post";
  spec.boxes.push_back({{1.55f, -0.45f}, {0.04f, 0.04f}, 1.0f, 0.0f});
  spec.boxes.push_back({{1.0f, -1.2f}, {0.4f, 0.4f}, 1.0f, 0.0f});
  const test::AnalysedRoom& room = test::analysed(spec);
  const AnalysisResult& r = room.result;
  ASSERT_TRUE(r.ok());
  const GridSpec& s = r.voxels.grid.spec;
  const FloorCeiling& l = *r.voxels.levels;
  const auto column = [&](float x, float z) {
    return std::pair{int((x - s.origin.x) / s.voxel_size), int((z - s.origin.z) / s.voxel_size)};
  };
  const auto [px, pz] = column(1.55f, -0.45f);
  const auto [bx, bz] = column(1.0f, -1.2f);
  const int y = l.floor + int(0.6f / s.voxel_size);  // below both tops
  ASSERT_TRUE(r.voxels.grid.at(px, y, pz)) << "the post is in V";
  const std::vector<std::uint8_t> flattened = bounds_volume(r.voxels.grid, l, r.features->y_end, r.features->room);
  const std::vector<std::uint8_t> kept =
      bounds_volume(r.voxels.grid, l, r.features->y_end, r.features->room, BoundsParams{0.0f});
  EXPECT_EQ(flattened[s.index(px, y, pz)], 0);
  EXPECT_EQ(kept[s.index(px, y, pz)], 1);
  EXPECT_EQ(flattened[s.index(bx, y, bz)], 1);
  EXPECT_EQ(kept[s.index(bx, y, bz)], 1);
}

TEST(Bounds, PlateausJustBelowTheSmallestSizeAreFlattenedWhateverTheirShape) {
  // Posts of two levels on a flat floor, each plateau one column short of the smallest size kept or just at it:
  // a pair and a bent three at 3 columns, a 2 x 2 block and a plus at 5. Every column of a small plateau has
  // fewer neighbours of its height than the size less one, the test that spares searches from large ones.
  GridSpec s;
  s.nx = 16, s.ny = 6, s.nz = 16, s.voxel_size = 0.1f;
  VoxelGrid grid(s);
  std::vector<std::uint8_t> room(s.column_count(), 1);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) grid.cells[s.index(x, 0, z)] = grid.cells[s.index(x, 5, z)] = 1;
  const auto post = [&](std::initializer_list<std::pair<int, int>> columns) {
    for (const auto& [x, z] : columns) grid.cells[s.index(x, 1, z)] = grid.cells[s.index(x, 2, z)] = 1;
  };
  post({{2, 2}, {3, 2}});                          // a pair
  post({{8, 2}, {9, 2}, {9, 3}});                  // three, bent
  post({{2, 8}, {3, 8}, {2, 9}, {3, 9}});          // a 2 x 2 block
  post({{9, 8}, {8, 9}, {9, 9}, {10, 9}, {9, 10}});  // a plus
  const FloorCeiling levels{0, 5, 0, 5};
  const auto standing = [&](float min_area, int x, int z) {
    return bounds_volume(grid, levels, 3, room, BoundsParams{min_area})[s.index(x, 1, z)] != 0;
  };
  // 3 columns at least (0.03 m²): the pair goes, the bent three stays.
  EXPECT_FALSE(standing(0.03f, 2, 2));
  EXPECT_TRUE(standing(0.03f, 9, 2));
  // 5 columns at least: the block goes, the plus stays; so does a pair at 2 columns.
  EXPECT_FALSE(standing(0.05f, 3, 9));
  EXPECT_TRUE(standing(0.05f, 9, 9));
  EXPECT_TRUE(standing(0.02f, 3, 2));
}

// BoundsParams::min_plateau_area as bounds.h states it, on G or H: in passes until one flattens nothing (at most
// eight), every plateau (room columns of one height, 4-connected) as the pass begins, in order of its first
// column, if smaller than `min_cells` columns, takes the height its border shares most with it as the pass has
// left it (on a tie the nearer, then the lower).
void flatten_by_definition(const GridSpec& s, const std::vector<std::uint8_t>& room, int min_cells,
                           std::vector<int>& height) {
  for (int pass = 0; pass < 8; ++pass) {
    std::vector<int> label(height.size(), -1);
    std::vector<std::vector<std::size_t>> plateaus;
    for (std::size_t start = 0; start < height.size(); ++start) {
      if (!room[start] || label[start] >= 0) continue;
      std::vector<std::size_t> cells{start}, stack{start};
      label[start] = int(plateaus.size());
      while (!stack.empty()) {
        const std::size_t c = stack.back();
        stack.pop_back();
        const int x = int(c % std::size_t(s.nx)), z = int(c / std::size_t(s.nx));
        for (const auto& [nx, nz] : {std::pair{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}}) {
          if (nx < 0 || nz < 0 || nx >= s.nx || nz >= s.nz) continue;
          const std::size_t n = s.column(nx, nz);
          if (!room[n] || label[n] >= 0 || height[n] != height[start]) continue;
          label[n] = label[start];
          cells.push_back(n);
          stack.push_back(n);
        }
      }
      plateaus.push_back(cells);
    }
    bool flattened = false;
    for (const std::vector<std::size_t>& p : plateaus) {  // in order of their first column
      if (int(p.size()) >= min_cells) continue;
      const int h = height[p[0]];
      std::map<int, int> border;  // height -> shared edges
      for (const std::size_t c : p) {
        const int x = int(c % std::size_t(s.nx)), z = int(c / std::size_t(s.nx));
        for (const auto& [nx, nz] : {std::pair{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}})
          if (nx >= 0 && nz >= 0 && nx < s.nx && nz < s.nz && room[s.column(nx, nz)] && height[s.column(nx, nz)] != h)
            ++border[height[s.column(nx, nz)]];
      }
      if (border.empty()) continue;
      const auto best = std::min_element(border.begin(), border.end(), [&](const auto& a, const auto& b) {
        return std::tuple(-a.second, std::abs(a.first - h), a.first) <
               std::tuple(-b.second, std::abs(b.first - h), b.first);
      });
      for (const std::size_t c : p) height[c] = best->first;
      flattened = true;
    }
    if (!flattened) return;
  }
}

// bounds_volume as Eq. 3.60-3.62, the flattening above (`min_cells` columns; 0: none) and §3.6's hole filling
// define it, voxel by voxel.
std::vector<std::uint8_t> bounds_volume_by_definition(const VoxelGrid& grid, const BoundsStorey& storey,
                                                      int min_cells) {
  const GridSpec& s = grid.spec;
  const FloorCeiling& l = storey.levels;
  const int y_end = std::clamp(storey.y_end, l.floor + 1, l.ceiling - 1);
  std::vector<int> gs(s.column_count()), hs(s.column_count());
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const std::size_t col = s.column(x, z);
      const bool room = (*storey.room)[col] != 0;
      const int ceiling = std::min((*storey.ceiling)[col], l.ceiling);
      int g = room ? l.floor : -1, h = room ? l.ceiling : l.ceiling + 1;
      for (int y = l.floor + 1; y <= std::min(y_end, ceiling - 1); ++y)
        if (grid.at(x, y, z)) g = y;
      for (int y = l.ceiling - 1; y >= y_end; --y)
        if (grid.at(x, y, z)) h = y;
      if (room && ceiling < l.ceiling) h = std::min(h, std::max(ceiling, l.floor + 1));
      gs[col] = g, hs[col] = h;
    }
  flatten_by_definition(s, *storey.room, min_cells, gs);
  flatten_by_definition(s, *storey.room, min_cells, hs);
  std::vector<std::uint8_t> volume(s.voxel_count(), 0);
  for (std::size_t col = 0; col < s.column_count(); ++col)
    for (int y = l.floor; y <= l.ceiling; ++y)
      volume[col * std::size_t(s.ny) + std::size_t(y)] = y <= gs[col] || y >= hs[col] ? 1 : 0;
  const auto at = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < s.nx && y < s.ny && z < s.nz ? int(volume[s.index(x, y, z)]) : 0;
  };
  std::vector<std::uint8_t> filled = volume;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      for (int y = l.floor; y <= l.ceiling; ++y) {
        const int left = at(x - 1, y, z), right = at(x + 1, y, z), back = at(x, y, z - 1), front = at(x, y, z + 1),
                  down = at(x, y - 1, z), up = at(x, y + 1, z);
        if (left + right + back + front >= 3 || left + right + down + up >= 3 || down + up + back + front >= 3)
          filled[s.index(x, y, z)] = 1;
      }
  return filled;
}

TEST(Bounds, TheVolumeIsTheThesisVolumeWithSmallPlateausFlattenedAndItsHolesFilled) {
  // Random grids of voxels in columns of a few runs, random rooms and ceilings, levels from the grid's bottom to
  // its top and inside it, storeys of 10 to 120 levels. The hole filling reads 64 levels at a time: every other
  // trial puts the runs' ends (G or H) about the 64th and 128th level of the storey.
  std::mt19937 rng(11);
  for (int trial = 0; trial < 160; ++trial) {
    GridSpec s;
    s.nx = 9 + trial % 5, s.nz = 7 + trial % 4, s.voxel_size = 0.1f;
    s.ny = std::array{12, 40, 70, 135}[std::size_t(trial / 2 % 4)];
    const int floor = trial % 3 == 0 ? 0 : int(rng() % 3);
    const int ceiling = trial % 5 < 2 ? s.ny - 1 : s.ny - 1 - int(rng() % 3);
    const bool at_words = trial % 2 == 1, g_at_words = at_words && trial / 8 % 2 == 0;
    const int y_end = !at_words  ? floor + int(rng() % std::uint32_t(ceiling - floor))
                      : g_at_words ? ceiling - 1
                                   : floor + 1;
    VoxelGrid grid(s);
    std::vector<std::uint8_t> room(s.column_count());
    std::vector<int> ceilings(s.column_count());
    std::uniform_int_distribution<int> level(0, s.ny - 1);
    for (std::size_t col = 0; col < s.column_count(); ++col) {
      room[col] = rng() % 4 != 0;
      ceilings[col] = rng() % 3 == 0 ? level(rng) : ceiling;
      for (int run = int(rng() % 4); run > 0; --run) {
        // A run ending (for G) or starting (for H) a level or two from the storey's 63rd or 127th level above
        // its floor (bit 0 of the second or third word holds level floor + 63 or + 127); else anywhere.
        const int edge = floor + (rng() % 2 == 0 ? 62 : 126) + int(rng() % 4);
        const int length = int(rng() % 6);
        const int a = !at_words ? level(rng) : g_at_words ? edge - length : edge;
        const int b = std::min(s.ny - 1, a + length);
        for (int y = std::max(a, 0); y <= b; ++y) grid.cells[col * std::size_t(s.ny) + std::size_t(y)] = 1;
      }
    }
    const BoundsStorey storey{{floor, ceiling, 0, 0}, y_end, &room, &ceilings};
    EXPECT_EQ(bounds_volume(grid, std::span(&storey, 1), BoundsParams{0.0f}),
              bounds_volume_by_definition(grid, storey, 0))
        << "trial " << trial << ": " << s.ny << " levels, " << floor << " to " << ceiling;
    // Plateaus of up to 2, 4 and 8 columns flattened (0.03, 0.05 and 0.09 m² at 0.1 m).
    const float area = std::array{0.03f, 0.05f, 0.09f}[std::size_t(trial % 3)];
    EXPECT_EQ(bounds_volume(grid, std::span(&storey, 1), BoundsParams{area}),
              bounds_volume_by_definition(grid, storey, int(std::lround(area * 100.0f))))
        << "trial " << trial << ", plateaus below " << area << " m² flattened";
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

// Without the areas, analyze() builds the bounds beside the heights' sums, for every storey the levels give, and
// again without a storey the heights then drop (less than 1.5 m between its surfaces). The same meshes as a run
// with the areas, which builds them after the heights: on rooms with furniture, two storeys, several rooms, a
// sloped ceiling, and a house with an attic whose levels are 15 apart but whose surfaces are 1.42 m apart.
TEST(AnalyzeBounds, BuiltBesideTheHeightsTheyEqualTheBoundsBuiltAfterThem) {
  synth::HouseSpec attic_house = synth::two_storey_house();
  synth::RoomSpec attic;
  attic.name = attic_house.name;
  attic.outline = attic_house.storeys[0].outline;
  // At this grid's origin its floor and ceiling levels are 15 apart: the levels make it a third storey, which the
  // heights drop (checked with a print in analyze(): three pairs of levels, two storeys kept).
  attic.floor_y = 5.46f;
  attic.ceiling_y = attic.floor_y + 1.42f;
  attic.seed = 23;
  attic_house.storeys.push_back(attic);
  const std::pair<const char*, Scan> rooms[] = {
      {"synthetic:thesis-room1", synth::generate_builtin_source("synthetic:thesis-room1")},
      {"synthetic:house", synth::generate_builtin_source("synthetic:house")},
      {"synthetic:flat", synth::generate_builtin_source("synthetic:flat")},
      {"synthetic:loft", synth::generate_builtin_source("synthetic:loft")},
      {"house with a low attic", synth::generate(attic_house)}};
  for (const auto& [name, scan] : rooms) {
    SCOPED_TRACE(name);
    AnalysisOptions bounds_only;
    bounds_only.find_areas = false;
    const AnalysisResult a = analyze(scan, bounds_only), b = analyze(scan);
    ASSERT_TRUE(a.ok());
    ASSERT_TRUE(b.ok());
    EXPECT_FALSE(a.bounds.indices.empty());
    test::expect_same_bounds(a, b);
    EXPECT_EQ(a.storeys.size(), b.storeys.size());
  }
  // The attic is dropped: two storeys are left of its three pairs of levels.
  EXPECT_EQ(analyze(rooms[4].second).storeys.size(), 2u);
}

// A bounds-only run without the areas' features (AnalysisOptions::area_features off, as StartRoomBounds runs) skips
// C, D, F and the openings and nothing the bounds read: the same bounds, room bounds, levels, heights, storeys and
// rooms as with them, on rooms with furniture, two storeys, several rooms and a sloped ceiling. What reads the
// skipped features gets none: no furniture tops among the surfaces, empty queries.
TEST(AnalyzeBounds, WithoutTheAreasFeaturesGivesTheSameBoundsLevelsAndRooms) {
  for (const char* room : {"synthetic:thesis-room1", "synthetic:house", "synthetic:flat", "synthetic:loft"}) {
    SCOPED_TRACE(room);
    const Scan scan = synth::generate_builtin_source(room);
    AnalysisOptions all;
    all.find_areas = false;
    AnalysisOptions lean = all;
    lean.area_features = false;
    const AnalysisResult a = analyze(scan, all), b = analyze(scan, lean);
    ASSERT_TRUE(a.ok());
    ASSERT_TRUE(b.ok());
    test::expect_same_bounds(b, a);
    EXPECT_EQ(b.floor_y, a.floor_y);
    EXPECT_EQ(b.ceiling_y, a.ceiling_y);
    ASSERT_EQ(b.storeys.size(), a.storeys.size());
    for (std::size_t i = 0; i < a.storeys.size(); ++i) {
      EXPECT_EQ(b.storeys[i].floor_y, a.storeys[i].floor_y);
      EXPECT_EQ(b.storeys[i].ceiling_y, a.storeys[i].ceiling_y);
      // Every feature the same but the four skipped, which are empty.
      RoomFeatures skipped = a.storey_features(std::uint32_t(i));
      EXPECT_FALSE(skipped.furniture.empty() || skipped.free_floor.empty() || skipped.normals.empty());
      skipped.furniture.clear(), skipped.free_floor.clear(), skipped.normals.clear(), skipped.wall_blocked.clear();
      test::expect_same_features(b.storey_features(std::uint32_t(i)), skipped);
    }
    EXPECT_EQ(b.rooms.size(), a.rooms.size());
    for (const Surface& surface : extract_surfaces(b))
      EXPECT_TRUE(surface.kind != SurfaceKind::Table && surface.kind != SurfaceKind::Furniture);
    EXPECT_TRUE(RoomQueries(b).empty());
    EXPECT_FALSE(RoomQueries(a).empty());
  }
}

}  // namespace
}  // namespace roomsense
