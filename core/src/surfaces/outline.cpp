// See outline.h.
#include "outline.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <utility>

namespace roomsense::detail {
namespace {

// The points of a closed chain, indexed cyclically: index i and i + size() are the same point.
struct Chain {
  std::span<const glm::dvec2> points;

  std::size_t size() const { return points.size(); }
  const glm::dvec2& at(std::size_t i) const { return points[i % points.size()]; }
  std::vector<glm::dvec2> range(std::size_t first, std::size_t last) const {  // both included
    std::vector<glm::dvec2> out;
    for (std::size_t i = first; i <= last; ++i) out.push_back(at(i));
    return out;
  }
};

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + ab * t);
}

// Douglas-Peucker on chain indices [first, last] (last may exceed size(): it wraps): adds the breakpoints
// strictly inside.
void split(const Chain& chain, std::size_t first, std::size_t last, double tolerance, std::vector<std::size_t>& out) {
  std::vector<std::pair<std::size_t, std::size_t>> todo{{first, last}};
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = distance_to_segment(chain.at(i), chain.at(a), chain.at(b));
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    if (worst <= tolerance) continue;
    out.push_back(at);
    todo.emplace_back(a, at);
    todo.emplace_back(at, b);
  }
}

// The worst distance of the points (first, last) from their least-squares line. The ends are left out: they
// are shared with the neighbouring segments, and at a corner they belong to the other wall as much.
double fit_error(const Chain& chain, std::size_t first, std::size_t last) {
  const std::vector<glm::dvec2> pts = last - first >= 4 ? chain.range(first + 1, last - 1) : chain.range(first, last);
  const Line2 line = fit_line(pts);
  double worst = 0.0;
  for (const glm::dvec2& p : pts) worst = std::max(worst, distance_to_line(line, p));
  return worst;
}

}  // namespace

std::vector<glm::ivec2> trace_outline(const ColumnMask& region) {
  // Start at the lowest corner of the first column in scan order: the columns before it and below it are
  // outside, so walking +z from there keeps the region on the right (inward_normal), as polygon.h wants.
  std::size_t first = 0;
  while (first < region.cells.size() && !region.cells[first]) ++first;
  if (first == region.cells.size()) return {};
  const glm::ivec2 start(int(first % std::size_t(region.nx)), int(first / std::size_t(region.nx)));
  const glm::ivec2 offset(region.x0, region.z0);
  std::vector<glm::ivec2> out;
  glm::ivec2 p = start, dir(0, 1);
  const std::size_t max_steps = 4 * region.count() + 4;  // each unit edge once; a guard, never reached
  do {
    // The columns ahead of lattice point p, to the right and to the left of dir (their lowest corners).
    const glm::ivec2 right(dir.y, -dir.x);
    const glm::ivec2 ahead_right = p + (dir + right - 1) / 2, ahead_left = p + (dir - right - 1) / 2;
    glm::ivec2 next = dir;
    if (!region.at(ahead_right.x, ahead_right.y)) next = right;                    // the region turns away
    else if (region.at(ahead_left.x, ahead_left.y)) next = glm::ivec2(-right.x, -right.y);  // it turns in
    if (next != dir || out.empty()) out.push_back(p + offset);
    dir = next;
    p += dir;
  } while (p != start && out.size() < max_steps);
  // The start is a corner: the edge into it runs -x along the bottom of the first column.
  return out;
}

Polygon2 simplify_outline(const std::vector<glm::ivec2>& outline, double tolerance) {
  Polygon2 raster(outline.begin(), outline.end());
  // Midpoints of the unit edges, in order.
  std::vector<glm::dvec2> mid;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const glm::ivec2 a = outline[i], b = outline[(i + 1) % outline.size()];
    const glm::ivec2 step = glm::sign(b - a);
    for (glm::ivec2 p = a; p != b; p += step) mid.push_back(glm::dvec2(p) + 0.5 * glm::dvec2(step));
  }
  const Chain chain{mid};
  const std::size_t n = chain.size();
  if (n < 6) return raster;

  // Split: from point 0 and the point farthest from it, each half by Douglas-Peucker.
  std::size_t far = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (glm::distance(chain.at(i), chain.at(0)) > glm::distance(chain.at(far), chain.at(0))) far = i;
  std::vector<std::size_t> cuts{0, far};
  split(chain, 0, far, tolerance, cuts);
  split(chain, far, n, tolerance, cuts);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  // Segment k runs over chain indices [cuts[k], cuts[k + 1]] (the last one up to cuts[0] + n).
  const auto last_of = [&](std::size_t k) { return k + 1 < cuts.size() ? cuts[k + 1] : cuts[0] + n; };

  // Merge: neighbours that one line fits within the tolerance, the best fit first. Split alone leaves a
  // raster line at an angle cut into pieces wherever the sawtooth happens to peak.
  // Dropping cut k joins the segments before and after it; only its neighbours' costs change when it goes.
  const auto join_error = [&](std::size_t k) {
    const std::size_t first = k == 0 ? cuts.back() : cuts[k - 1];
    const std::size_t last = k == 0 ? cuts[1] + n : last_of(k);
    return fit_error(chain, first, last);
  };
  std::vector<double> error(cuts.size());
  for (std::size_t k = 0; k < cuts.size(); ++k) error[k] = join_error(k);
  while (cuts.size() > 3) {
    const std::size_t drop = std::size_t(std::min_element(error.begin(), error.end()) - error.begin());
    if (error[drop] > tolerance) break;
    cuts.erase(cuts.begin() + std::ptrdiff_t(drop));
    error.erase(error.begin() + std::ptrdiff_t(drop));
    const std::size_t m = cuts.size();
    error[(drop + m - 1) % m] = join_error((drop + m - 1) % m);
    error[drop % m] = join_error(drop % m);
  }

  // Lines of the segments; then bevels shorter than two voxels give way to their neighbours' crossing.
  std::vector<Line2> lines;
  std::vector<glm::dvec2> near;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    // The ends are shared with the neighbours (a bevel's midpoint, say): fit without them where others exist.
    const std::size_t first = cuts[k], last = last_of(k);
    lines.push_back(fit_line(last - first >= 4 ? chain.range(first + 1, last - 1) : chain.range(first, last)));
    near.push_back(chain.at(cuts[k]));
  }
  // A bevel: where a corner of the room meets the raster at an angle, its outline cuts the corner off with an
  // edge or two up to about 2 * tolerance + 1 long. Shortest first, each such edge whose neighbours cross
  // near it gives way to that crossing; a short edge between parallel neighbours (a step, a pillar) stays.
  const double bevel = 2.0 * tolerance + 1.0;
  for (bool changed = true; changed && lines.size() > 3;) {
    changed = false;
    const std::size_t m = lines.size();
    std::vector<std::pair<double, std::size_t>> by_length;
    for (std::size_t k = 0; k < m; ++k) by_length.emplace_back(glm::distance(near[k], near[(k + 1) % m]), k);
    std::sort(by_length.begin(), by_length.end());
    for (const auto& [len, k] : by_length) {
      if (len >= bevel) break;
      const Line2 &before = lines[(k + m - 1) % m], &after = lines[(k + 1) % m];
      const glm::dvec2 middle = 0.5 * (near[k] + near[(k + 1) % m]);
      const auto corner = intersect(before, after);
      if (!corner || glm::distance(*corner, middle) > bevel) continue;
      near[(k + 1) % m] = *corner;
      lines.erase(lines.begin() + std::ptrdiff_t(k));
      near.erase(near.begin() + std::ptrdiff_t(k));
      changed = true;
      break;
    }
  }
  Polygon2 out = corners_of(lines, near, 2.0 * tolerance + 2.0);
  if (!is_simple(out) || signed_area(out) >= 0.0) return raster;
  return out;
}

}  // namespace roomsense::detail
