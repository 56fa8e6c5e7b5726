// Which cells of the X-Z plane a wall's top segment or a rotated square covers (Eq. 3.23/3.24 and
// Eq. 3.30-3.37). Cell (x, z) is the unit square around its centre (x, z); corners sit on cell centres.
#pragma once
#include <glm/vec2.hpp>

#include <cmath>
#include <span>

namespace roomsense::detail {

struct ZSpan {
  int lo = 0, hi = -1;  // inclusive; empty when lo > hi
};

// The cells in column x whose interior the convex polygon (or segment, 2 points) reaches. A polygon touching a
// cell only along its border or at a corner does not cover it: this is the "at least partly within" of Fig. 3.9
// and the "voxels touching the line" of Fig. 3.7, with the thesis's rounding of Eq. 3.24 made exact.
inline ZSpan covered_cells(std::span<const glm::dvec2> polygon, int x) {
  const double a = x - 0.5, b = x + 0.5;  // the column's strip
  double zmin = INFINITY, zmax = -INFINITY;
  // Comparisons rather than std::fmin and std::fmax, which GCC leaves as calls into libm (a fifth of a ring's
  // time): no z here is NaN, and a zero's sign does not move the cells below.
  const auto take = [&](double z) {
    zmin = z < zmin ? z : zmin;
    zmax = z > zmax ? z : zmax;
  };
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % n];
    if (p.x >= a && p.x <= b) take(p.y);
    if (p.x == q.x) continue;
    for (const double edge_x : {a, b}) {
      const double t = (edge_x - p.x) / (q.x - p.x);
      if (t > 0.0 && t < 1.0) take(p.y + t * (q.y - p.y));
    }
  }
  if (!(zmin <= zmax)) return {};
  // Cells z with z - 0.5 < zmax and z + 0.5 > zmin; the tolerance keeps exact border contacts out.
  constexpr double kEps = 1e-9;
  ZSpan s{int(std::floor(zmin - 0.5 + kEps)) + 1, int(std::ceil(zmax + 0.5 - kEps)) - 1};
  if (s.lo > s.hi) s.lo = s.hi = int(std::floor(zmin + 0.5));  // a flat segment exactly on a cell border
  return s;
}

}  // namespace roomsense::detail
