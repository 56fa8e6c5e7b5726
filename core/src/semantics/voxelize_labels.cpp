// The runtime's labels onto the voxel grid (labels.h), with the triangle test of triangle mode.
#include "roomsense/labels.h"
#include "roomsense/voxelize.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace roomsense {

LabelGrid voxelize_labels(const GridSpec& spec, const LabelledTriangles& in, std::uint64_t test_budget,
                          std::vector<std::string>& warnings) {
  LabelGrid out;
  if (in.labels.empty()) return out;
  if (in.indices.size() != 3 * in.labels.size()) {
    warnings.push_back("runtime labels ignored: " + std::to_string(in.labels.size()) + " labels for " +
                       std::to_string(in.indices.size() / 3) + " labelled triangles");
    return out;
  }
  struct Box {
    glm::vec3 a, b, c;
    glm::ivec3 lo, hi;
    SurfaceLabel label;
  };
  std::vector<Box> boxes;
  std::size_t dropped = 0;
  std::uint64_t tests = 0;
  const glm::vec3 n(float(spec.nx), float(spec.ny), float(spec.nz));
  for (std::size_t t = 0; t < in.labels.size(); ++t) {
    const std::uint32_t i0 = in.indices[3 * t], i1 = in.indices[3 * t + 1], i2 = in.indices[3 * t + 2];
    const std::size_t nv = in.vertices.size();
    if (i0 >= nv || i1 >= nv || i2 >= nv || std::size_t(in.labels[t]) >= std::size_t(kSurfaceLabelCount)) {
      ++dropped;
      continue;
    }
    if (in.labels[t] == SurfaceLabel::Unknown) continue;  // says nothing
    const glm::vec3 a = (in.vertices[i0] - spec.origin) / spec.voxel_size;
    const glm::vec3 b = (in.vertices[i1] - spec.origin) / spec.voxel_size;
    const glm::vec3 c = (in.vertices[i2] - spec.origin) / spec.voxel_size;
    const glm::vec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(lo) || !finite(hi)) {
      ++dropped;
      continue;
    }
    if (glm::any(glm::lessThan(hi, glm::vec3(0.0f))) || glm::any(glm::greaterThanEqual(lo, n))) continue;
    const glm::ivec3 first(box_index(lo.x, spec.nx), box_index(lo.y, spec.ny), box_index(lo.z, spec.nz));
    const glm::ivec3 last(box_index(hi.x, spec.nx), box_index(hi.y, spec.ny), box_index(hi.z, spec.nz));
    const glm::ivec3 extent = last - first + 1;
    tests += std::uint64_t(extent.x) * std::uint64_t(extent.y) * std::uint64_t(extent.z);
    if (tests > test_budget) {
      warnings.push_back("runtime labels ignored: they need more than " + std::to_string(test_budget) +
                         " triangle-voxel tests (a larger voxel size helps)");
      return out;
    }
    boxes.push_back({a, b, c, first, last, in.labels[t]});
  }
  if (dropped > 0)
    warnings.push_back(std::to_string(dropped) + " labelled triangles with bad indices, labels or coordinates ignored");
  if (boxes.empty()) return out;
  out.masks.assign(spec.voxel_count(), 0);
  for (const Box& t : boxes) {
    const LabelMask bit = label_bit(t.label);
    out.present = LabelMask(out.present | bit);
    for (int z = t.lo.z; z <= t.hi.z; ++z)
      for (int x = t.lo.x; x <= t.hi.x; ++x)
        for (int y = t.lo.y; y <= t.hi.y; ++y)
          if (triangle_overlaps_voxel(t.a, t.b, t.c, x, y, z)) out.masks[spec.index(x, y, z)] |= bit;
  }
  return out;
}

}  // namespace roomsense
