// voxelize_labels (labels.h) in two passes, so that an IncrementalAnalysis can keep each chunk's labelled voxels:
// the boxes of a run of labelled triangles (cheap: the test budget is checked on them), then the voxels their
// triangles touch.
#pragma once
#include "roomsense/labels.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace roomsense::detail {

struct LabelBoxes {
  struct Box {
    glm::vec3 a, b, c;  // in voxels from the grid's origin
    glm::ivec3 lo, hi;
    SurfaceLabel label;
  };
  std::vector<Box> boxes;   // of the triangles with a label but Unknown, inside the grid
  std::uint64_t tests = 0;  // the triangle-voxel tests the boxes take
  std::size_t dropped = 0;  // triangles with bad indices, labels or coordinates
};

// Whether `labels` has one label per labelled triangle (else one warning); false too when it has none.
bool labels_usable(const LabelledTriangles& labels, std::vector<std::string>& warnings);
// The same from the counts of labelled triangles' indices and of labels.
bool labels_usable(std::size_t indices, std::size_t labels, std::vector<std::string>& warnings);
// The boxes of triangles `labels.size()` triangles of `indices` (into `vertices`), each with its label.
LabelBoxes label_boxes(const GridSpec& spec, std::span<const glm::vec3> vertices, std::span<const std::uint32_t> indices,
                       std::span<const SurfaceLabel> labels);
// The warning that the labels need more than `test_budget` tests, and that of `dropped` triangles (none for 0).
std::string over_budget_warning(std::uint64_t test_budget);
void add_dropped_warning(std::size_t dropped, std::vector<std::string>& warnings);
// Each voxel a box's triangle touches, with the labels of all boxes that touch it (in no order), one entry per
// voxel. `scratch` is all zero and `spec.voxel_count()` long, and is left so; the grid has at most 2^32 voxels.
using TouchedVoxels = std::vector<std::pair<std::uint32_t, LabelMask>>;
TouchedVoxels touched_voxels(const GridSpec& spec, const LabelBoxes& boxes, std::vector<LabelMask>& scratch);

}  // namespace roomsense::detail
