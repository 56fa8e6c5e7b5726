// Free floor tiles D (Eq. 3.14) and free ceiling tiles E (Eq. 3.15).
#include "column_steps.h"
#include "roomsense/features.h"

#include <algorithm>

namespace roomsense {
namespace {

// Whether column `col` of `grid` has no active voxel in [from, to]; a column with to < 0 is not clear.
bool clear_between(const VoxelGrid& grid, std::size_t col, int from, int to) {
  if (to < 0) return false;
  const GridSpec& s = grid.spec;
  from = std::max(from, 0), to = std::min(to, s.ny - 1);
  const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
  return from > to || std::none_of(v + from, v + to + 1, [](std::uint8_t c) { return c != 0; });
}

}  // namespace

std::uint8_t detail::FreeFloorTile::operator()(std::size_t col) const {
  const auto& [grid, levels, ceiling, walls, room] = in_;
  if (walls[col] || !room[col]) return 0;
  // Beyond the thesis: voxels within the floor's roughness above I_Floor are floor (a rug, a sloping scan);
  // under a ceiling lower than I_yEnd (a roof's eaves) the column must be clear up to it, and high enough.
  const int to = ceiling[col] - levels.floor < headroom_ ? -1
                 : ceiling[col] < levels.ceiling         ? std::min(y_end_, ceiling[col] - 1)
                                                         : y_end_;
  if (!clear_between(grid, col, levels.floor + 1 + rough_, to)) return 0;
  // Beyond the thesis: B fills the patches of floor the scan missed, but a column with no floor voxel that
  // has scanned surface further down looks down a drop (a stairwell, a gallery's edge): no free floor.
  const GridSpec& s = grid.spec;
  const int band_lo = std::max(levels.floor_peak - 1, 0), band_hi = std::min(levels.floor + rough_, s.ny - 1);
  const auto any = [](const std::uint8_t* b, const std::uint8_t* e) { return std::find(b, e, std::uint8_t{1}) != e; };
  const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
  return !any(v + band_lo, v + band_hi + 1) && any(v, v + band_lo) ? 0 : 1;
}

std::uint8_t detail::FreeCeilingTile::operator()(std::size_t col) const {
  // DESIGN.md's reading of the garbled Eq. 3.15: y in [I_yStart, I_Ceiling - 1], I_yStart = I_Ceiling - ⌊1/S⌋;
  // beyond the thesis, below each column's own ceiling (its facet, find_ceiling_facets, says which plane).
  if (walls_[col] || !room_[col]) return 0;
  return clear_between(grid_, col, ceiling_[col] - clear_, ceiling_[col] - 1) ? 1 : 0;
}

std::vector<std::uint8_t> detect_free_floor(const VoxelGrid& grid, const FloorCeiling& levels,
                                            const std::vector<int>& ceiling, int y_end,
                                            const std::vector<std::uint8_t>& walls,
                                            const std::vector<std::uint8_t>& room, int rough_levels,
                                            int headroom_levels) {
  return detail::every_column<std::uint8_t>(
      grid.spec.column_count(),
      detail::FreeFloorTile(grid, levels, ceiling, y_end, walls, room, rough_levels, headroom_levels));
}

std::vector<std::uint8_t> detect_free_ceiling(const VoxelGrid& grid, const std::vector<int>& ceiling,
                                              int clear_levels, const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room) {
  return detail::every_column<std::uint8_t>(grid.spec.column_count(),
                                            detail::FreeCeilingTile(grid, ceiling, clear_levels, walls, room));
}

}  // namespace roomsense
