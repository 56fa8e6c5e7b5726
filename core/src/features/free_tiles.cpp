// Free floor tiles D (Eq. 3.14) and free ceiling tiles E (Eq. 3.15).
#include "roomsense/features.h"

#include <algorithm>

namespace roomsense {
namespace {

// 1 where the column is no wall, lies in the room, and has no active voxel in [from, to[column]]; a column
// with to < 0 is not clear.
template <class From, class To>
std::vector<std::uint8_t> clear_columns(const VoxelGrid& grid, From from_of, To to_of,
                                        const std::vector<std::uint8_t>& walls, const std::vector<std::uint8_t>& room) {
  const GridSpec& s = grid.spec;
  std::vector<std::uint8_t> out(s.column_count(), 0);
  for (std::size_t col = 0; col < out.size(); ++col) {
    if (walls[col] || !room[col] || to_of(col) < 0) continue;
    const int from = std::max(from_of(col), 0), to = std::min(to_of(col), s.ny - 1);
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    out[col] = from > to || std::none_of(v + from, v + to + 1, [](std::uint8_t c) { return c != 0; }) ? 1 : 0;
  }
  return out;
}

}  // namespace

std::vector<std::uint8_t> detect_free_floor(const VoxelGrid& grid, const FloorCeiling& levels,
                                            const std::vector<int>& ceiling, int y_end,
                                            const std::vector<std::uint8_t>& walls,
                                            const std::vector<std::uint8_t>& room, int rough_levels,
                                            int headroom_levels) {
  // Beyond the thesis: voxels within the floor's roughness above I_Floor are floor (a rug, a sloping scan);
  // under a ceiling lower than I_yEnd (a roof's eaves) the column must be clear up to it, and high enough.
  std::vector<int> to(ceiling.size());
  for (std::size_t col = 0; col < to.size(); ++col) {
    to[col] = ceiling[col] < levels.ceiling ? std::min(y_end, ceiling[col] - 1) : y_end;
    if (ceiling[col] - levels.floor < headroom_levels) to[col] = -1;
  }
  const int from = levels.floor + 1 + rough_levels;
  std::vector<std::uint8_t> out =
      clear_columns(grid, [from](std::size_t) { return from; }, [&to](std::size_t col) { return to[col]; }, walls, room);
  // Beyond the thesis: B fills the patches of floor the scan missed, but a column with no floor voxel that
  // has scanned surface further down looks down a drop (a stairwell, a gallery's edge): no free floor.
  const GridSpec& s = grid.spec;
  const int band_lo = std::max(levels.floor_peak - 1, 0), band_hi = std::min(levels.floor + rough_levels, s.ny - 1);
  const auto any = [](const std::uint8_t* b, const std::uint8_t* e) { return std::find(b, e, std::uint8_t{1}) != e; };
  for (std::size_t col = 0; col < out.size(); ++col) {
    if (!out[col]) continue;
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    if (!any(v + band_lo, v + band_hi + 1) && any(v, v + band_lo)) out[col] = 0;
  }
  return out;
}

std::vector<std::uint8_t> detect_free_ceiling(const VoxelGrid& grid, const std::vector<int>& ceiling,
                                              int clear_levels, const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room) {
  // DESIGN.md's reading of the garbled Eq. 3.15: y in [I_yStart, I_Ceiling - 1], I_yStart = I_Ceiling - ⌊1/S⌋;
  // beyond the thesis, below each column's own ceiling (its facet, find_ceiling_facets, says which plane).
  return clear_columns(
      grid, [&](std::size_t col) { return ceiling[col] - clear_levels; },
      [&](std::size_t col) { return ceiling[col] - 1; }, walls, room);
}

}  // namespace roomsense
