#include "triangle_work.h"

#include "roomsense/voxelize.h"

#include <glm/common.hpp>

#include <algorithm>
#include <thread>

namespace roomsense::compute {
namespace {

// Triangles per thread below which one thread lists them all: a thread's start costs about as much as
// listing 20k triangles.
constexpr std::size_t kTrianglesPerThread = 1u << 17;

// Triangles [begin, end): their tests, and the extra items of boxes past one chunk appended to `extra`.
bool list_range(std::span<const glm::vec3> p, std::span<const std::uint32_t> indices, int nx, int ny, int nz,
                std::size_t begin, std::size_t end, std::uint64_t budget, std::uint64_t& tests,
                std::vector<std::uint32_t>& extra) {
  for (std::size_t t = begin; t < end; ++t) {
    const glm::vec3& a = p[indices[3 * t]];
    const glm::vec3& b = p[indices[3 * t + 1]];
    const glm::vec3& c = p[indices[3 * t + 2]];
    const glm::vec3 lo = glm::min(glm::min(a, b), c), hi = glm::max(glm::max(a, b), c);
    const std::uint64_t sx = std::uint64_t(box_index(hi.x, nx) - box_index(lo.x, nx) + 1);
    const std::uint64_t sy = std::uint64_t(box_index(hi.y, ny) - box_index(lo.y, ny) + 1);
    const std::uint64_t sz = std::uint64_t(box_index(hi.z, nz) - box_index(lo.z, nz) + 1);
    const std::uint64_t volume = sx * sy * sz;
    if (volume <= 1) continue;  // a box of one voxel is marked without a test
    tests += volume;
    if (tests > budget) return false;
    for (std::uint64_t k = 1; k * kChunkVoxels < volume; ++k) {
      extra.push_back(std::uint32_t(t));
      extra.push_back(std::uint32_t(k));
    }
  }
  return true;
}

}  // namespace

bool build_triangle_work(std::span<const glm::vec3> p, std::span<const std::uint32_t> indices, int nx, int ny, int nz,
                         std::uint64_t budget, TriangleWork& work, unsigned max_threads) {
  work.tests = 0;
  work.extra.clear();
  const std::size_t triangles = indices.size() / 3;
  if (max_threads == 0) max_threads = std::min(8u, std::thread::hardware_concurrency());
  const std::size_t threads = std::clamp<std::size_t>(triangles / kTrianglesPerThread, 1, std::max(1u, max_threads));
  if (threads == 1) return list_range(p, indices, nx, ny, nz, 0, triangles, budget, work.tests, work.extra);

  // Contiguous ranges, concatenated in order: the same list as one thread's.
  struct Part {
    std::uint64_t tests = 0;
    std::vector<std::uint32_t> extra;
    bool within = true;
  };
  std::vector<Part> parts(threads);
  {
    std::vector<std::jthread> workers;
    for (std::size_t i = 1; i < threads; ++i)
      workers.emplace_back([&, i] {
        parts[i].within = list_range(p, indices, nx, ny, nz, triangles * i / threads, triangles * (i + 1) / threads,
                                     budget, parts[i].tests, parts[i].extra);
      });
    parts[0].within = list_range(p, indices, nx, ny, nz, 0, triangles / threads, budget, parts[0].tests, work.extra);
  }
  std::size_t words = work.extra.size();
  for (const Part& part : parts) {
    work.tests += part.tests;
    if (!part.within || work.tests > budget) return false;
    words += part.extra.size();
  }
  work.extra.reserve(words);
  for (std::size_t i = 1; i < threads; ++i) work.extra.insert(work.extra.end(), parts[i].extra.begin(), parts[i].extra.end());
  return true;
}

}  // namespace roomsense::compute
