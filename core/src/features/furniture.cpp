// Furniture levels C (Eq. 3.13).
#include "roomsense/features.h"

#include <algorithm>

namespace roomsense {

std::vector<int> detect_furniture(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                                  const std::vector<std::uint8_t>& walls, int clear_levels) {
  const GridSpec& s = grid.spec;
  std::vector<int> furniture(s.column_count(), kNoFurniture);
  const int top = std::min(y_end, s.ny - 1);
  for (std::size_t col = 0; col < furniture.size(); ++col) {
    if (walls[col]) continue;
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    // The maximum of f_Level over (I_Floor, I_yEnd] is the highest qualifying y: walk down from I_yEnd.
    // `next` is the lowest active level above y (or ny), so "no voxel in (y, f_Limit(y)]" is next > limit.
    int next = s.ny;
    for (int y = std::min(s.ny - 1, std::max(top, y_end + clear_levels)); y > top; --y)
      if (v[y]) next = y;
    for (int y = top; y > levels.floor; --y) {
      if (v[y]) {
        const int limit = std::max(y + clear_levels, y_end);  // f_Limit (DESIGN.md's reading of Eq. 3.13)
        if (limit < levels.ceiling && next > limit) {
          furniture[col] = y + 1;
          break;
        }
        next = y;
      }
    }
  }
  return furniture;
}

}  // namespace roomsense
