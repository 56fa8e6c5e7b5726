// The Vulkan triangle pass's work list (compute/src/triangle_work.h): one thread or several list the same
// items, the budget stops the list early, and the device marks what the CPU marks when the list was split.
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

TEST(TriangleWork, ThreadsListTheSameItemsAsOne) {
  const Soup s = soup(600'000, 7);
  compute::TriangleWork one, four;
  ASSERT_TRUE(compute::build_triangle_work(s.vertices, s.indices, s.spec.nx, s.spec.ny, s.spec.nz, ~std::uint64_t{0}, one, 1));
  ASSERT_TRUE(compute::build_triangle_work(s.vertices, s.indices, s.spec.nx, s.spec.ny, s.spec.nz, ~std::uint64_t{0}, four, 4));
  EXPECT_EQ(one.tests, four.tests);
  EXPECT_EQ(one.extra, four.extra);
  // Every big box's extra chunks, and only those, in triangle order.
  std::uint64_t tests = 0;
  std::vector<std::uint32_t> expected;
  for (std::size_t t = 0; t < s.indices.size() / 3; ++t) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (int k = 0; k < 3; ++k) {
      lo = glm::min(lo, s.vertices[s.indices[3 * t + k]]);
      hi = glm::max(hi, s.vertices[s.indices[3 * t + k]]);
    }
    const std::uint64_t volume = std::uint64_t(box_index(hi.x, s.spec.nx) - box_index(lo.x, s.spec.nx) + 1) *
                                 std::uint64_t(box_index(hi.y, s.spec.ny) - box_index(lo.y, s.spec.ny) + 1) *
                                 std::uint64_t(box_index(hi.z, s.spec.nz) - box_index(lo.z, s.spec.nz) + 1);
    if (volume > 1) tests += volume;
    for (std::uint64_t k = 1; k < (volume + compute::kChunkVoxels - 1) / compute::kChunkVoxels; ++k) {
      expected.push_back(std::uint32_t(t));
      expected.push_back(std::uint32_t(k));
    }
  }
  EXPECT_EQ(one.tests, tests);
  EXPECT_EQ(one.extra, expected);
  EXPECT_GT(expected.size(), 10'000u);  // the soup has big boxes
}

TEST(TriangleWork, StopsAtTheBudget) {
  const Soup s = soup(600'000, 8);
  for (unsigned threads : {1u, 4u}) {
    compute::TriangleWork w;
    EXPECT_FALSE(compute::build_triangle_work(s.vertices, s.indices, s.spec.nx, s.spec.ny, s.spec.nz, 100'000, w, threads));
    // Each thread stops at its first box past the budget: the list stays near budget / chunk items.
    EXPECT_LT(w.extra.size(), 2 * threads * (100'000 / compute::kChunkVoxels + 200)) << threads;
  }
}

// Enough triangles that the list is split over the machine's threads: the device still marks what the CPU
// marks.
TEST(TriangleWork, SplitListGivesTheCpuResult) {
  ROOMSENSE_REQUIRE_VULKAN(stage);
  const Soup s = soup(300'000, 9, 6.0f);  // about 10M tests: seconds, not minutes, on lavapipe
  VoxelizeRequest r;
  r.spec = s.spec;
  r.grid_vertices = s.vertices;
  r.indices = s.indices;
  r.mode = VoxelMode::Triangles;
  const VoxelStageResult cpu = CpuVoxelStage().run(r);
  const VoxelStageResult gpu = stage->run(r);
  EXPECT_FALSE(stage->last_timings().fell_back);
  test::expect_identical(cpu, gpu);
}

}  // namespace
}  // namespace roomsense
