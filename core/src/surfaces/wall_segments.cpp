// See wall_segments.h.
#include "wall_segments.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

namespace roomsense::detail {
namespace {

constexpr double kBand = 2.5;          // voxels either side of an outline edge searched for its wall columns
constexpr double kOnLine = 1.5;        // voxels either side of a wall line where columns count as that wall
constexpr double kLayer = 1.0 + 1e-6;  // voxels: neighbouring columns of one run, and the depth of a wall's run
constexpr double kMaxSlope = 0.15;     // the fitted line may turn this far (tan, ~8.5°) off the outline edge
constexpr double kSnap = 2.0;          // voxels: segment ends this near a corner reach it

// A column centre in an edge's frame: t along the edge from its start, d inward from its line.
struct Hit {
  double t = 0.0, d = 0.0;
};

// Narrows [x_lo, x_hi] to the columns x whose centre meets lo <= k (x + 0.5) + m <= hi.
void clip(double k, double m, double lo, double hi, double& x_lo, double& x_hi) {
  if (std::abs(k) < 1e-12) {
    if (m < lo || m > hi) x_hi = x_lo - 1.0;
    return;
  }
  double a = (lo - m) / k - 0.5, b = (hi - m) / k - 0.5;
  if (a > b) std::swap(a, b);
  x_lo = std::max(x_lo, a);
  x_hi = std::min(x_hi, b);
}

// Columns within `band` of the line through a with direction u (inward n), t in [t_lo, t_hi]: row by row,
// only the stretch of the row inside that strip, so a long wall at an angle costs its length, not its box.
template <class Keep>
std::vector<Hit> columns_near(const glm::dvec2& a, const glm::dvec2& u, double length, double band, double t_lo,
                              double t_hi, int nx, int nz, Keep&& keep) {
  const glm::dvec2 n = inward_normal(u), b = a + u * length;
  const int z_lo = std::max(0, int(std::floor(std::min(a.y, b.y) - band - 1.0)));
  const int z_hi = std::min(nz - 1, int(std::ceil(std::max(a.y, b.y) + band + 1.0)));
  std::vector<Hit> out;
  for (int z = z_lo; z <= z_hi; ++z) {
    const double cz = z + 0.5 - a.y;
    double x_lo = 0.0, x_hi = double(nx - 1);
    clip(u.x, cz * u.y - a.x * u.x, t_lo, t_hi, x_lo, x_hi);
    clip(n.x, cz * n.y - a.x * n.x, -band, band, x_lo, x_hi);
    for (int x = int(std::ceil(x_lo - 1e-9)); x <= int(std::floor(x_hi + 1e-9)); ++x) {
      const glm::dvec2 c = glm::dvec2(x + 0.5, z + 0.5) - a;
      const Hit h{glm::dot(c, u), glm::dot(c, n)};
      if (h.t >= t_lo && h.t <= t_hi && std::abs(h.d) <= band && keep(x, z)) out.push_back(h);
    }
  }
  return out;
}

// d = alpha + beta t by least squares.
bool fit(const std::vector<Hit>& hits, double& alpha, double& beta) {
  if (hits.size() < 2) return false;
  double st = 0, sd = 0, stt = 0, std_ = 0;
  for (const Hit& h : hits) {
    st += h.t;
    sd += h.d;
    stt += h.t * h.t;
    std_ += h.t * h.d;
  }
  const double n = double(hits.size()), det = n * stt - st * st;
  if (det <= 1e-9 * n * n) return false;
  beta = (n * std_ - st * sd) / det;
  alpha = (sd - beta * st) / n;
  return true;
}

// The line of an outline edge's wall, through the centres of the wall's own columns, where the scanned
// surface lies (to half a voxel). Per one-voxel station along the edge the outermost column is the wall's:
// their least-squares line gives the direction. The offset is the mean over the wall's run of columns at
// each station, which is at most two deep (a surface straddling a voxel boundary); a deeper run is furniture
// against the wall (a cabinet reads as wall too, §3.2.2), of which only the outermost column counts.
// Nothing without enough wall columns.
std::optional<Line2> wall_line(const glm::dvec2& a, const glm::dvec2& b, const WallSearch& search) {
  const double length = glm::distance(a, b);
  const glm::dvec2 u = (b - a) / length, n = inward_normal(u);
  const double margin = std::min(2.0, length / 4.0);  // the ends belong to the corners as much as to this wall
  const ColumnMask& walls = *search.walls;
  const std::vector<Hit> hits = columns_near(a, u, length, kBand, margin, length - margin, walls.nx, walls.nz,
                                             [&](int x, int z) { return walls.at(x, z); });
  std::map<long, std::vector<Hit>> stations;
  for (const Hit& h : hits) stations[long(std::floor(h.t))].push_back(h);
  if (double(stations.size()) < std::max(3.0, 0.3 * (length - 2.0 * margin))) return std::nullopt;
  std::vector<Hit> outermost, run;
  for (auto& [station, at] : stations) {
    std::sort(at.begin(), at.end(), [](const Hit& p, const Hit& q) { return p.d < q.d; });
    outermost.push_back(at.front());
    std::size_t end = 1;
    while (end < at.size() && at[end].d - at[end - 1].d <= kLayer) ++end;
    if (at[end - 1].d - at.front().d > kLayer) end = 1;
    run.insert(run.end(), at.begin(), at.begin() + std::ptrdiff_t(end));
  }
  double alpha = 0.0, beta = 0.0;
  if (!fit(outermost, alpha, beta)) return std::nullopt;
  // Once more without the columns far off the first line (a corner's other wall, clutter).
  std::erase_if(outermost, [&](const Hit& h) { return std::abs(h.d - alpha - beta * h.t) > 1.0; });
  if (!fit(outermost, alpha, beta)) return std::nullopt;
  if (std::abs(beta) > kMaxSlope) {  // not one straight wall after all: keep the outline's direction
    std::vector<double> d;
    for (const Hit& h : outermost) d.push_back(h.d);
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
    alpha = d[d.size() / 2];
    beta = 0.0;
  }
  std::erase_if(run, [&](const Hit& h) {
    const double off = h.d - alpha - beta * h.t;  // the second layer lies about one voxel in
    return off < -1.0 || off > kLayer + 0.5;
  });
  if (!run.empty()) {
    double sum = 0.0;
    for (const Hit& h : run) sum += h.d - beta * h.t;
    alpha = sum / double(run.size());
  }
  return Line2{a + n * alpha, glm::normalize(u + n * beta)};
}

// The segments of the wall along edge a-b (already on its wall line): runs of stations (one voxel along the
// edge) with a wall column or a bridging one on the line, cut at gaps of at least an opening.
void segments_along(const glm::dvec2& a, const glm::dvec2& b, const WallSearch& search, std::vector<WallSegment>& out) {
  const double length = glm::distance(a, b);
  if (length < search.min_width || !(length > 0.0)) return;
  const glm::dvec2 u = (b - a) / length;
  const ColumnMask& walls = *search.walls;
  const std::vector<Hit> hits = columns_near(a, u, length, kOnLine, 0.0, length, walls.nx, walls.nz,
                                             [&](int x, int z) { return walls.at(x, z) || search.bridges(x, z); });
  const std::size_t stations = std::size_t(std::ceil(length));
  std::vector<std::uint8_t> held(stations, 0);
  for (const Hit& h : hits) held[std::min(stations - 1, std::size_t(std::max(0.0, h.t)))] = 1;

  const auto emit = [&](std::size_t first, std::size_t last) {  // stations [first, last], both held
    std::size_t count = 0;
    for (std::size_t s = first; s <= last; ++s) count += held[s];
    double t0 = double(first), t1 = std::min(length, double(last + 1));
    if (t0 <= kSnap) t0 = 0.0;
    if (t1 >= length - kSnap) t1 = length;
    // Too short, or more gap than wall (gaps shorter than an opening add up): not a wall plane.
    if (t1 - t0 < search.min_width || 2.0 * double(count) < t1 - t0) return;
    out.push_back({a + u * t0, a + u * t1});
  };
  std::size_t first = stations, last = 0;  // the open run's held ends; first == stations: none open
  for (std::size_t s = 0; s < stations; ++s) {
    if (!held[s]) continue;
    if (first != stations && double(s - last - 1) >= search.opening) {
      emit(first, last);
      first = stations;
    }
    if (first == stations) first = s;
    last = s;
  }
  if (first != stations) emit(first, last);
}

}  // namespace

StoreyOutline fit_walls(const Polygon2& outline, const WallSearch& search) {
  Polygon2 near = outline;
  std::vector<std::optional<Line2>> walls(near.size());
  for (std::size_t k = 0; k < near.size(); ++k) walls[k] = wall_line(near[k], near[(k + 1) % near.size()], search);
  // A bevel the outline left at a corner: one edge or a few, together shorter than two minimum wall widths
  // and with no wall of their own or too short to be a wall segment, between two walls that cross near them.
  // They give way to that crossing. Between parallel walls (a step, a pillar) nothing crosses: they stay.
  const double bevel = 2.0 * search.min_width;
  for (bool changed = true; changed && near.size() > 3;) {
    changed = false;
    const std::size_t m = near.size();
    const auto edge_length = [&](std::size_t e) { return glm::distance(near[e % m], near[(e + 1) % m]); };
    const auto anchor = [&](std::size_t e) { return walls[e % m].has_value() && edge_length(e) >= bevel; };
    for (std::size_t k = 0; k < m && !changed; ++k) {
      if (!anchor(k)) continue;
      // Edges k + 1 .. next - 1 are the bevel; vertices k + 1 .. next lie between walls k and next.
      std::size_t next = k + 1;
      double length = 0.0;
      for (; next < k + m && !anchor(next); ++next) length += edge_length(next);
      if (next == k + 1 || next == k + m || length >= bevel || next - k >= m - 2) continue;
      const auto corner = intersect(*walls[k], *walls[next % m]);
      if (!corner) continue;
      bool close = true;
      for (std::size_t v = k + 1; v <= next; ++v) close = close && glm::distance(*corner, near[v % m]) <= length + 2.0;
      if (!close) continue;
      // Vertex k + 1 becomes the corner and starts wall `next`; vertices k + 2 .. next and their edges go.
      Polygon2 kept_near;
      std::vector<std::optional<Line2>> kept_walls;
      for (std::size_t i = 0; i < m; ++i) {
        const bool dropped = (i + m - (k + 2) % m) % m <= next - (k + 2);
        if (next >= k + 2 && dropped) continue;
        const bool corner_here = i == (k + 1) % m;
        kept_near.push_back(corner_here ? *corner : near[i]);
        kept_walls.push_back(corner_here ? walls[next % m] : walls[i]);
      }
      near = std::move(kept_near);
      walls = std::move(kept_walls);
      changed = true;
    }
  }
  // Edges without a wall: the line of the boundary columns' centres, half a voxel in.
  const std::size_t n = near.size();
  std::vector<Line2> lines(n);
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2 u = glm::normalize(near[(k + 1) % n] - near[k]);
    lines[k] = walls[k].value_or(Line2{near[k] + inward_normal(u) * 0.5, u});
  }
  StoreyOutline out;
  out.polygon = corners_of(lines, near, 4.0);
  if (!is_simple(out.polygon) || signed_area(out.polygon) >= 0.0) out.polygon = inset_polygon(outline, 0.5);
  out.polygon = start_at_lowest(std::move(out.polygon));
  for (std::size_t k = 0, m = out.polygon.size(); k < m; ++k)
    segments_along(out.polygon[k], out.polygon[(k + 1) % m], search, out.walls);
  return out;
}

}  // namespace roomsense::detail
