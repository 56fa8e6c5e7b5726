#include "surface_heights.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace roomsense::detail {

float surface_height(const GridSpec& spec, std::span<const glm::vec3> vertices,
                     std::span<const std::uint32_t> indices, int lo, int hi) {
  // The band's levels as triangle mode sees them: test cubes sit kVoxelTestEpsilon below the voxels.
  const float y_lo = spec.origin.y + (float(lo) - kVoxelTestEpsilon) * spec.voxel_size;
  const float y_hi = spec.origin.y + (float(hi + 1) - kVoxelTestEpsilon) * spec.voxel_size;
  const auto in_band = [&](float y) { return y >= y_lo && y < y_hi; };
  double weighted = 0.0, weight = 0.0;
  if (!indices.empty()) {
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
      const glm::vec3 &a = vertices[indices[t]], &b = vertices[indices[t + 1]], &c = vertices[indices[t + 2]];
      const glm::vec3 n = glm::cross(b - a, c - a);
      const float area2 = glm::length(n);
      const float cy = (a.y + b.y + c.y) / 3.0f;
      // Near-horizontal (within ~25°) either way up: scans disagree on winding.
      if (area2 <= 0.0f || std::fabs(n.y) < 0.9f * area2 || !in_band(cy)) continue;
      weighted += double(cy) * area2;
      weight += area2;
    }
  } else {
    // A point cloud has no normals: wall points spread evenly over the band while the surface's pile up, so
    // take the fullest 1 cm bin and average the points within a bin of it.
    constexpr float kBin = 0.01f;
    std::vector<std::uint32_t> bins(std::size_t(std::max(1.0f, std::ceil((y_hi - y_lo) / kBin))), 0);
    const auto bin_of = [&](float y) { return std::min(bins.size() - 1, std::size_t((y - y_lo) / kBin)); };
    for (const glm::vec3& v : vertices)
      if (in_band(v.y)) ++bins[bin_of(v.y)];
    const std::size_t peak = std::size_t(std::max_element(bins.begin(), bins.end()) - bins.begin());
    for (const glm::vec3& v : vertices)
      if (in_band(v.y) && bin_of(v.y) + 1 >= peak && bin_of(v.y) <= peak + 1) {
        weighted += v.y;
        weight += 1.0;
      }
  }
  if (weight > 0.0) return float(weighted / weight);
  return 0.5f * (y_lo + y_hi);
}

}  // namespace roomsense::detail
