// Furniture levels C (Eq. 3.13).
#include "roomsense/features.h"

#include <algorithm>

namespace roomsense {

std::vector<int> detect_furniture(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling,
                                  int y_end, const std::vector<std::uint8_t>& walls, int clear_levels, int rough_levels) {
  const GridSpec& s = grid.spec;
  std::vector<int> furniture(s.column_count(), kNoFurniture);
  const int top = std::min(y_end, s.ny - 1);
  for (std::size_t col = 0; col < furniture.size(); ++col) {
    if (walls[col]) continue;
    const std::uint8_t* v = grid.cells.data() + col * std::size_t(s.ny);
    // Beyond the thesis: the space above a top must be clear up to the column's own ceiling.
    const int below = std::min(levels.ceiling, ceiling[col]);
    // The maximum of f_Level over (I_Floor, I_yEnd] is the highest qualifying y: walk down from I_yEnd.
    // `next` is the lowest active level above y (or ny), so "no voxel in (y, f_Limit(y)]" is next > limit.
    int next = s.ny;
    for (int y = std::min(s.ny - 1, std::max(top, y_end + clear_levels)); y > top; --y)
      if (v[y]) next = y;
    // Beyond the thesis: a top within the floor's roughness is a bump in the floor, not furniture.
    for (int y = top; y > levels.floor + rough_levels; --y) {
      if (v[y]) {
        const int limit = std::max(y + clear_levels, y_end);  // f_Limit (DESIGN.md's reading of Eq. 3.13)
        if (limit < below && next > limit) {
          furniture[col] = y + 1;
          break;
        }
        next = y;
      }
    }
  }
  return furniture;
}

void apply_furniture_labels(const GridSpec& spec, const FloorCeiling& levels, const LabelGrid& labels,
                            std::vector<std::uint8_t>& free_floor, std::vector<int>& furniture) {
  // Beyond the thesis (issue 14): the runtime knows a couch, a bed, a plant from a box of voxels. Only labels
  // the runtime uses count: a runtime that labels no furniture says nothing about it.
  if (labels.empty()) return;
  const bool standing = labels.has_any(kStandingLabels), tops = labels.has_any(kFurnitureTopLabels);
  for (int z = 0; z < spec.nz; ++z)
    for (int x = 0; x < spec.nx; ++x) {
      const std::size_t col = spec.column(x, z);
      if (standing && free_floor[col])
        for (int y = levels.floor + 1; y < levels.ceiling && free_floor[col]; ++y)
          if (labels.at(spec, x, y, z) & kStandingLabels) free_floor[col] = 0;
      if (tops && furniture[col] != kNoFurniture) {
        // C holds the level above the top voxel (Eq. 3.13); the label's plane may sit a voxel off.
        bool labelled = false;
        for (int y = furniture[col] - 2; y <= furniture[col] && !labelled; ++y)
          labelled = (labels.at(spec, x, y, z) & kFurnitureTopLabels) != 0;
        if (!labelled) furniture[col] = kNoFurniture;
      }
    }
}

}  // namespace roomsense
