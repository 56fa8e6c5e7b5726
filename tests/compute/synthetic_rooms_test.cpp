// CPU vs Vulkan, bit for bit, on generated inputs: the project's synthetic rooms (synthetic/), and
// triangle soups built to hit the edge cases of the SAT test and of the level/column passes.
#include "roomsense/grid.h"
#include "roomsense/input.h"
#include "roomsense/synthetic.h"
#include "vulkan_test_env.h"

#include <cmath>
#include <random>

namespace roomsense {
namespace {

VoxelizeRequest request_of(const GridSpec& spec, const std::vector<glm::vec3>& grid_vertices,
                           const std::vector<std::uint32_t>& indices, VoxelMode mode, int min_separation = 15) {
  VoxelizeRequest r;
  r.spec = spec;
  r.grid_vertices = grid_vertices;
  r.indices = indices;
  r.mode = mode;
  r.min_separation_levels = min_separation;
  return r;
}

void check_both_modes(VulkanVoxelStage& stage, const GridSpec& spec, const std::vector<glm::vec3>& grid_vertices,
                      const std::vector<std::uint32_t>& indices, int min_separation = 15) {
  for (VoxelMode mode : {VoxelMode::Vertices, VoxelMode::Triangles}) {
    SCOPED_TRACE(mode == VoxelMode::Triangles ? "triangle mode" : "vertex mode");
    const VoxelizeRequest r = request_of(spec, grid_vertices, indices, mode, min_separation);
    const VoxelStageResult cpu = CpuVoxelStage().run(r);
    ValidationScope validation(stage);
    const VoxelStageResult gpu = stage.run(r);
    EXPECT_FALSE(stage.last_timings().fell_back);
    test::expect_identical(cpu, gpu);
  }
}

GridSpec grid(int nx, int ny, int nz) {
  GridSpec s;
  s.nx = nx;
  s.ny = ny;
  s.nz = nz;
  return s;
}

class SyntheticRoom : public ::testing::TestWithParam<std::string> {};

TEST_P(SyntheticRoom, VulkanMatchesCpuBitForBit) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const std::optional<synth::RoomSpec> spec = synth::builtin(GetParam());
  ASSERT_TRUE(spec.has_value());
  const PreparedInput in = prepare_input(synth::generate(*spec));
  const GridSpec g = make_grid_spec(in.lo, in.hi, kDefaultVoxelSize);
  check_both_modes(*stage, g, to_grid_units(in.vertices, g), in.indices);
}

INSTANTIATE_TEST_SUITE_P(Builtin, SyntheticRoom, ::testing::ValuesIn(synth::builtin_names()),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(SyntheticRoom, RotatedAndFineVoxels) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  for (float yaw : {7.0f, 33.0f, 45.0f}) {
    const PreparedInput in = prepare_input(synth::generate(synth::rotated_room(yaw)));
    for (float voxel : {0.05f, 0.1f, 0.23f}) {
      SCOPED_TRACE("yaw " + std::to_string(yaw) + " voxel " + std::to_string(voxel));
      const GridSpec g = make_grid_spec(in.lo, in.hi, voxel);
      check_both_modes(*stage, g, to_grid_units(in.vertices, g), in.indices, int(std::lround(1.5f / voxel)));
    }
  }
}

// Random soups in grid units, including vertices outside the grid (clamped like Eq. 3.6 clamps).
TEST(TriangleSoup, RandomTriangles) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  std::mt19937 rng(12345);
  for (int round = 0; round < 6; ++round) {
    const GridSpec g = grid(17 + round * 5, 23 + round * 3, 11 + round * 7);
    std::uniform_real_distribution<float> u(-1.5f, 1.0f);
    std::uniform_real_distribution<float> size(0.0f, round % 2 == 0 ? 2.0f : 12.0f);
    std::vector<glm::vec3> v;
    std::vector<std::uint32_t> idx;
    for (int t = 0; t < 4000; ++t) {
      const glm::vec3 base((u(rng) + 1.5f) / 2.5f * float(g.nx), (u(rng) + 1.5f) / 2.5f * float(g.ny),
                           (u(rng) + 1.5f) / 2.5f * float(g.nz));
      for (int k = 0; k < 3; ++k) {
        v.push_back(base + glm::vec3(u(rng), u(rng), u(rng)) * size(rng));
        idx.push_back(std::uint32_t(v.size() - 1));
      }
    }
    check_both_modes(*stage, g, v, idx, 3 + round);
  }
}

// Faces and edges exactly on voxel boundaries, vertices one ulp either side of them, degenerate triangles:
// where the shrunk upper faces (kVoxelTestEpsilon) and the exact comparisons decide.
TEST(TriangleSoup, LatticeAlignedAndDegenerate) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const GridSpec g = grid(24, 20, 24);
  std::vector<glm::vec3> v;
  std::vector<std::uint32_t> idx;
  const auto tri = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    for (const glm::vec3& p : {a, b, c}) {
      v.push_back(p);
      idx.push_back(std::uint32_t(v.size() - 1));
    }
  };
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cell(1, 18);
  const auto ulp = [](float x, float dir) { return std::nextafter(x, dir); };
  for (int i = 0; i < 800; ++i) {
    const float x = float(cell(rng)), y = float(cell(rng)), z = float(cell(rng));
    const float w = float(cell(rng) % 5), h = float(cell(rng) % 4 + 1);
    switch (i % 8) {
      case 0: tri({x, y, z}, {x + w, y, z}, {x, y + h, z}); break;                         // in the plane z = k
      case 1: tri({x, y, z}, {x, y, z + w}, {x, y + h, z + w}); break;                     // in the plane x = k
      case 2: tri({x, y, z}, {x + w, y, z}, {x + w, y, z + h}); break;                     // floor-like, y = k
      case 3: tri({ulp(x, 0), y, z}, {ulp(x, 0), ulp(y + h, 99), z}, {ulp(x, 0), y, z + w + 1}); break;
      case 4: tri({ulp(x, 99), y, z}, {x + w + 0.5f, y, z}, {x, y, ulp(z + h, 0)}); break;
      case 5: tri({x, y, z}, {x + w, y + h, z + w}, {x + 2 * w, y + 2 * h, z + 2 * w}); break;  // collinear
      case 6: tri({x, y, z}, {x, y, z}, {x + w + 1, y + h, z}); break;                     // two equal vertices
      default: tri({x + 0.5f, y, z + 0.5f}, {x + 0.5f + w, y + h, z + 0.5f}, {x + 0.5f, y + h, z + 0.5f + w}); break;
    }
  }
  check_both_modes(*stage, g, v, idx, 5);
}

// A few triangles spanning the whole grid: one invocation walks a large bounding box.
TEST(TriangleSoup, LargeTriangles) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const GridSpec g = grid(60, 30, 50);
  const std::vector<glm::vec3> v = {{0.0f, 0.0f, 0.0f},   {60.0f, 0.0f, 0.0f},  {0.0f, 0.0f, 50.0f},
                                    {60.0f, 29.5f, 50.0f}, {0.3f, 15.2f, 0.1f}, {59.9f, 1.1f, 49.7f},
                                    {-5.0f, 10.0f, 25.0f}, {70.0f, 20.0f, -3.0f}, {30.0f, 40.0f, 60.0f}};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 1, 3, 2, 4, 5, 3, 6, 7, 8};
  check_both_modes(*stage, g, v, idx, 10);
}

// Grids where the level passes hit their edges: one level, no second level far enough, a separation of 1.
TEST(TriangleSoup, LevelSelectionEdgeCases) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const std::vector<glm::vec3> v = {{0.5f, 0.5f, 0.5f}, {3.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 3.5f},
                                    {0.5f, 1.5f, 0.5f}, {2.5f, 1.5f, 2.5f}, {1.5f, 2.5f, 1.5f}};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 4, 5};
  check_both_modes(*stage, grid(4, 1, 4), {v[0], v[1], v[2]}, {0, 1, 2}, 1);  // a single level
  check_both_modes(*stage, grid(4, 3, 4), v, idx, 15);                        // nothing far enough apart
  check_both_modes(*stage, grid(4, 3, 4), v, idx, 1);                         // bands that cross
  check_both_modes(*stage, grid(5, 4, 3), {}, {}, 2);                         // empty grid
}

// The buffers are reused and grown across runs of different sizes; results stay exact throughout.
TEST(TriangleSoup, BuffersReusedAcrossSizes) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  std::mt19937 rng(99);
  for (int n : {40, 8, 64, 16, 64}) {
    const GridSpec g = grid(n, n / 2 + 3, n);
    std::uniform_real_distribution<float> u(0.0f, float(n));
    std::vector<glm::vec3> v;
    std::vector<std::uint32_t> idx;
    for (int i = 0; i < 3 * n * 10; ++i) {
      v.push_back({u(rng), u(rng) / 2.0f, u(rng)});
      idx.push_back(std::uint32_t(i));
    }
    check_both_modes(*stage, g, v, idx, 2);
  }
}

}  // namespace
}  // namespace roomsense
