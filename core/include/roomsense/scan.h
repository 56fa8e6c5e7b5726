// A room scan as the pipeline takes it: world-space vertices and, optionally, triangle indices, and what the
// runtime says its surfaces are.
#pragma once
#include "roomsense/surface_label.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace roomsense {

// Labelled triangles in the scan's frame: the runtime's semantics. They label the voxels they pass through and
// add no geometry, so they may repeat the scan's own triangles (Android XR's per-vertex labels, labelled
// XR_EXT_spatial_plane_tracking planes) or be surfaces the scan does not hold (Quest scene anchors' plane
// rectangles and boxes, an MRUK room's anchors). Labels that cannot be used (a count that does not match,
// an index out of range, non-finite vertices) are dropped with a warning; they never fail an analysis.
struct LabelledTriangles {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;  // 3 per triangle
  std::vector<SurfaceLabel> labels;    // one per triangle
  bool empty() const { return labels.empty(); }
  // Appends the triangles of `mesh` (indices into `mesh_vertices`), all labelled `label`, or each with its own
  // label (one per triangle).
  void add(const std::vector<glm::vec3>& mesh_vertices, const std::vector<std::uint32_t>& mesh_indices,
           SurfaceLabel label);
  void add(const std::vector<glm::vec3>& mesh_vertices, const std::vector<std::uint32_t>& mesh_indices,
           const std::vector<SurfaceLabel>& triangle_labels);
};

struct Scan {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;  // triangles, 3 per face; empty for a point cloud (thesis input)
  LabelledTriangles labels{};          // empty: the runtime gave no semantics (the thesis's input)
};

// Thesis Eq. 3.1: a flattened array x1,y1,z1,x2,... of `size` floats. Throws Error with the thesis's codes:
// EmptyInput (null data or size < 1) and SizeNotMultipleOfThree.
Scan scan_from_flat_array(const float* data, long long size);

enum class UpAxis { Y, Z };
enum class Units { Metres, Centimetres, Millimetres };

// Where the scan comes from. Our frame is right-handed, +Y up, metres (OpenXR STAGE/LOCAL).
struct SourceFrame {
  UpAxis up = UpAxis::Y;
  Units units = Units::Metres;
  bool left_handed = false;  // Unity (with up Y) or Unreal (with up Z)
};

// Converts positions in place to our frame (thesis Eq. 3.2 generalised; see scan.cpp for each mapping).
void convert_to_roomsense_frame(Scan& scan, const SourceFrame& frame);

}  // namespace roomsense
