// Straight wall segments along a storey's outline, from its wall columns (Eq. 3.11), in lattice units
// (outline.h). The outline follows the outer face of the room region; each of its edges that wall columns
// line becomes the line through those columns' centres, where the scanned wall surface lies, and is cut
// where no wall stands for an opening's width. Working edge by edge of the simplified outline gives one
// segment per real wall even where a wall off the grid axes rasterises into a staircase of columns.
#pragma once
#include "polygon.h"
#include "regions.h"

#include <functional>
#include <vector>

namespace roomsense::detail {

struct WallSearch {
  const ColumnMask* walls = nullptr;    // A of the storey
  // Columns that bridge a gap in A without being an opening: wall both below and above it (a window).
  std::function<bool(int x, int z)> bridges;
  double opening = 5.0;    // voxels: a run at least this long without wall splits a segment
  double min_width = 3.0;  // voxels: shorter segments are dropped
};

struct WallSegment {
  glm::dvec2 a{0.0}, b{0.0};  // on the wall line, in outline order: the room lies to the right (inward_normal)
};

struct StoreyOutline {
  Polygon2 polygon;                // the outline with each edge on its wall line, or half a voxel in without one
  std::vector<WallSegment> walls;  // in outline order, from the polygon's lowest vertex (start_at_lowest)
};

// `outline`: simplify_outline's polygon of the storey's room region.
StoreyOutline fit_walls(const Polygon2& outline, const WallSearch& search);

}  // namespace roomsense::detail
