// Metric heights of the floor and ceiling levels (internal to the pipeline).
#pragma once
#include "roomsense/analysis.h"
#include "roomsense/features.h"

#include <span>

namespace roomsense::detail {

// The height of the scanned surface in the levels [lo, hi]: the area-weighted mean height of near-horizontal
// triangles there, or of the vertices there for a point cloud; the middle of the band if neither exists.
float surface_height(const GridSpec& spec, std::span<const glm::vec3> vertices,
                     std::span<const std::uint32_t> indices, int lo, int hi);

// The highest vertex in the levels [lo, hi]: the ridge of a roof that raised_ceiling raised I_Ceiling to; the
// middle of the band without one.
float surface_top(const GridSpec& spec, std::span<const glm::vec3> vertices, int lo, int hi);

// Per facet of `features` but the first (SurfaceLevels::ceiling_planes): the plane y = p.x x + p.y z + p.z
// fitted (least squares, by area) to the scan's triangles that are not walls (points, for a point cloud)
// above the facet's tiles within a level of its ceiling; the facet's fitted levels where fewer than three
// such samples span a plane.
std::vector<glm::vec3> ceiling_planes(const GridSpec& spec, std::span<const glm::vec3> vertices,
                                      std::span<const std::uint32_t> indices, const RoomFeatures& features);

}  // namespace roomsense::detail
