#include "triangle_work.h"

#include "roomsense/voxelize.h"

#include <glm/common.hpp>

namespace roomsense::compute {

void list_extra_chunks(std::span<const glm::vec3> p, std::span<const std::uint32_t> indices, int nx, int ny, int nz,
                       std::span<const std::uint32_t> big, std::vector<std::uint32_t>& extra) {
  for (const std::uint32_t t : big) {
    const glm::vec3& a = p[indices[3 * std::size_t(t)]];
    const glm::vec3& b = p[indices[3 * std::size_t(t) + 1]];
    const glm::vec3& c = p[indices[3 * std::size_t(t) + 2]];
    const glm::vec3 lo = glm::min(glm::min(a, b), c), hi = glm::max(glm::max(a, b), c);
    const std::uint64_t volume = std::uint64_t(box_index(hi.x, nx) - box_index(lo.x, nx) + 1) *
                                 std::uint64_t(box_index(hi.y, ny) - box_index(lo.y, ny) + 1) *
                                 std::uint64_t(box_index(hi.z, nz) - box_index(lo.z, nz) + 1);
    for (std::uint64_t k = 1; k * kChunkVoxels < volume; ++k) {
      extra.push_back(t);
      extra.push_back(std::uint32_t(k));
    }
  }
}

}  // namespace roomsense::compute
