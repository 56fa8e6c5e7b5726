// Triangulation of a lattice polygon with holes, using its own vertices only (ear clipping with hole
// bridges, after Eberly's "Triangulation by Ear Clipping"). Collinear vertices are kept: they are the
// T-junctions a watertight mesh needs, so every one must end up as a triangle corner.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <stop_token>
#include <vector>

namespace roomsense::detail {

struct LatticePoint2 {
  std::int32_t a = 0, b = 0;
  std::uint32_t id = 0;  // caller's vertex index, copied into the triangles
};

// One loop: the outer boundary counter-clockwise (positive area), each hole clockwise. A hole may touch
// the outer loop or another hole at a vertex. Loops must not cross.
using Loop = std::vector<LatticePoint2>;

using Triangles = std::vector<std::array<std::uint32_t, 3>>;  // counter-clockwise, like the outer loop

// Appends the n + 2h - 2 triangles of a polygon of n vertices and h holes to `out`. On input that breaks the
// contract above, where no ear can be found, the rest of the ring is fanned: the surface stays closed but
// those triangles may overlap (the exact-area tests would show it).
// A stop request throws Error(Cancelled) (roomsense/cancel.h).
void triangulate_polygon(const Loop& outer, const std::vector<Loop>& holes, Triangles& out,
                         const std::stop_token& stop = {});

}  // namespace roomsense::detail
