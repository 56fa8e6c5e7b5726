// Plane geometry for outlines in the X-Z plane: lines, polygon tests, and the bounding rectangle of least
// area. Outline polygons here turn counter-clockwise seen from above (+Y), which in (x, z) coordinates is a
// negative signed area, so the inside lies to the right of each edge: inward_normal(dir) = (dir.y, -dir.x).
#pragma once
#include <glm/vec2.hpp>

#include <optional>
#include <span>
#include <vector>

namespace roomsense::detail {

using Polygon2 = std::vector<glm::dvec2>;

struct Line2 {
  glm::dvec2 point{0.0};
  glm::dvec2 dir{1.0, 0.0};  // unit
};

inline glm::dvec2 inward_normal(const glm::dvec2& dir) { return {dir.y, -dir.x}; }

// The shoelace area in (x, z): negative for a polygon counter-clockwise seen from above.
double signed_area(std::span<const glm::dvec2> polygon);

// At least 3 finite vertices, no zero-length edge, no two edges meeting except neighbours at their shared
// vertex.
bool is_simple(std::span<const glm::dvec2> polygon);

// The total-least-squares line through points (at least 2 distinct).
Line2 fit_line(std::span<const glm::dvec2> points);

double distance_to_line(const Line2& line, const glm::dvec2& p);

// Where two lines cross, unless they meet at less than asin(min_sin).
std::optional<glm::dvec2> intersect(const Line2& a, const Line2& b, double min_sin = 0.25);

// The polygon whose edge k lies on lines[k]: vertex k where lines[k - 1] and lines[k] cross. Where they are
// nearly parallel or cross farther than max_shift from near[k] (the vertex before refinement), vertex k is
// the mean of near[k]'s projections onto the two lines.
Polygon2 corners_of(std::span<const Line2> lines, std::span<const glm::dvec2> near, double max_shift);

// The polygon with every edge moved `inset` inward, or the polygon unchanged where that would not leave a
// simple polygon of the same orientation (a region too thin for it).
Polygon2 inset_polygon(const Polygon2& polygon, double inset);

// The same polygon starting at its lowest vertex in z, then x: an order that depends on where the polygon
// lies, not on where a trace began.
Polygon2 start_at_lowest(Polygon2 polygon);

// The direction (unit, its angle to +X in [-45°, 45°)) of the least-area rectangle around the points, found
// over the edge directions of their convex hull (Freeman & Shapira 1975); +X for fewer than 3 points.
glm::dvec2 least_area_rectangle_direction(std::span<const glm::dvec2> points);

}  // namespace roomsense::detail
