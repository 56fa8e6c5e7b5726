// Rectangles of placement queries: which raster cells one covers (at any rotation), and whether two clear boxes
// (a rectangle in the horizontal plane and a height interval) overlap.
#pragma once
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace roomsense::detail {

// A rectangle in raster units (one cell = 1): centre, unit axis u, half extents a along u and b across it.
struct RasterRect {
  glm::dvec2 centre{0.0};
  glm::dvec2 u{1.0, 0.0};
  double a = 0.0, b = 0.0;
};

// Calls visit(x, z) for each cell [x, x+1) × [z, z+1) the rectangle shares area with (separating-axis test on the
// two grid axes and the rectangle's two), until visit returns false. Returns false when stopped so.
template <class Visit>
bool for_cells_under(const RasterRect& r, Visit&& visit) {
  constexpr double kEps = 1e-6;  // a rectangle edge on a cell boundary does not cover the next cell
  const glm::dvec2 v(-r.u.y, r.u.x);
  const double ex = r.a * std::abs(r.u.x) + r.b * std::abs(v.x);
  const double ez = r.a * std::abs(r.u.y) + r.b * std::abs(v.y);
  const double cell_u = 0.5 * (std::abs(r.u.x) + std::abs(r.u.y));  // a cell's half extent along u (and along v)
  const int x0 = int(std::floor(r.centre.x - ex + kEps)), x1 = int(std::ceil(r.centre.x + ex - kEps)) - 1;
  const int z0 = int(std::floor(r.centre.y - ez + kEps)), z1 = int(std::ceil(r.centre.y + ez - kEps)) - 1;
  for (int z = z0; z <= z1; ++z)
    for (int x = x0; x <= x1; ++x) {
      const glm::dvec2 d = glm::dvec2(x + 0.5, z + 0.5) - r.centre;
      if (std::abs(glm::dot(d, r.u)) >= r.a + cell_u - kEps || std::abs(glm::dot(d, v)) >= r.b + cell_u - kEps)
        continue;
      if (!visit(x, z)) return false;
    }
  return true;
}

// An object's clear box: a rectangle in the horizontal plane (metres, x and z) and a height interval.
struct ClearBox {
  glm::vec2 centre{0.0f};
  glm::vec2 u{1.0f, 0.0f};
  float a = 0.0f, b = 0.0f;  // half extents along u and across it
  float y0 = 0.0f, y1 = 0.0f;
};

inline bool overlap(const ClearBox& p, const ClearBox& q) {
  constexpr float kEps = 1e-5f;  // boxes that only touch do not overlap
  if (p.y1 <= q.y0 + kEps || q.y1 <= p.y0 + kEps) return false;
  const glm::vec2 d = q.centre - p.centre;
  const auto radius = [](const ClearBox& r, const glm::vec2& axis) {
    const glm::vec2 v(-r.u.y, r.u.x);
    return r.a * std::abs(glm::dot(r.u, axis)) + r.b * std::abs(glm::dot(v, axis));
  };
  for (const glm::vec2& axis : {p.u, glm::vec2(-p.u.y, p.u.x), q.u, glm::vec2(-q.u.y, q.u.x)})
    if (std::abs(glm::dot(d, axis)) >= radius(p, axis) + radius(q, axis) - kEps) return false;
  return true;
}

}  // namespace roomsense::detail
