// Beyond the thesis (issue 15): the ceiling per column (a roof's slope, a soffit, a beam), the storey's
// ceiling raised to a pitched roof's ridge, and the facets of free ceiling the areas lie on.
#include "roomsense/features.h"
#include "bounds/column_levels.h"
#include "feature_memo.h"
#include "surfaces/regions.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

namespace roomsense {
namespace {

using detail::CeilingSteps;
using detail::FloodRuns;

// The levels a flood reads, (floor, top) within the grid, and the level a part must rise to.
struct FloodLevels {
  int lo, hi, reach;
  bool none() const { return hi < lo || hi < reach; }  // no run rises to `reach`
};
FloodLevels flood_levels(const GridSpec& s, const FloorCeiling& levels, int top, int reach) {
  return {std::max(levels.floor + 1, 0), std::min(top, s.ny) - 1, reach};
}

// Column `col`'s runs of empty levels in [lo, hi], appended to `runs`; true, and none listed, where it is empty
// over them all (most of a room's free columns: found eight levels at a time, column_levels.h).
bool list_runs(const VoxelGrid& grid, std::size_t col, const FloodLevels& l, std::vector<FloodRuns::Run>& runs) {
  const std::uint8_t* v = grid.cells.data() + col * std::size_t(grid.spec.ny);
  if (detail::lowest_solid(v, l.lo, l.hi + 1) > l.hi) return true;
  for (int y = l.lo; y <= l.hi;) {
    if (v[y]) {
      ++y;
      continue;
    }
    const int y0 = y;
    y = detail::lowest_solid(v, y, l.hi + 1);
    runs.push_back({y0, y - 1});
  }
  return false;
}

// The parts of the runs of `columns` (ascending, and holding every column with runs beside one of them), as
// union-find in column order: each run joins the runs it touches in the columns before it along x and z, and is
// marked where it touches an open column. Every part is then what a flood from any of its runs reaches; a part
// holds a seed where one of its runs starts just above the floor. Only the parts that rise to `reach` or touch an
// open column count: a part that stays lower is shut in (the inside of a hollow box, a cupboard under a stair),
// not the room's free space. Sets the highest level of each column's counted runs (from -1). One sequential pass,
// not a flood's stack.
void flood_parts(FloodRuns& f, std::span<const std::uint32_t> columns, const GridSpec& s, const FloodLevels& l) {
  const std::vector<FloodRuns::Run>& runs = f.runs;
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
  const std::size_t nx = std::size_t(s.nx), column_count = s.column_count();
  const auto touches = [&](std::size_t r, std::size_t col, bool before) {  // run r and the column `col` beside it
    if (f.open[col]) counts[r] = 1;
    for (std::size_t q = f.first[col]; before && q < f.first[col + 1]; ++q)
      if (runs[q].y0 <= runs[r].y1 && runs[r].y0 <= runs[q].y1) join(q, r);  // runs after r join it in turn
  };
  for (const std::size_t col : columns)
    for (std::size_t r = f.first[col]; r < f.first[col + 1]; ++r) {
      parent[r] = r;
      if (col % nx > 0) touches(r, col - 1, true);
      if (col % nx + 1 < nx) touches(r, col + 1, false);
      if (col >= nx) touches(r, col - nx, true);
      if (col + nx < column_count) touches(r, col + nx, false);
    }
  std::vector<int> part_top(runs.size(), -1);  // per root: its highest level
  std::vector<std::uint8_t> seeded(runs.size(), 0);
  for (const std::size_t col : columns)
    for (std::size_t r = f.first[col]; r < f.first[col + 1]; ++r) {
      const std::size_t p = root(r);
      part_top[p] = std::max(part_top[p], runs[r].y1);
      if (runs[r].y0 == l.lo) seeded[p] = 1;
      if (counts[r]) counts[p] = 1;
    }
  for (const std::size_t col : columns) {
    f.highest[col] = -1;
    for (std::size_t r = f.first[col]; r < f.first[col + 1]; ++r) {
      const std::size_t p = root(r);
      if (counts[p] || (seeded[p] && part_top[p] >= l.reach)) f.highest[col] = std::max(f.highest[col], runs[r].y1);
    }
  }
}

// The flood of 6-connected empty voxels of `room`'s columns in the levels `l` reads, seeded at every empty voxel
// just above the floor: per column its runs, and the highest level the flood reaches in it, or -1. The flood
// walks runs of empty voxels in a column, not voxels: two runs of neighbouring columns that share a level touch,
// as their voxels would. A column empty over every level is one run that is seeded and rises to `reach`: its
// part counts, and so does every run it touches; the runs of the others (under a table, over furniture, beside a
// wall) are listed.
FloodRuns flood(const VoxelGrid& grid, const std::vector<std::uint8_t>& room, const FloodLevels& l) {
  const GridSpec& s = grid.spec;
  FloodRuns f;
  f.open.assign(s.column_count(), 0);
  f.first.assign(s.column_count() + 1, 0);
  f.highest.assign(s.column_count(), -1);
  if (l.none()) return f;
  std::vector<std::uint32_t> with_runs;
  for (std::size_t col = 0; col < s.column_count(); ++col) {
    f.first[col] = f.runs.size();
    if (!room[col]) continue;
    if (list_runs(grid, col, l, f.runs)) f.open[col] = 1, f.highest[col] = l.hi;
    else if (f.runs.size() > f.first[col]) with_runs.push_back(std::uint32_t(col));
  }
  f.first[s.column_count()] = f.runs.size();
  flood_parts(f, with_runs, s, l);
  return f;
}

// A column's ceiling: the level above the highest the flood reaches in it; where it reaches none (a wall), above
// the highest of its four neighbours'; else `cap`.
int column_ceiling(const GridSpec& s, const std::vector<int>& highest, int cap, std::size_t col) {
  if (highest[col] >= 0) return highest[col] + 1;
  const int x = int(col % std::size_t(s.nx)), z = int(col / std::size_t(s.nx));
  int best = -1;
  const int nbr[4][2] = {{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}};
  for (const auto& n : nbr)
    if (n[0] >= 0 && n[1] >= 0 && n[0] < s.nx && n[1] < s.nz) best = std::max(best, highest[s.column(n[0], n[1])]);
  return best >= 0 ? best + 1 : cap;
}

std::vector<int> ceilings_of(const GridSpec& s, const std::vector<int>& highest, int cap) {
  std::vector<int> ceiling(s.column_count());
  for (std::size_t col = 0; col < ceiling.size(); ++col) ceiling[col] = column_ceiling(s, highest, cap, col);
  return ceiling;
}

// The flood of `f` after the columns `changed` (ascending) changed their voxels or their room: their runs listed
// again, and the clusters of columns with runs that hold or lie beside one of them flooded again. Any other
// cluster keeps its runs, and its neighbours their openness (one beside a changed column is a seed), so its parts
// are as they were. The ceilings of the columns whose highest level changed, and of their neighbours, found again.
void update_flood(CeilingSteps& memo, const VoxelGrid& grid, const std::vector<std::uint8_t>& room,
                  const FloodLevels& l, int cap, std::span<const std::uint32_t> changed) {
  const GridSpec& s = grid.spec;
  const std::size_t n = s.column_count(), nx = std::size_t(s.nx);
  FloodRuns& f = memo.flood;
  // The runs again: the changed columns' listed, the others' copied a stretch at a time.
  std::vector<FloodRuns::Run> runs;
  runs.reserve(f.runs.size() + 64);
  std::vector<std::size_t> first(n + 1);
  std::size_t from = 0;  // the first column not yet placed
  const auto copy_until = [&](std::size_t end) {
    const std::size_t at = runs.size(), old = f.first[from];
    runs.insert(runs.end(), f.runs.begin() + std::ptrdiff_t(old), f.runs.begin() + std::ptrdiff_t(f.first[end]));
    for (std::size_t c = from; c < end; ++c) first[c] = f.first[c] - old + at;
    from = end;
  };
  for (const std::uint32_t col : changed) {
    copy_until(col);
    first[col] = runs.size();
    f.open[col] = room[col] && list_runs(grid, col, l, runs) ? 1 : 0;
    from = col + 1;
  }
  copy_until(n);
  first[n] = runs.size();
  f.runs = std::move(runs), f.first = std::move(first);
  // The clusters to flood again, from the changed columns and their neighbours.
  const auto has_runs = [&](std::size_t col) { return f.first[col + 1] > f.first[col]; };
  std::vector<std::uint8_t> seen(n, 0);
  std::vector<std::uint32_t> cluster, stack;
  const auto visit = [&](std::size_t col) {
    if (!has_runs(col) || seen[col]) return;
    seen[col] = 1;
    stack.push_back(std::uint32_t(col));
  };
  const auto each_neighbour = [&](std::size_t col, const auto& fn) {
    if (col % nx > 0) fn(col - 1);
    if (col % nx + 1 < nx) fn(col + 1);
    if (col >= nx) fn(col - nx);
    if (col + nx < n) fn(col + nx);
  };
  for (const std::uint32_t col : changed) {
    visit(col);
    each_neighbour(col, visit);
    while (!stack.empty()) {
      const std::uint32_t c = stack.back();
      stack.pop_back();
      cluster.push_back(c);
      each_neighbour(c, visit);
    }
  }
  std::sort(cluster.begin(), cluster.end());
  // Every column flooded again (the changed and the clusters'), with its highest level before.
  std::vector<std::uint32_t> again;
  std::set_union(cluster.begin(), cluster.end(), changed.begin(), changed.end(), std::back_inserter(again));
  std::vector<int> before(again.size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    before[i] = f.highest[again[i]];
    f.highest[again[i]] = f.open[again[i]] ? l.hi : -1;
  }
  flood_parts(f, cluster, s, l);
  const auto ceiling_again = [&](std::size_t col) { memo.ceiling[col] = column_ceiling(s, f.highest, cap, col); };
  for (std::size_t i = 0; i < again.size(); ++i) {
    if (f.highest[again[i]] == before[i]) continue;
    ceiling_again(again[i]);
    each_neighbour(again[i], ceiling_again);
  }
}

}  // namespace

std::vector<int> column_ceilings(const VoxelGrid& grid, const FloorCeiling& levels,
                                 const std::vector<std::uint8_t>& room, int cap) {
  return ceilings_of(grid.spec, flood(grid, room, flood_levels(grid.spec, levels, cap, cap - 1)).highest, cap);
}

std::vector<int> detail::column_ceilings(const VoxelGrid& grid, const FloorCeiling& levels,
                                         const std::vector<std::uint8_t>& room, int cap, CeilingSteps* memo,
                                         const GridChange& change) {
  if (memo == nullptr) return roomsense::column_ceilings(grid, levels, room, cap);
  const FloodLevels l = flood_levels(grid.spec, levels, cap, cap - 1);
  const std::optional<std::vector<std::uint32_t>> changed = memo->inputs.begin(change, {grid.spec, levels, cap}, room);
  if (!changed || l.none()) {
    memo->flood = flood(grid, room, l);
    memo->ceiling = ceilings_of(grid.spec, memo->flood.highest, cap);
  } else if (!changed->empty()) {
    update_flood(*memo, grid, room, l, cap, *changed);
  }
  memo->inputs.done(change);
  return memo->ceiling;
}

std::optional<FloorCeiling> raised_ceiling(const VoxelGrid& grid, const FloorCeiling& levels,
                                           const std::vector<std::uint8_t>& room, int upper) {
  constexpr float kRaise = 0.3f;
  const GridSpec& s = grid.spec;
  upper = std::min(upper, s.ny);
  const int raise = std::max(1, voxels_for(kRaise, s.voxel_size));
  if (levels.ceiling + raise >= upper) return std::nullopt;
  const std::vector<int> highest = flood(grid, room, flood_levels(s, levels, upper, levels.ceiling - 1)).highest;
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
