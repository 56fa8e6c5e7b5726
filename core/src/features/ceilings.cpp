// Beyond the thesis (issue 15): the ceiling per column (a roof's slope, a soffit, a beam), the storey's
// ceiling raised to a pitched roof's ridge, and the facets of free ceiling the areas lie on.
#include "roomsense/features.h"
#include "bounds/column_levels.h"
#include "surfaces/regions.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace roomsense {
namespace {

// The highest level the flood reaches in each column, or -1: 6-connected empty voxels of `room`'s columns in
// levels (floor, top), seeded at every empty voxel just above the floor. Only the parts of the flood that rise
// to `reach` count: a part that stays lower is shut in (the inside of a hollow box, a cupboard under a stair),
// not the room's free space. The flood walks runs of empty voxels in a column, not voxels: two runs of
// neighbouring columns that share a level touch, as their voxels would.
std::vector<int> flood_tops(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<std::uint8_t>& room,
                            int top, int reach) {
  const GridSpec& s = grid.spec;
  std::vector<int> highest(s.column_count(), -1);
  const int lo = std::max(levels.floor + 1, 0), hi = std::min(top, s.ny) - 1;
  if (hi < lo || hi < reach) return highest;  // no run rises to `reach`
  // A column empty over every level, [lo, hi], is one run that is seeded and rises to `reach`: its part counts,
  // and so does every run it touches. Most of a room's free columns are such a column (`open`, their highest
  // level found at once); the runs of the others (under a table, over furniture, beside a wall) are listed.
  struct Run {
    int y0, y1;
  };
  std::vector<Run> runs;
  std::vector<std::uint8_t> open(s.column_count(), 0);
  std::vector<std::size_t> first(s.column_count() + 1, 0);  // runs of column c: [first[c], first[c + 1])
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    first[col] = runs.size();
    if (!room[col]) continue;
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    // Empty runs found eight levels at a time (column_levels.h): most columns are one run over [lo, hi].
    if (detail::lowest_solid(v, lo, hi + 1) > hi) {
      open[col] = 1, highest[col] = hi;
      continue;
    }
    for (int y = lo; y <= hi;) {
      if (v[y]) {
        ++y;
        continue;
      }
      const int y0 = y;
      y = detail::lowest_solid(v, y, hi + 1);
      runs.push_back({y0, y - 1});
    }
  }
  first[s.column_count()] = runs.size();
  // The listed runs' parts, as union-find in column order: each run joins the runs it touches in the columns
  // before it along x and z, and is marked where it touches an open column. Every part is then what a flood from
  // any of its runs reaches; a part holds a seed where one of its runs starts just above the floor. One
  // sequential pass, not a flood's stack.
  std::vector<std::size_t> parent(runs.size());
  std::vector<std::uint8_t> counts(runs.size(), 0);  // per run, then per root: it touches an open column
  const auto root = [&](std::size_t r) {
    while (parent[r] != r) r = parent[r] = parent[parent[r]];
    return r;
  };
  const auto join = [&](std::size_t a, std::size_t b) {
    a = root(a), b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  const std::size_t nx = std::size_t(s.nx), columns = s.column_count();
  const auto touches = [&](std::size_t r, std::size_t col, bool before) {  // run r and the column `col` beside it
    if (open[col]) counts[r] = 1;
    for (std::size_t q = first[col]; before && q < first[col + 1]; ++q)
      if (runs[q].y0 <= runs[r].y1 && runs[r].y0 <= runs[q].y1) join(q, r);  // runs after r join it in turn
  };
  for (std::size_t col = 0; col < columns; ++col)
    for (std::size_t r = first[col]; r < first[col + 1]; ++r) {
      parent[r] = r;
      if (col % nx > 0) touches(r, col - 1, true);
      if (col % nx + 1 < nx) touches(r, col + 1, false);
      if (col >= nx) touches(r, col - nx, true);
      if (col + nx < columns) touches(r, col + nx, false);
    }
  std::vector<int> part_top(runs.size(), -1);  // per root: its highest level
  std::vector<std::uint8_t> seeded(runs.size(), 0);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const std::size_t p = root(r);
    part_top[p] = std::max(part_top[p], runs[r].y1);
    if (runs[r].y0 == lo) seeded[p] = 1;
    if (counts[r]) counts[p] = 1;
  }
  for (std::size_t col = 0; col < columns; ++col)
    for (std::size_t r = first[col]; r < first[col + 1]; ++r) {
      const std::size_t p = root(r);
      if (counts[p] || (seeded[p] && part_top[p] >= reach)) highest[col] = std::max(highest[col], runs[r].y1);
    }
  return highest;
}

}  // namespace

std::vector<int> column_ceilings(const VoxelGrid& grid, const FloorCeiling& levels,
                                 const std::vector<std::uint8_t>& room, int cap) {
  const GridSpec& s = grid.spec;
  const std::vector<int> highest = flood_tops(grid, levels, room, cap, cap - 1);
  std::vector<int> ceiling(s.column_count(), cap);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const std::size_t col = s.column(x, z);
      if (highest[col] >= 0) {
        ceiling[col] = highest[col] + 1;
        continue;
      }
      int best = -1;
      const int nbr[4][2] = {{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}};
      for (const auto& n : nbr)
        if (n[0] >= 0 && n[1] >= 0 && n[0] < s.nx && n[1] < s.nz) best = std::max(best, highest[s.column(n[0], n[1])]);
      if (best >= 0) ceiling[col] = best + 1;
    }
  return ceiling;
}

std::optional<FloorCeiling> raised_ceiling(const VoxelGrid& grid, const FloorCeiling& levels,
                                           const std::vector<std::uint8_t>& room, int upper) {
  constexpr float kRaise = 0.3f;
  const GridSpec& s = grid.spec;
  upper = std::min(upper, s.ny);
  const int raise = std::max(1, voxels_for(kRaise, s.voxel_size));
  if (levels.ceiling + raise >= upper) return std::nullopt;
  const std::vector<int> highest = flood_tops(grid, levels, room, upper, levels.ceiling - 1);
  std::size_t reached = 0, raised = 0, open = 0;
  int top = levels.ceiling;
  for (const int h : highest) {
    if (h < 0) continue;
    ++reached;
    if (h + 1 >= upper) {
      ++open;
    } else if (h + 1 >= levels.ceiling + raise) {
      ++raised;
      top = std::max(top, h + 1);
    }
  }
  if (reached == 0 || 4 * raised < reached || 20 * open > reached) return std::nullopt;
  FloorCeiling out = levels;
  out.ceiling = top;
  out.ceiling_peak = std::min(top + 1, s.ny - 1);
  return out;
}

void find_ceiling_facets(const GridSpec& s, const FloorCeiling& levels, const std::vector<int>& ceiling,
                         const std::vector<std::uint8_t>& free_ceiling, std::size_t min_columns,
                         std::vector<int>& facet_of, std::vector<CeilingFacet>& facets) {
  facet_of.assign(s.column_count(), kNoFacet);
  facets.assign(1, CeilingFacet{levels.ceiling - 1, 0, 0.0f, 0.0f, float(levels.ceiling)});
  // Facet 0: the thesis's E, the tiles under I_Ceiling.
  for (std::size_t col = 0; col < facet_of.size(); ++col)
    if (free_ceiling[col] && ceiling[col] >= levels.ceiling) {
      facet_of[col] = 0;
      ++facets[0].columns;
    }
  // The others by the direction their ceiling rises in, over 2 tiles either side (0: flat, 1-8: 45° sectors).
  const auto tile_level = [&](int x, int z) {
    if (x < 0 || z < 0 || x >= s.nx || z >= s.nz) return -1;
    const std::size_t col = s.column(x, z);
    return free_ceiling[col] ? ceiling[col] : -1;
  };
  const auto gradient = [&](int x, int z, int dx, int dz) {
    for (int reach = 2; reach >= 1; --reach) {
      const int a = tile_level(x - reach * dx, z - reach * dz), b = tile_level(x + reach * dx, z + reach * dz);
      if (a >= 0 && b >= 0) return float(b - a) / float(2 * reach);
    }
    return 0.0f;
  };
  std::vector<int> direction(s.column_count(), -1);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const std::size_t col = s.column(x, z);
      if (!free_ceiling[col] || facet_of[col] == 0) continue;
      const float gx = gradient(x, z, 1, 0), gz = gradient(x, z, 0, 1);
      if (gx * gx + gz * gz < 0.35f * 0.35f) {
        direction[col] = 0;
        continue;
      }
      const double sector = std::atan2(double(gz), double(gx)) / (std::numbers::pi / 4.0);
      direction[col] = 1 + int(std::lround(sector) + 8) % 8;
    }
  // 4-connected tiles of one direction whose levels step by at most 1 (level) or 2 (sloping) are one facet.
  const detail::Components parts = detail::label_components(
      s.nx, s.nz, [&](std::size_t c) { return direction[c] >= 0; },
      [&](std::size_t a, std::size_t b) {
        return direction[a] == direction[b] && std::abs(ceiling[a] - ceiling[b]) <= (direction[a] == 0 ? 1 : 2);
      });
  // Per part, the least squares of level = a x + b z + d over its tiles (column centres), and its mean level.
  std::vector<glm::dmat3> m(parts.sizes.size(), glm::dmat3(0.0));
  std::vector<glm::dvec3> r(parts.sizes.size(), glm::dvec3(0.0));
  std::vector<double> sum(parts.sizes.size(), 0.0);
  std::vector<int> direction_of(parts.sizes.size(), 0);
  for (std::size_t c = 0; c < facet_of.size(); ++c) {
    if (parts.label[c] < 0) continue;
    const std::size_t k = std::size_t(parts.label[c]);
    direction_of[k] = direction[c];
    const glm::dvec3 p(double(c % std::size_t(s.nx)) + 0.5, double(c / std::size_t(s.nx)) + 0.5, 1.0);
    m[k] += glm::outerProduct(p, p);
    r[k] += p * double(ceiling[c]);
    sum[k] += double(ceiling[c]);
  }
  std::vector<int> facet_of_part(parts.sizes.size(), kNoFacet);
  for (std::size_t k = 0; k < parts.sizes.size(); ++k) {
    const double mean = sum[k] / double(parts.sizes[k]);
    // A level ceiling a voxel below I_Ceiling is the ceiling's own unevenness (a scan's jitter), no step.
    const bool step = direction_of[k] != 0 || mean <= double(levels.ceiling - 2);
    if (parts.sizes[k] < min_columns || !step) continue;
    CeilingFacet f{int(std::lround(mean)) - 1, parts.sizes[k], 0.0f, 0.0f, float(mean)};
    if (std::fabs(glm::determinant(m[k])) > 1e-9) {
      const glm::dvec3 fit = glm::inverse(m[k]) * r[k];
      f.slope_x = float(fit.x), f.slope_z = float(fit.y), f.offset = float(fit.z);
    }
    facet_of_part[k] = int(facets.size());
    facets.push_back(f);
  }
  for (std::size_t c = 0; c < facet_of.size(); ++c)
    if (parts.label[c] >= 0) facet_of[c] = facet_of_part[std::size_t(parts.label[c])];
}

}  // namespace roomsense
