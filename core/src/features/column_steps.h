// The steps of §3.2 that decide each column from that column alone: its voxels and its own entries of the
// walls, the room's inside and the ceiling. detect_furniture, detect_free_floor and detect_free_ceiling run them
// over every column; an IncrementalAnalysis runs them again only where a column's voxels or entries changed
// (feature_memo.h).
#pragma once
#include "roomsense/features.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace roomsense::detail {

// C (Eq. 3.13) of one column: the level above its furniture top, or kNoFurniture.
class FurnitureTop {
 public:
  FurnitureTop(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling, int y_end,
               const std::vector<std::uint8_t>& walls, int clear_levels, int rough_levels)
      : grid_(grid), levels_(levels), ceiling_(ceiling), walls_(walls), y_end_(y_end), clear_(clear_levels),
        rough_(rough_levels) {}
  int operator()(std::size_t col) const;

 private:
  const VoxelGrid& grid_;
  const FloorCeiling& levels_;
  const std::vector<int>& ceiling_;
  const std::vector<std::uint8_t>& walls_;
  int y_end_, clear_, rough_;
};

// D (Eq. 3.14) of one column: 1 where it is a free floor tile.
class FreeFloorTile {
 public:
  FreeFloorTile(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling, int y_end,
                const std::vector<std::uint8_t>& walls, const std::vector<std::uint8_t>& room, int rough_levels,
                int headroom_levels)
      : grid_(grid), levels_(levels), ceiling_(ceiling), walls_(walls), room_(room), y_end_(y_end),
        rough_(rough_levels), headroom_(headroom_levels) {}
  std::uint8_t operator()(std::size_t col) const;

 private:
  const VoxelGrid& grid_;
  const FloorCeiling& levels_;
  const std::vector<int>& ceiling_;
  const std::vector<std::uint8_t>& walls_;
  const std::vector<std::uint8_t>& room_;
  int y_end_, rough_, headroom_;
};

// E (Eq. 3.15) of one column: 1 where it is a free ceiling tile.
class FreeCeilingTile {
 public:
  FreeCeilingTile(const VoxelGrid& grid, const std::vector<int>& ceiling, int clear_levels,
                  const std::vector<std::uint8_t>& walls, const std::vector<std::uint8_t>& room)
      : grid_(grid), ceiling_(ceiling), walls_(walls), room_(room), clear_(clear_levels) {}
  std::uint8_t operator()(std::size_t col) const;

 private:
  const VoxelGrid& grid_;
  const std::vector<int>& ceiling_;
  const std::vector<std::uint8_t>& walls_;
  const std::vector<std::uint8_t>& room_;
  int clear_;
};

// `step` of every column, as a vector.
template <class Value, class Step>
std::vector<Value> every_column(std::size_t columns, const Step& step) {
  std::vector<Value> out(columns);
  for (std::size_t col = 0; col < columns; ++col) out[col] = step(col);
  return out;
}

}  // namespace roomsense::detail
