// The runtime's labels onto the voxel grid (labels.h), with the triangle test of triangle mode.
#include "label_voxels.h"

#include "roomsense/voxelize.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace roomsense {
namespace detail {

bool labels_usable(std::size_t indices, std::size_t labels, std::vector<std::string>& warnings) {
  if (labels == 0) return false;
  if (indices != 3 * labels) {
    warnings.push_back("runtime labels ignored: " + std::to_string(labels) + " labels for " +
                       std::to_string(indices / 3) + " labelled triangles");
    return false;
  }
  return true;
}

bool labels_usable(const LabelledTriangles& in, std::vector<std::string>& warnings) {
  return labels_usable(in.indices.size(), in.labels.size(), warnings);
}

LabelBoxes label_boxes(const GridSpec& spec, std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices,
                       std::span<const SurfaceLabel> labels) {
  LabelBoxes out;
  const glm::vec3 n(float(spec.nx), float(spec.ny), float(spec.nz));
  const std::size_t nv = vertices.size();
  for (std::size_t t = 0; t < labels.size(); ++t) {
    const std::uint32_t i0 = indices[3 * t], i1 = indices[3 * t + 1], i2 = indices[3 * t + 2];
    if (i0 >= nv || i1 >= nv || i2 >= nv || std::size_t(labels[t]) >= std::size_t(kSurfaceLabelCount)) {
      ++out.dropped;
      continue;
    }
    if (labels[t] == SurfaceLabel::Unknown) continue;  // says nothing
    const glm::vec3 a = (vertices[i0] - spec.origin) / spec.voxel_size;
    const glm::vec3 b = (vertices[i1] - spec.origin) / spec.voxel_size;
    const glm::vec3 c = (vertices[i2] - spec.origin) / spec.voxel_size;
    const glm::vec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(lo) || !finite(hi)) {
      ++out.dropped;
      continue;
    }
    if (glm::any(glm::lessThan(hi, glm::vec3(0.0f))) || glm::any(glm::greaterThanEqual(lo, n))) continue;
    const glm::ivec3 first(box_index(lo.x, spec.nx), box_index(lo.y, spec.ny), box_index(lo.z, spec.nz));
    const glm::ivec3 last(box_index(hi.x, spec.nx), box_index(hi.y, spec.ny), box_index(hi.z, spec.nz));
    const glm::ivec3 extent = last - first + 1;
    out.tests += std::uint64_t(extent.x) * std::uint64_t(extent.y) * std::uint64_t(extent.z);
    out.boxes.push_back({a, b, c, first, last, labels[t]});
  }
  return out;
}

std::string over_budget_warning(std::uint64_t test_budget) {
  return "runtime labels ignored: they need more than " + std::to_string(test_budget) +
         " triangle-voxel tests (a larger voxel size helps)";
}

void add_dropped_warning(std::size_t dropped, std::vector<std::string>& warnings) {
  if (dropped > 0)
    warnings.push_back(std::to_string(dropped) + " labelled triangles with bad indices, labels or coordinates ignored");
}

template <typename Mark>
void for_each_touched(const GridSpec& spec, const LabelBoxes& boxes, Mark mark) {
  for (const LabelBoxes::Box& t : boxes.boxes) {
    const LabelMask bit = label_bit(t.label);
    for (int z = t.lo.z; z <= t.hi.z; ++z)
      for (int x = t.lo.x; x <= t.hi.x; ++x)
        for (int y = t.lo.y; y <= t.hi.y; ++y)
          if (triangle_overlaps_voxel(t.a, t.b, t.c, x, y, z)) mark(spec.index(x, y, z), bit);
  }
}

TouchedVoxels touched_voxels(const GridSpec& spec, const LabelBoxes& boxes, std::vector<LabelMask>& scratch) {
  std::vector<std::uint32_t> order;  // the voxels touched, each once, as first touched
  for_each_touched(spec, boxes, [&](std::size_t i, LabelMask bit) {
    if (scratch[i] == 0) order.push_back(static_cast<std::uint32_t>(i));
    scratch[i] |= bit;
  });
  TouchedVoxels touched;
  touched.reserve(order.size());
  for (const std::uint32_t i : order) touched.emplace_back(i, scratch[i]), scratch[i] = 0;
  return touched;
}

}  // namespace detail

LabelGrid voxelize_labels(const GridSpec& spec, const LabelledTriangles& in, std::uint64_t test_budget,
                          std::vector<std::string>& warnings) {
  LabelGrid out;
  if (!detail::labels_usable(in, warnings)) return out;
  const detail::LabelBoxes boxes = detail::label_boxes(spec, in.vertices, in.indices, in.labels);
  if (boxes.tests > test_budget) {
    warnings.push_back(detail::over_budget_warning(test_budget));
    return out;
  }
  detail::add_dropped_warning(boxes.dropped, warnings);
  if (boxes.boxes.empty()) return out;
  out.masks.assign(spec.voxel_count(), 0);
  for (const detail::LabelBoxes::Box& t : boxes.boxes) out.present = LabelMask(out.present | label_bit(t.label));
  detail::for_each_touched(spec, boxes, [&](std::size_t i, LabelMask bit) { out.masks[i] |= bit; });
  return out;
}

}  // namespace roomsense
