// The second corners a search tries from a first one: Eq. 3.21's ranges (as DESIGN.md corrects them), kept to
// the offsets whose distance d lies in [w_min, w_max], in the thesis's loop order. The cells a rectangle covers
// depend only on the offset between its corners, so each offset carries them, relative to the first corner.
#pragma once
#include "candidate.h"
#include "cell_cover.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

namespace roomsense::detail {

struct CellRun {  // cells (x1 + dx, z1 + dz_lo ... z1 + dz_hi)
  int dx = 0, dz_lo = 0, dz_hi = 0;
};

struct RingOffset {
  int dx = 0, dz = 0;
  double d = 0;                // Eq. 3.20's distance, in voxels
  std::vector<CellRun> runs;   // the covered cells, one run per column
  int cells = 0;               // how many
  // Their bounding box (x, z) with the corners' cells, relative to the first corner: every cell a rectangle of
  // this offset reads (a search after a change tests whether it meets the changed columns).
  glm::ivec2 box_lo{0}, box_hi{0};
  // A box of covered cells (the largest over runs of whole columns), relative to the first corner; empty
  // (core_lo.x > core_hi.x) for a wall top.
  glm::ivec2 core_lo{1, 0}, core_hi{0, 0};
};

enum class Shape {
  WallTop,  // the segment from corner 1 to corner 2 (Eq. 3.23/3.24)
  Square,   // the square v1 v2 v3 v4 of Eq. 3.28 (Eq. 3.30-3.37)
};

// dx >= 0, and dz > 0 when dx == 0, so each unordered pair of corners is tried once (Eq. 3.21).
inline std::vector<RingOffset> ring_offsets(const SizeRange& size, Shape shape) {
  std::vector<RingOffset> out;
  const int reach = int(std::floor(size.max_d));
  const double lo2 = size.min_d * size.min_d - 1e-9, hi2 = size.max_d * size.max_d + 1e-9;
  for (int dx = 0; dx <= reach; ++dx)
    for (int dz = dx == 0 ? 1 : -reach; dz <= reach; ++dz) {
      const double d2 = double(dx) * dx + double(dz) * dz;
      if (d2 < lo2 || d2 > hi2) continue;
      RingOffset o{dx, dz, std::sqrt(d2), {}, 0};
      // On the stack, and the runs one allocation: rings of large squares hold thousands of offsets, made each
      // analysis, and their vectors were a third of its allocations.
      const std::array<glm::dvec2, 4> corners = {glm::dvec2(0, 0), glm::dvec2(dx, dz), glm::dvec2(dx - dz, dz + dx),
                                                 glm::dvec2(-dz, dx)};
      const std::span<const glm::dvec2> polygon(corners.data(), shape == Shape::Square ? 4 : 2);
      const int x_first = shape == Shape::Square ? std::min({0, dx, dx - dz, -dz}) : 0;
      const int x_last = shape == Shape::Square ? std::max({0, dx, dx - dz, -dz}) : dx;
      o.runs.reserve(std::size_t(x_last - x_first + 1));
      for (int x = x_first; x <= x_last; ++x) {
        const ZSpan span = covered_cells(polygon, x);
        if (span.lo > span.hi) continue;
        o.runs.push_back({x, span.lo, span.hi});
        o.cells += span.hi - span.lo + 1;
      }
      o.box_lo = {o.runs.front().dx, o.runs.front().dz_lo};
      o.box_hi = {o.runs.back().dx, o.runs.front().dz_hi};
      for (const CellRun& r : o.runs) o.box_lo.y = std::min(o.box_lo.y, r.dz_lo), o.box_hi.y = std::max(o.box_hi.y, r.dz_hi);
      for (const glm::dvec2& corner : polygon)
        o.box_lo = glm::min(o.box_lo, glm::ivec2(corner)), o.box_hi = glm::max(o.box_hi, glm::ivec2(corner));
      if (shape == Shape::Square) {
        // The first largest box, as trying every pair of runs i <= j finds it; pairs that cannot beat the best so
        // far are not tried: the runs from i on are at most n - i wide, and no taller than run i (or than
        // the part of it that runs i..j share).
        const std::size_t n = o.runs.size();
        long best = 0;
        for (std::size_t i = 0; i < n; ++i) {
          int lo = o.runs[i].dz_lo, hi = o.runs[i].dz_hi;  // the z both ends of runs i..j cover
          if (long(n - i) * long(hi - lo + 1) <= best) continue;
          for (std::size_t j = i; j < n; ++j) {
            lo = std::max(lo, o.runs[j].dz_lo), hi = std::min(hi, o.runs[j].dz_hi);
            if (lo > hi || long(n - i) * long(hi - lo + 1) <= best) break;
            const long area = long(j - i + 1) * long(hi - lo + 1);
            if (area > best) best = area, o.core_lo = {o.runs[i].dx, lo}, o.core_hi = {o.runs[j].dx, hi};
          }
        }
      }
      out.push_back(std::move(o));
    }
  return out;
}

}  // namespace roomsense::detail
