#include "triangle_work.h"

#include "roomsense/voxelize.h"

#include <glm/common.hpp>

#include <cmath>

namespace roomsense::compute {
namespace {

// Calls f(t, volume) for each triangle t with the voxel count of its box.
template <class F>
void for_each_box(std::span<const glm::vec3> p, std::span<const std::uint32_t> indices, int nx, int ny, int nz, F&& f) {
  const std::size_t triangles = indices.size() / 3;
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3& a = p[indices[3 * t]];
    const glm::vec3& b = p[indices[3 * t + 1]];
    const glm::vec3& c = p[indices[3 * t + 2]];
    const glm::vec3 lo = glm::min(glm::min(a, b), c), hi = glm::max(glm::max(a, b), c);
    const std::uint64_t sx = std::uint64_t(box_index(hi.x, nx) - box_index(lo.x, nx) + 1);
    const std::uint64_t sy = std::uint64_t(box_index(hi.y, ny) - box_index(lo.y, ny) + 1);
    const std::uint64_t sz = std::uint64_t(box_index(hi.z, nz) - box_index(lo.z, nz) + 1);
    f(t, sx * sy * sz);
  }
}

}  // namespace

std::uint64_t count_box_tests(std::span<const glm::vec3> p, std::span<const std::uint32_t> indices, int nx, int ny,
                              int nz) {
  std::uint64_t tests = 0;
  for_each_box(p, indices, nx, ny, nz, [&](std::size_t, std::uint64_t volume) {
    if (volume > 1) tests += volume;  // a box of one voxel is marked without a test
  });
  return tests;
}

void build_triangle_work(std::span<const glm::vec3> p, std::span<const std::uint32_t> indices, int nx, int ny, int nz,
                         std::vector<std::uint32_t>& out) {
  out.reserve(out.size() + 2 * (indices.size() / 3));
  for_each_box(p, indices, nx, ny, nz, [&](std::size_t t, std::uint64_t volume) {
    const std::uint64_t chunks = (volume + kChunkVoxels - 1) / kChunkVoxels;
    for (std::uint64_t k = 0; k < chunks; ++k) {
      out.push_back(std::uint32_t(t));
      out.push_back(std::uint32_t(k));
    }
  });
}

}  // namespace roomsense::compute
