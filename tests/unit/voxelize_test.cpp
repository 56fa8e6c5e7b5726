// Voxelization (Eq. 3.6/3.7, triangle mode), levels (Eq. 3.8-3.10) and their determinism.
#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "roomsense/synthetic.h"
#include "roomsense/voxelize.h"
#include "synthetic_fixture.h"
#include "../../core/src/grid/voxelize_cpu.h"

#include <gtest/gtest.h>

#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>

namespace roomsense {
namespace {

VoxelGrid voxelize(const GridSpec& spec, const std::vector<glm::vec3>& world, const std::vector<std::uint32_t>& indices,
                   VoxelMode mode, unsigned threads = 1) {
  const std::vector<glm::vec3> g = to_grid_units(world, spec);
  return voxelize_cpu({spec, g, indices, mode, 15, kDefaultVoxelTestBudget, {}}, threads);
}

// Triangle mode's reference: each triangle's corners' cells untested, every other voxel of its box (box_index per
// axis) tested; by_size counts boxes of one voxel, of at most 2 x 2 x 2, and larger.
VoxelGrid whole_boxes(const GridSpec& spec, const std::vector<glm::vec3>& g, const std::vector<std::uint32_t>& indices,
                      std::size_t (&by_size)[3]) {
  VoxelGrid want(spec);
  const auto cell = [&](const glm::vec3& v) {
    return glm::ivec3(box_index(v.x, spec.nx), box_index(v.y, spec.ny), box_index(v.z, spec.nz));
  };
  for (std::size_t t = 0; t < indices.size() / 3; ++t) {
    const glm::vec3 &a = g[indices[3 * t]], &b = g[indices[3 * t + 1]], &c = g[indices[3 * t + 2]];
    const glm::ivec3 first = glm::min(glm::min(cell(a), cell(b)), cell(c)), last = glm::max(glm::max(cell(a), cell(b)), cell(c));
    ++by_size[first == last ? 0 : glm::all(glm::lessThan(last - first, glm::ivec3(2))) ? 1 : 2];
    for (const glm::vec3* corner : {&a, &b, &c}) want.set(cell(*corner).x, cell(*corner).y, cell(*corner).z);
    for (int z = first.z; z <= last.z; ++z)
      for (int x = first.x; x <= last.x; ++x)
        for (int y = first.y; y <= last.y; ++y)
          if (triangle_overlaps_voxel(a, b, c, x, y, z)) want.set(x, y, z);
  }
  return want;
}

TEST(Voxelize, VertexModeFollowsEq36) {
  const GridSpec spec = make_grid_spec({0, 0, 0}, {1, 1, 1}, 0.25f);
  EXPECT_EQ(spec.nx, 5);  // Eq. 3.4: floor(1 / 0.25) + 1
  const VoxelGrid grid = voxelize(spec, {{0.05f, 0.55f, 0.95f}, {1, 1, 1}}, {}, VoxelMode::Vertices);
  EXPECT_EQ(grid.at(0, 2, 3), 1);
  EXPECT_EQ(grid.at(4, 4, 4), 1);
  EXPECT_EQ(std::count(grid.cells.begin(), grid.cells.end(), 1), 2);
}

TEST(Voxelize, TriangleModeMarksEveryVoxelATrianglePassesThrough) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 3.0f);
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<glm::vec3> tri = {{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    const GridSpec spec = make_grid_spec({0, 0, 0}, {3, 3, 3}, 0.1f);
    const VoxelGrid grid = voxelize(spec, tri, {0, 1, 2}, VoxelMode::Triangles);
    // Every point of the triangle lies in a marked voxel...
    for (int i = 0; i <= 60; ++i)
      for (int j = 0; i + j <= 60; ++j) {
        const glm::vec3 p = tri[0] + (tri[1] - tri[0]) * (float(i) / 60) + (tri[2] - tri[0]) * (float(j) / 60);
        const glm::ivec3 v = glm::ivec3(glm::floor(p / 0.1f));
        if (spec.contains(v.x, v.y, v.z)) { ASSERT_EQ(grid.at(v.x, v.y, v.z), 1) << "trial " << trial; }
      }
    // ...and every marked voxel touches the triangle (SAT is exact; check by the test itself).
    const std::vector<glm::vec3> g = to_grid_units(tri, spec);
    for (int z = 0; z < spec.nz; ++z)
      for (int x = 0; x < spec.nx; ++x)
        for (int y = 0; y < spec.ny; ++y)
          if (grid.at(x, y, z) && !triangle_overlaps_voxel(g[0], g[1], g[2], x, y, z)) {
            const glm::ivec3 a = glm::ivec3(glm::floor(g[0])), b = glm::ivec3(glm::floor(g[1])), c = glm::ivec3(glm::floor(g[2]));
            const glm::ivec3 here(x, y, z);
            ASSERT_TRUE(here == a || here == b || here == c) << "marked voxel off the triangle";
          }
  }
}

TEST(Voxelize, IntoAGridAddsToItsMarksAndRefusesAnotherGrid) {
  // Two triangles voxelized one at a time into one grid mark what both do at once (the incremental stage's
  // scratch grid relies on it), and a grid of other dimensions is refused, not written past.
  const GridSpec spec = make_grid_spec({0, 0, 0}, {3, 3, 3}, 0.1f);
  const std::vector<glm::vec3> world = {{0.2f, 0.1f, 0.3f}, {2.7f, 0.4f, 0.5f}, {1.1f, 2.9f, 0.2f},
                                        {0.4f, 1.3f, 2.8f}, {2.2f, 0.7f, 2.5f}, {1.6f, 2.4f, 1.9f}};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 3, 4, 5};
  const VoxelGrid both = voxelize(spec, world, indices, VoxelMode::Triangles);
  const std::vector<glm::vec3> g = to_grid_units(world, spec);
  VoxelGrid grid(spec);
  std::uint64_t tests_first = 0, tests_second = 0, tests_both = 0;
  voxelize_cpu_into({spec, g, std::span(indices).first(3), VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, grid,
                    1, &tests_first);
  const auto after_first = std::count(grid.cells.begin(), grid.cells.end(), 1);
  voxelize_cpu_into({spec, g, std::span(indices).last(3), VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, grid,
                    1, &tests_second);
  EXPECT_GT(after_first, 0);
  EXPECT_GT(std::count(grid.cells.begin(), grid.cells.end(), 1), after_first);
  EXPECT_EQ(grid.cells, both.cells);
  voxelize_cpu({spec, g, indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, 1, &tests_both);
  EXPECT_EQ(tests_first + tests_second, tests_both);
  VoxelGrid other(make_grid_spec({0, 0, 0}, {2, 3, 3}, 0.1f));
  try {
    voxelize_cpu_into({spec, g, indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, other);
    FAIL() << "a grid of other dimensions was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::BadParameter);
  }
}

TEST(Voxelize, AMeshOfSharedVerticesMarksExactlyWhatTheTestAcceptsInEachBox) {
  // A jittered lattice of shared vertices (the corners' cells found once per vertex), its triangles from one
  // voxel to boxes of a few and of many voxels: the marks are exactly the box voxels the test accepts, plus the
  // voxel of each one-voxel box, and the same when each triangle is voxelized alone (cells found per triangle).
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> jitter(-0.04f, 0.04f);
  const GridSpec spec = make_grid_spec({-0.1f, -0.1f, -0.1f}, {2.1f, 2.1f, 2.1f}, 0.1f);
  constexpr int kSide = 21;
  std::vector<glm::vec3> world;
  for (int k = 0; k < kSide; ++k)
    for (int i = 0; i < kSide; ++i)
      world.push_back({0.1f * float(i) + jitter(rng), 1.0f + 0.3f * std::sin(0.7f * float(i + k)) + jitter(rng),
                       0.1f * float(k) + jitter(rng)});
  std::vector<std::uint32_t> indices;
  for (int k = 0; k + 1 < kSide; ++k)
    for (int i = 0; i + 1 < kSide; ++i) {
      const std::uint32_t a = std::uint32_t(k * kSide + i), b = a + 1, c = a + kSide, d = c + 1;
      indices.insert(indices.end(), {a, b, d, a, d, c});
    }
  indices.insert(indices.end(), {0, kSide * kSide - 1, kSide - 1});  // one triangle across the whole grid
  ASSERT_GE(indices.size(), 2 * world.size());
  const std::vector<glm::vec3> g = to_grid_units(world, spec);
  std::size_t by_size[3] = {0, 0, 0};  // one voxel, at most 2 x 2 x 2, more
  const VoxelGrid want = whole_boxes(spec, g, indices, by_size);
  for (const std::size_t n : by_size) EXPECT_GT(n, 0u);
  EXPECT_EQ(voxelize(spec, world, indices, VoxelMode::Triangles, 2).cells, want.cells);
  VoxelGrid alone(spec);
  for (std::size_t t = 0; t < indices.size() / 3; ++t)
    voxelize_cpu_into({spec, g, std::span(indices).subspan(3 * t, 3), VoxelMode::Triangles, 15,
                       kDefaultVoxelTestBudget, {}},
                      alone, 1);
  EXPECT_EQ(alone.cells, want.cells);
}

// Corners past a grid's edges, on them and a test epsilon off them (and some near the grid), in grid units, shared
// by 150 random triangles.
std::pair<std::vector<glm::vec3>, std::vector<std::uint32_t>> corners_at_the_edges(const GridSpec& spec, unsigned seed) {
  std::mt19937 rng(seed);
  const auto coordinate = [&](int n) {
    const float e = kVoxelTestEpsilon;
    const float picks[] = {-3.0f, -1e9f, -e, -0.5f * e, 0.0f, float(n - 1) - e, float(n - 1) - 0.5f * e, float(n - 1),
                           float(n - 1) + 0.4f, float(n) + 2.0f, 1e9f, float(n / 2) - e};
    const float near = std::uniform_real_distribution<float>(-1.5f, float(n) + 0.5f)(rng);
    return rng() % 3 == 0 ? near : picks[rng() % std::size(picks)];
  };
  std::vector<glm::vec3> g;
  for (int i = 0; i < 60; ++i) g.push_back({coordinate(spec.nx), coordinate(spec.ny), coordinate(spec.nz)});
  std::vector<std::uint32_t> indices;
  for (int t = 0; t < 150; ++t)
    for (int k = 0; k < 3; ++k) indices.push_back(std::uint32_t(rng() % g.size()));
  return {g, indices};
}

// Corners past the grid's edges, on them, and a test epsilon off them land where box_index puts them (the edge
// voxel past an edge), as one scan's vertices shared by many triangles and as a few triangles' own.
TEST(Voxelize, CornersPastTheGridLandWhereBoxIndexPutsThem) {
  const GridSpec spec = make_grid_spec({0, 0, 0}, {2, 1.5f, 2.5f}, 0.25f);
  const auto [g, indices] = corners_at_the_edges(spec, 17);
  std::size_t by_size[3] = {0, 0, 0};
  const VoxelGrid want = whole_boxes(spec, g, indices, by_size);
  for (const std::size_t n : by_size) EXPECT_GT(n, 0u);
  // Every vertex's cell found first (triangles >= 2 x vertices), and each triangle's own (a chunk of a few).
  EXPECT_EQ(voxelize_cpu({spec, g, indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, 2).cells, want.cells);
  VoxelGrid alone(spec);
  for (std::size_t t = 0; t < indices.size() / 3; ++t)
    voxelize_cpu_into({spec, g, std::span(indices).subspan(3 * t, 3), VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}},
                      alone, 1);
  EXPECT_EQ(alone.cells, want.cells);
}

// to_grid_units converts whole fours of vertices at a time: every vertex is (v - origin) / voxel size exactly,
// whatever the count and however the threads' slices cut the vertices.
TEST(Voxelize, GridUnitsAreEachVertexsOwnFormula) {
  const GridSpec spec = make_grid_spec({-1.3f, 0.2f, 5.1f}, {4.0f, 3.1f, 9.7f}, 0.07f);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{4}, std::size_t{7},
                              std::size_t{33}, std::size_t{50001}}) {
    std::vector<glm::vec3> world(n);
    for (glm::vec3& v : world) v = {coordinate(rng), coordinate(rng), coordinate(rng)};
    for (const unsigned threads : {1u, 2u, 3u}) {
      const std::vector<glm::vec3> g = to_grid_units(world, spec, threads);
      ASSERT_EQ(g.size(), n);
      for (std::size_t i = 0; i < n; ++i)
        for (int axis = 0; axis < 3; ++axis)
          ASSERT_EQ(g[i][axis], (world[i][axis] - spec.origin[axis]) / spec.voxel_size)
              << "vertex " << i << " of " << n << ", axis " << axis << ", " << threads << " threads";
    }
  }
}

// Where the CPU has SSE4.1, the voxelizer's hottest loops run a copy built for it (voxelize_cpu.h): it marks the
// voxels and counts the tests the baseline copy does, on whole rooms (every vertex's cell found first) and on
// corners past the grid's edges and on them (a few triangles' cells found as they go), on one and two threads.
TEST(Voxelize, TheSse41CopyMarksWhatTheBaselineMarks) {
  if (!detail::voxel_sse41_copy()) GTEST_SKIP() << "no SSE4.1 copy on this CPU or build: one copy of the loops";
  const auto both = [](const VoxelizeRequest& request, const char* what) {
    for (const unsigned threads : {1u, 2u}) {
      VoxelGrid best(request.spec), baseline(request.spec);
      std::uint64_t best_tests = 0, baseline_tests = 0;
      detail::voxelize_cpu_into(request, best, threads, &best_tests, detail::VoxelInstructions::Best);
      detail::voxelize_cpu_into(request, baseline, threads, &baseline_tests, detail::VoxelInstructions::Baseline);
      EXPECT_EQ(best.cells, baseline.cells) << what << ", " << threads << " threads";
      EXPECT_EQ(best_tests, baseline_tests) << what << ", " << threads << " threads";
      EXPECT_GT(std::count(best.cells.begin(), best.cells.end(), 1), 0) << what;
    }
  };
  for (const char* room : {"synthetic:thesis-room1", "synthetic:rotated", "synthetic:house"}) {
    const Scan scan = synth::generate_builtin_source(room);
    const PreparedInput in = prepare_input(scan);
    const GridSpec spec = make_grid_spec(in.lo, in.hi, kDefaultVoxelSize);
    const std::vector<glm::vec3> g = to_grid_units(in.vertices, spec);
    both({spec, g, in.indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, room);
    both({spec, g, std::span(in.indices).first(300), VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, room);
  }
  const GridSpec spec = make_grid_spec({0, 0, 0}, {2, 1.5f, 2.5f}, 0.25f);
  const auto [g, indices] = corners_at_the_edges(spec, 23);
  both({spec, g, indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}, "corners past the edges");
}

TEST(Voxelize, AFaceOnAVoxelBoundaryLandsInTheUpperVoxelOnly) {
  // A floor exactly at y = 1.0 with voxels of 0.25 m (exact in binary): level 4, as a vertex would be.
  const GridSpec spec = make_grid_spec({0, 0, 0}, {2, 2, 2}, 0.25f);
  const VoxelGrid grid = voxelize(spec, {{0, 1, 0}, {2, 1, 0}, {2, 1, 2}, {0, 1, 2}}, {0, 2, 1, 0, 3, 2},
                                  VoxelMode::Triangles);
  const std::vector<std::uint32_t> levels = count_levels(grid);
  EXPECT_EQ(levels[4], std::uint32_t(spec.nx * spec.nz));
  EXPECT_EQ(levels[3], 0u);
}

TEST(Voxelize, LargeTriangleRoomWorksInTriangleModeOnly) {
  // The thesis's room 4: walls and floor of a few large triangles leave vertex mode with only corners.
  const Scan scan = synth::generate(synth::large_triangle_room());
  EXPECT_LT(scan.indices.size() / 3, 200u);
  const AnalysisResult tri = analyze(scan);
  ASSERT_TRUE(tri.ok()) << tri.status_message;
  EXPECT_NEAR(tri.floor_y, 0.0f, 0.05f);
  EXPECT_NEAR(tri.ceiling_y, 2.6f, 0.05f);
  EXPECT_GT(std::count(tri.features->free_floor.begin(), tri.features->free_floor.end(), 1), 1000);
  AnalysisOptions vertices;
  vertices.mode = VoxelMode::Vertices;
  const AnalysisResult vtx = analyze(scan, vertices);
  const bool vertex_mode_fails = !vtx.ok() || std::count(vtx.features->free_floor.begin(), vtx.features->free_floor.end(), 1) < 100;
  EXPECT_TRUE(vertex_mode_fails);
}

TEST(Levels, SelectionFollowsEq39And310) {
  std::vector<std::uint32_t> counts(40, 0);
  counts[3] = 100;
  counts[10] = 90;  // too close to 3
  counts[30] = 80;
  auto fc = select_floor_ceiling(counts, 15);
  ASSERT_TRUE(fc);
  EXPECT_EQ(fc->floor, 3);
  EXPECT_EQ(fc->ceiling, 30);
  counts[30] = 0;
  counts[25] = 0;
  EXPECT_FALSE(select_floor_ceiling(counts, 15));  // nothing 1.5 m from the fullest level
  EXPECT_FALSE(select_floor_ceiling(std::vector<std::uint32_t>(10, 0), 15));
}

TEST(Levels, AFloorStraddlingALevelBoundaryIsOneBand) {
  std::vector<std::uint32_t> counts(40, 1);
  counts[3] = 100;
  counts[4] = 40;  // the same floor, a voxel higher in places
  counts[30] = 80;
  counts[29] = 10;  // below the share: not part of the ceiling
  const auto fc = select_floor_ceiling(counts, 15);
  ASSERT_TRUE(fc);
  EXPECT_EQ(fc->floor_peak, 3);
  EXPECT_EQ(fc->floor, 4);
  EXPECT_EQ(fc->ceiling, 30);
}

TEST(Levels, SyntheticRoomsMatchTheirFloorAndCeiling) {
  for (const std::string& name : synth::builtin_names()) {
    const test::AnalysedRoom& room = test::analysed(*synth::builtin(name));
    ASSERT_TRUE(room.result.ok()) << name << ": " << room.result.status_message;
    EXPECT_NEAR(room.result.floor_y, room.spec.floor_y, 0.03f) << name;
    EXPECT_NEAR(room.result.ceiling_y, room.spec.ceiling_y, 0.03f) << name;
    EXPECT_EQ(room.result.storeys.size(), 1u) << name;
  }
}

TEST(Levels, NoCeilingIsAStatusNotACrash) {
  synth::RoomSpec flat = synth::default_room();
  Scan scan = synth::generate(flat);
  // Keep only the floor: vertices above 0.2 m go, with their triangles.
  Scan floor_only;
  std::vector<std::uint32_t> remap(scan.vertices.size(), UINT32_MAX);
  for (std::size_t i = 0; i < scan.vertices.size(); ++i)
    if (scan.vertices[i].y < 0.2f) {
      remap[i] = std::uint32_t(floor_only.vertices.size());
      floor_only.vertices.push_back(scan.vertices[i]);
    }
  for (std::size_t t = 0; t < scan.indices.size(); t += 3) {
    const std::uint32_t a = remap[scan.indices[t]], b = remap[scan.indices[t + 1]], c = remap[scan.indices[t + 2]];
    if (a != UINT32_MAX && b != UINT32_MAX && c != UINT32_MAX) floor_only.indices.insert(floor_only.indices.end(), {a, b, c});
  }
  const AnalysisResult r = analyze(floor_only);
  EXPECT_EQ(r.status, AnalysisStatus::NoFloorCeiling);
  EXPECT_FALSE(r.status_message.empty());
  EXPECT_TRUE(r.bounds.indices.empty());
}

TEST(Determinism, ResultsDoNotDependOnTheThreadCount) {
  const Scan scan = synth::generate(synth::rotated_room(30.0f));
  AnalysisOptions one, many;
  one.threads = 1;
  many.threads = 7;
  const AnalysisResult a = analyze(scan, one), b = analyze(scan, many), c = analyze(scan, many);
  EXPECT_EQ(a.voxels.grid.cells, b.voxels.grid.cells);
  EXPECT_EQ(a.voxels.column_counts, b.voxels.column_counts);
  EXPECT_EQ(a.features->walls, b.features->walls);
  EXPECT_EQ(a.features->furniture, b.features->furniture);
  EXPECT_EQ(a.features->free_floor, b.features->free_floor);
  EXPECT_EQ(a.features->free_ceiling, b.features->free_ceiling);
  EXPECT_EQ(a.features->normals, b.features->normals);
  EXPECT_EQ(a.bounds.vertices, b.bounds.vertices);
  EXPECT_EQ(a.bounds.indices, b.bounds.indices);
  EXPECT_EQ(b.bounds.indices, c.bounds.indices);
}

}  // namespace
}  // namespace roomsense
