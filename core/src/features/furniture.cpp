// Furniture levels C (Eq. 3.13).
#include "column_steps.h"
#include "roomsense/features.h"

#include <algorithm>

namespace roomsense {

int detail::FurnitureTop::operator()(std::size_t col) const {
  if (walls_[col]) return kNoFurniture;
  const GridSpec& s = grid_.spec;
  const int top = std::min(y_end_, s.ny - 1);
  const std::uint8_t* v = grid_.cells.data() + col * std::size_t(s.ny);
  // Beyond the thesis: the space above a top must be clear up to the column's own ceiling.
  const int below = std::min(levels_.ceiling, ceiling_[col]);
  // The maximum of f_Level over (I_Floor, I_yEnd] is the highest qualifying y: walk down from I_yEnd.
  // `next` is the lowest active level above y (or ny), so "no voxel in (y, f_Limit(y)]" is next > limit.
  int next = s.ny;
  for (int y = std::min(s.ny - 1, std::max(top, y_end_ + clear_)); y > top; --y)
    if (v[y]) next = y;
  // Beyond the thesis: a top within the floor's roughness is a bump in the floor, not furniture.
  for (int y = top; y > levels_.floor + rough_; --y) {
    if (v[y]) {
      const int limit = std::max(y + clear_, y_end_);  // f_Limit (DESIGN.md's reading of Eq. 3.13)
      if (limit < below && next > limit) return y + 1;
      next = y;
    }
  }
  return kNoFurniture;
}

std::vector<int> detect_furniture(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling,
                                  int y_end, const std::vector<std::uint8_t>& walls, int clear_levels, int rough_levels) {
  return detail::every_column<int>(grid.spec.column_count(),
                                   detail::FurnitureTop(grid, levels, ceiling, y_end, walls, clear_levels, rough_levels));
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
