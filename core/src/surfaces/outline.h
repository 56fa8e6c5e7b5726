// The outline of a raster region and its simplification into straight edges, in lattice units (x, z): the
// lattice point (i, k) is the corner origin + (i, ·, k) · S_Voxel of the grid, column (x, z) the unit square
// [x, x + 1] × [z, z + 1].
#pragma once
#include "polygon.h"
#include "regions.h"

#include <glm/vec2.hpp>

#include <vector>

namespace roomsense::detail {

// The boundary of a non-empty, 4-connected region without holes (fill_holes) along the lattice lines,
// counter-clockwise seen from above, corners only, in the grid's lattice (the mask's x0, z0 added). Simple, since such a region never touches itself at a
// corner.
std::vector<glm::ivec2> trace_outline(const ColumnMask& region);

// The outline as few straight edges: split-and-merge (Douglas-Peucker, then merging neighbours that one line
// fits) on the midpoints of the unit boundary edges, which takes the half-voxel sawtooth out of a raster
// line at any angle; edges shorter than two voxels (the bevel a corner leaves) give way to their neighbours'
// crossing, and every edge is the least-squares line of its raster points. No raster point strays more than
// about `tolerance` voxels from its edge. Counter-clockwise seen from above and simple; the raster outline
// itself where simplifying would break that.
Polygon2 simplify_outline(const std::vector<glm::ivec2>& outline, double tolerance);

}  // namespace roomsense::detail
