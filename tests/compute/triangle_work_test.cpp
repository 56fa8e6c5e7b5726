// The Vulkan triangle pass's sizing (shaders/voxelize_triangles.comp) and further chunks
// (compute/src/triangle_work.h): the host lists every further chunk of the big boxes the device reports, the
// device counts the boxes' tests, marks what the CPU marks, and leaves work past the budget to the CPU.
#include "triangle_work.h"

#include "roomsense/voxelize.h"
#include "vulkan_test_env.h"

#include <random>

namespace roomsense {
namespace {

struct Soup {
  GridSpec spec;
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;
};

// `triangles` random triangles in a 120 x 40 x 90 grid: most inside a voxel or two, one in 50 spanning up to
// 2 * big voxels per axis, so that boxes of one voxel, of one chunk and of several chunks all occur.
Soup soup(std::size_t triangles, unsigned seed, float big = 20.0f) {
  Soup s;
  s.spec.nx = 120;
  s.spec.ny = 40;
  s.spec.nz = 90;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> x(-2.0f, 122.0f), y(-2.0f, 42.0f), z(-2.0f, 92.0f), unit(-1.0f, 1.0f);
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3 base(x(rng), y(rng), z(rng));
    const float size = t % 50 == 0 ? big : 1.5f;
    for (int k = 0; k < 3; ++k) {
      s.vertices.push_back(base + glm::vec3(unit(rng), unit(rng), unit(rng)) * size);
      s.indices.push_back(std::uint32_t(s.vertices.size() - 1));
    }
  }
  return s;
}

// Each box's voxel count, its tests (none for a box of one voxel), and the further chunks of the big ones.
struct Boxes {
  std::uint64_t tests = 0;
  std::vector<std::uint32_t> big;    // triangles whose boxes pass kChunkVoxels
  std::vector<std::uint32_t> extra;  // their (triangle, chunk >= 1) items, in triangle order
};

Boxes boxes(const Soup& s) {
  Boxes b;
  for (std::size_t t = 0; t < s.indices.size() / 3; ++t) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (int k = 0; k < 3; ++k) {
      lo = glm::min(lo, s.vertices[s.indices[3 * t + k]]);
      hi = glm::max(hi, s.vertices[s.indices[3 * t + k]]);
    }
    const std::uint64_t volume = std::uint64_t(box_index(hi.x, s.spec.nx) - box_index(lo.x, s.spec.nx) + 1) *
                                 std::uint64_t(box_index(hi.y, s.spec.ny) - box_index(lo.y, s.spec.ny) + 1) *
                                 std::uint64_t(box_index(hi.z, s.spec.nz) - box_index(lo.z, s.spec.nz) + 1);
    if (volume > 1) b.tests += volume;
    if (volume > compute::kChunkVoxels) b.big.push_back(std::uint32_t(t));
    const std::uint64_t chunks = (volume + compute::kChunkVoxels - 1) / compute::kChunkVoxels;
    for (std::uint64_t k = 1; k < chunks; ++k) {
      b.extra.push_back(std::uint32_t(t));
      b.extra.push_back(std::uint32_t(k));
    }
  }
  return b;
}

VoxelizeRequest triangles_of(const Soup& s) {
  VoxelizeRequest r;
  r.spec = s.spec;
  r.grid_vertices = s.vertices;
  r.indices = s.indices;
  r.mode = VoxelMode::Triangles;
  return r;
}

TEST(TriangleWork, ListsEveryFurtherChunkOfTheBigBoxes) {
  const Soup s = soup(200'000, 7);
  const Boxes want = boxes(s);
  ASSERT_GT(want.big.size(), 1000u);
  std::vector<std::uint32_t> extra;
  compute::list_extra_chunks(s.vertices, s.indices, s.spec.nx, s.spec.ny, s.spec.nz, want.big, extra);
  EXPECT_EQ(extra, want.extra);
  // The device reports the big boxes in any order: each one's items follow it.
  std::vector<std::uint32_t> reversed(want.big.rbegin(), want.big.rend()), extra_reversed;
  compute::list_extra_chunks(s.vertices, s.indices, s.spec.nx, s.spec.ny, s.spec.nz, reversed, extra_reversed);
  ASSERT_EQ(extra_reversed.size(), extra.size());
  EXPECT_EQ(extra_reversed.front(), want.big.back());
  EXPECT_EQ(extra_reversed[extra_reversed.size() - 2], want.big.front());
}

// Boxes of one voxel, of one chunk and of several, in a soup big enough for thousands of big boxes: the
// device marks what the CPU marks and counts the tests the boxes need.
TEST(TriangleWork, BigBoxesOnTheDevice) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const Soup s = soup(300'000, 9, 6.0f);  // about 10M tests: seconds, not minutes, on lavapipe
  const VoxelizeRequest r = triangles_of(s);
  const VoxelStageResult cpu = CpuVoxelStage().run(r);
  const VoxelStageResult gpu = stage->run(r);
  EXPECT_FALSE(stage->last_timings().fell_back);
  test::expect_identical(cpu, gpu);
  EXPECT_EQ(gpu.voxel_tests, boxes(s).tests);
}

// Past the budget the device hands the run to the CPU stage, which scans only near each triangle's plane.
TEST(TriangleWork, WorkPastTheBudgetGoesToTheCpu) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const Soup s = soup(20'000, 10);
  VoxelizeRequest r = triangles_of(s);
  r.test_budget = boxes(s).tests - 1;
  const VoxelStageResult gpu = stage->run(r);
  EXPECT_TRUE(stage->last_timings().fell_back);
  test::expect_identical(CpuVoxelStage().run(r), gpu);
  r.test_budget += 1;
  test::expect_identical(CpuVoxelStage().run(r), stage->run(r));
  EXPECT_FALSE(stage->last_timings().fell_back);
}

}  // namespace
}  // namespace roomsense
