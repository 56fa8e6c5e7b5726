// Metric heights of the floor and ceiling levels (internal to the pipeline).
#pragma once
#include "roomsense/analysis.h"

#include <span>

namespace roomsense::detail {

// The height of the scanned surface in the levels [lo, hi]: the area-weighted mean height of near-horizontal
// triangles there, or of the vertices there for a point cloud; the middle of the band if neither exists.
float surface_height(const GridSpec& spec, std::span<const glm::vec3> vertices,
                     std::span<const std::uint32_t> indices, int lo, int hi);

}  // namespace roomsense::detail
