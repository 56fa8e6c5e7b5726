// Beyond the thesis (issue 15): the ceiling per column (a roof's slope, a soffit, a beam), the storey's
// ceiling raised to a pitched roof's ridge, and the facets of free ceiling the areas lie on.
#include "roomsense/features.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace roomsense {
namespace {

// The highest level the flood reaches in each column, or -1: 6-connected empty voxels of `room`'s columns in
// levels (floor, top), seeded at every empty voxel just above the floor. Only the parts of the flood that rise
// to `reach` count: a part that stays lower is shut in (the inside of a hollow box, a cupboard under a stair),
// not the room's free space.
std::vector<int> flood_tops(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<std::uint8_t>& room,
                            int top, int reach) {
  const GridSpec& s = grid.spec;
  std::vector<int> highest(s.column_count(), -1);
  const int lo = std::max(levels.floor + 1, 0), hi = std::min(top, s.ny) - 1;
  if (hi < lo) return highest;
  std::vector<std::uint8_t> seen(s.voxel_count(), 0);
  std::vector<std::size_t> stack, part;
  const auto push = [&](int x, int y, int z) {
    if (x < 0 || z < 0 || x >= s.nx || z >= s.nz || y < lo || y > hi) return;
    const std::size_t col = s.column(x, z), i = s.index(x, y, z);
    if (!room[col] || seen[i] || grid.cells[i]) return;
    seen[i] = 1;
    stack.push_back(i);
  };
  const std::size_t ny = std::size_t(s.ny);
  for (int z0 = 0; z0 < s.nz; ++z0)
    for (int x0 = 0; x0 < s.nx; ++x0) {
      push(x0, lo, z0);
      part.clear();
      int part_top = -1;
      while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        part.push_back(i);
        const std::size_t col = i / ny;
        const int y = int(i % ny), x = int(col % std::size_t(s.nx)), z = int(col / std::size_t(s.nx));
        part_top = std::max(part_top, y);
        push(x, y + 1, z);
        push(x, y - 1, z);
        push(x + 1, y, z);
        push(x - 1, y, z);
        push(x, y, z + 1);
        push(x, y, z - 1);
      }
      if (part_top < reach) continue;
      for (const std::size_t i : part) highest[i / ny] = std::max(highest[i / ny], int(i % ny));
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
  std::vector<std::size_t> stack, part;
  for (std::size_t seed = 0; seed < facet_of.size(); ++seed) {
    if (direction[seed] < 0 || facet_of[seed] != kNoFacet) continue;
    const int id = int(facets.size());
    part.clear();
    stack.assign(1, seed);
    facet_of[seed] = id;
    const int steep = direction[seed] == 0 ? 1 : 2;
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      part.push_back(c);
      const int x = int(c % std::size_t(s.nx)), z = int(c / std::size_t(s.nx));
      const int nbr[4][2] = {{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}};
      for (const auto& n : nbr) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= s.nx || n[1] >= s.nz) continue;
        const std::size_t nc = s.column(n[0], n[1]);
        if (facet_of[nc] != kNoFacet || direction[nc] != direction[seed] || std::abs(ceiling[nc] - ceiling[c]) > steep)
          continue;
        facet_of[nc] = id;
        stack.push_back(nc);
      }
    }
    // A level ceiling a voxel below I_Ceiling is the ceiling's own unevenness (a scan's jitter), no step.
    double sum = 0.0;
    for (const std::size_t c : part) sum += double(ceiling[c]);
    const bool step = direction[seed] != 0 || sum <= double(part.size()) * double(levels.ceiling - 2);
    if (part.size() < min_columns || !step) {
      for (const std::size_t c : part) facet_of[c] = -2;  // seen, on no facet
      continue;
    }
    // Least squares of level = a x + b z + d over the facet's tiles (column centres).
    glm::dmat3 m(0.0);
    glm::dvec3 r(0.0);
    double mean = 0.0;
    for (const std::size_t c : part) {
      const glm::dvec3 p(double(c % std::size_t(s.nx)) + 0.5, double(c / std::size_t(s.nx)) + 0.5, 1.0);
      const double level = double(ceiling[c]);
      m += glm::outerProduct(p, p);
      r += p * level;
      mean += level;
    }
    mean /= double(part.size());
    CeilingFacet f{int(std::lround(mean)) - 1, part.size(), 0.0f, 0.0f, float(mean)};
    if (std::fabs(glm::determinant(m)) > 1e-9) {
      const glm::dvec3 k = glm::inverse(m) * r;
      f.slope_x = float(k.x), f.slope_z = float(k.y), f.offset = float(k.z);
    }
    facets.push_back(f);
  }
  for (int& f : facet_of)
    if (f == -2) f = kNoFacet;
}

}  // namespace roomsense
