// See polygon.h.
#include "polygon.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomsense::detail {
namespace {

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

int side(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  const double c = cross(b - a, p - a);
  return c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
}

bool within_box(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Closed segments a-b and c-d share a point.
bool segments_meet(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d) {
  const int s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
  if (s1 * s2 < 0 && s3 * s4 < 0) return true;  // a proper crossing; below, one end lies on the other segment
  return (s1 == 0 && within_box(a, b, c)) || (s2 == 0 && within_box(a, b, d)) || (s3 == 0 && within_box(c, d, a)) ||
         (s4 == 0 && within_box(c, d, b));
}

glm::dvec2 project(const Line2& line, const glm::dvec2& p) {
  return line.point + line.dir * glm::dot(p - line.point, line.dir);
}

// Andrew's monotone chain; counter-clockwise in (x, z), without collinear points.
Polygon2 convex_hull(std::span<const glm::dvec2> points) {
  Polygon2 sorted(points.begin(), points.end());
  std::sort(sorted.begin(), sorted.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() < 3) return sorted;
  Polygon2 hull(2 * sorted.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], sorted[i] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = sorted[i];
  }
  for (std::size_t i = sorted.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && cross(hull[k - 1] - hull[k - 2], sorted[i - 1] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = sorted[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

double signed_area(std::span<const glm::dvec2> polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) twice += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * twice;
}

bool is_simple(std::span<const glm::dvec2> polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (const glm::dvec2& p : polygon)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;  // a degenerate line crossed nowhere
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 &a = polygon[i], &b = polygon[(i + 1) % n];
    if (a == b) return false;
    // Neighbours share a vertex; they must not fold back onto each other.
    const glm::dvec2& c = polygon[(i + 2) % n];
    if (cross(b - a, c - b) == 0.0 && glm::dot(b - a, c - b) < 0.0) return false;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_meet(a, b, polygon[j], polygon[(j + 1) % n])) return false;
    }
  }
  return true;
}

Line2 fit_line(std::span<const glm::dvec2> points) {
  glm::dvec2 mean(0.0);
  for (const glm::dvec2& p : points) mean += p;
  mean /= double(points.size());
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (const glm::dvec2& p : points) {
    const glm::dvec2 d = p - mean;
    sxx += d.x * d.x;
    sxy += d.x * d.y;
    syy += d.y * d.y;
  }
  // The principal axis of the scatter: angle ½·atan2(2 sxy, sxx - syy).
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  return {mean, {std::cos(angle), std::sin(angle)}};
}

double distance_to_line(const Line2& line, const glm::dvec2& p) { return std::abs(cross(line.dir, p - line.point)); }

std::optional<glm::dvec2> intersect(const Line2& a, const Line2& b, double min_sin) {
  const double s = cross(a.dir, b.dir);
  if (std::abs(s) < min_sin) return std::nullopt;
  return a.point + a.dir * (cross(b.point - a.point, b.dir) / s);
}

Polygon2 corners_of(std::span<const Line2> lines, std::span<const glm::dvec2> near, double max_shift) {
  const std::size_t n = lines.size();
  Polygon2 out(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Line2& before = lines[(k + n - 1) % n];
    const std::optional<glm::dvec2> p = intersect(before, lines[k]);
    out[k] = p && glm::distance(*p, near[k]) <= max_shift ? *p
                                                           : 0.5 * (project(before, near[k]) + project(lines[k], near[k]));
  }
  return out;
}

Polygon2 inset_polygon(const Polygon2& polygon, double inset) {
  const std::size_t n = polygon.size();
  std::vector<Line2> lines(n);
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2 dir = glm::normalize(polygon[(k + 1) % n] - polygon[k]);
    lines[k] = {polygon[k] + inward_normal(dir) * inset, dir};
  }
  Polygon2 out = corners_of(lines, polygon, 4.0 * inset + 1.0);
  // Moving every edge inward shrinks the area by about inset × perimeter; a flip or crossing means too thin.
  if (!is_simple(out) || signed_area(out) >= 0.0 || std::abs(signed_area(out)) > std::abs(signed_area(polygon)))
    return polygon;
  return out;
}

Polygon2 start_at_lowest(Polygon2 polygon) {
  const auto first = std::min_element(polygon.begin(), polygon.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
    return a.y < b.y || (a.y == b.y && a.x < b.x);
  });
  std::rotate(polygon.begin(), first, polygon.end());
  return polygon;
}

glm::dvec2 least_area_rectangle_direction(std::span<const glm::dvec2> points) {
  const Polygon2 hull = convex_hull(points);
  if (hull.size() < 3) return {1.0, 0.0};
  glm::dvec2 best(1.0, 0.0);
  double best_area = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2 u = glm::normalize(hull[(i + 1) % hull.size()] - hull[i]), v(-u.y, u.x);
    double u_lo = std::numeric_limits<double>::infinity(), u_hi = -u_lo, v_lo = u_lo, v_hi = -u_lo;
    for (const glm::dvec2& p : hull) {
      u_lo = std::min(u_lo, glm::dot(p, u));
      u_hi = std::max(u_hi, glm::dot(p, u));
      v_lo = std::min(v_lo, glm::dot(p, v));
      v_hi = std::max(v_hi, glm::dot(p, v));
    }
    // Ties (a square, or float noise on a rectangle's parallel edges) keep the earlier edge: deterministic.
    const double area = (u_hi - u_lo) * (v_hi - v_lo);
    if (area < best_area * (1.0 - 1e-9)) {
      best_area = area;
      best = u;
    }
  }
  // The four directions a quarter turn apart give the same rectangle: take the one nearest +X.
  glm::dvec2 pick = best, d = best;
  for (int turn = 1; turn < 4; ++turn) {
    d = {-d.y, d.x};
    if (d.x > pick.x || (d.x == pick.x && d.y < pick.y)) pick = d;
  }
  return pick;
}

}  // namespace roomsense::detail
