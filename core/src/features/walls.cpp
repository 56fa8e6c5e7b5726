// Wall columns A (Eq. 3.11) and the room mask B (Eq. 3.12).
#include "roomsense/features.h"
#include "surfaces/regions.h"

#include <algorithm>
#include <cmath>

namespace roomsense {

int voxels_for(float metres, float voxel_size) { return int(std::floor(metres / voxel_size + 1e-4f)); }

std::vector<std::uint8_t> detect_walls(const GridSpec& spec, const std::vector<std::uint32_t>& column_counts,
                                       const FloorCeiling& levels, const std::vector<int>& over_walls, float wall_fill) {
  // |V_xz| > (I_Ceiling - I_Floor) * 0.5, compared in double to keep the thesis's strict inequality exact.
  std::vector<std::uint8_t> walls(spec.column_count(), 0);
  for (std::size_t c = 0; c < walls.size(); ++c) {
    const double threshold = double(std::min(over_walls[c], levels.ceiling) - levels.floor) * double(wall_fill);
    walls[c] = double(column_counts[c]) > threshold ? 1 : 0;
  }
  return walls;
}

std::vector<int> wall_ceilings(const GridSpec& spec, const FloorCeiling& levels, const std::vector<int>& ceiling,
                               const std::vector<std::uint8_t>& room, int step_levels, std::size_t min_columns) {
  // Only a lower ceiling over a wide stretch counts (a roof's eaves, a soffit): a pocket above a cabinet that
  // the floor's free space does not reach is no ceiling of the cabinet's sides.
  const detail::Components parts = detail::label_components(
      spec.nx, spec.nz, [&](std::size_t c) { return room[c] && ceiling[c] <= levels.ceiling - step_levels; },
      [](std::size_t, std::size_t) { return true; });
  // Without a wide lower ceiling every column's is the storey's, its neighbours' highest included (most rooms).
  if (std::none_of(parts.sizes.begin(), parts.sizes.end(), [&](std::size_t n) { return n >= min_columns; }))
    return std::vector<int>(spec.column_count(), levels.ceiling);
  std::vector<int> wide(ceiling.size(), levels.ceiling);
  for (std::size_t c = 0; c < wide.size(); ++c)
    if (parts.label[c] >= 0 && parts.sizes[std::size_t(parts.label[c])] >= min_columns) wide[c] = ceiling[c];
  // The highest over the column and its 8 neighbours in the room, not the column's own: a window's lintel is
  // no ceiling of the columns under it, while a room's side under a roof's eaves has nothing higher.
  std::vector<int> out(spec.column_count(), levels.ceiling);
  for (int z = 0; z < spec.nz; ++z)
    for (int x = 0; x < spec.nx; ++x) {
      int top = -1;
      for (int dz = -1; dz <= 1; ++dz)
        for (int dx = -1; dx <= 1; ++dx)
          if (x + dx >= 0 && z + dz >= 0 && x + dx < spec.nx && z + dz < spec.nz && room[spec.column(x + dx, z + dz)])
            top = std::max(top, wide[spec.column(x + dx, z + dz)]);
      if (top >= 0) out[spec.column(x, z)] = top;
    }
  return out;
}

std::vector<std::uint8_t> detect_room(const GridSpec& spec, const std::vector<std::uint8_t>& column_any) {
  // First case of Eq. 3.12 is column_any; the second fills a hole with >= 3 of 4 active neighbours. The
  // neighbours are read from the first case, not from cells filled in the same pass, so the order of the
  // pass does not matter.
  std::vector<std::uint8_t> room = column_any;
  const auto any = [&](int x, int z) {
    return x >= 0 && z >= 0 && x < spec.nx && z < spec.nz ? int(column_any[spec.column(x, z)]) : 0;
  };
  for (int z = 0; z < spec.nz; ++z)
    for (int x = 0; x < spec.nx; ++x)
      if (!column_any[spec.column(x, z)] && any(x + 1, z) + any(x - 1, z) + any(x, z + 1) + any(x, z - 1) >= 3)
        room[spec.column(x, z)] = 1;
  return room;
}

void drop_free_standing(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& over_walls,
                        int gap_levels, std::vector<std::uint8_t>& walls) {
  // Beyond the thesis (issue 14): Eq. 3.11 makes any column fuller than half the room a wall, so a cabinet, a
  // screen or a shelf taller than that reads as wall and gets wall areas on its side. Walls reach the ceiling;
  // where a scan barely reaches it, most walls end at the same lower height, which then serves instead. Under
  // a lower ceiling (a roof's slope, a soffit) the ceiling over the wall (wall_ceilings) serves.
  const GridSpec& s = grid.spec;
  std::vector<int> top(walls.size(), -1);
  std::vector<int> tops;
  for (std::size_t col = 0; col < walls.size(); ++col) {
    if (!walls[col]) continue;
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    for (int y = std::min(levels.ceiling - 1, s.ny - 1); y >= levels.floor; --y)
      if (v[y]) {
        top[col] = y;
        break;
      }
    tops.push_back(top[col]);
  }
  if (tops.empty()) return;
  // The height most walls reach: the upper quartile of the wall columns' tops.
  const auto quartile = tops.begin() + std::ptrdiff_t(3 * (tops.size() - 1) / 4);
  std::nth_element(tops.begin(), quartile, tops.end());
  const int reference = std::min(*quartile, levels.ceiling - 1);
  for (std::size_t col = 0; col < walls.size(); ++col)
    if (walls[col] && top[col] < std::min(reference, over_walls[col] - 1) - gap_levels) walls[col] = 0;
}

}  // namespace roomsense
