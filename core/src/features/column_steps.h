// The steps of §3.2 that decide each column from that column alone (its voxels and its own entries of the walls,
// the room's inside and the ceiling), or from the columns a reach away along the grid's axes (wall normals,
// openings). detect_furniture, detect_free_floor, detect_free_ceiling, detect_wall_normals and
// detect_wall_openings run them over every column; an IncrementalAnalysis runs them again only where a column's
// voxels or entries changed, or within that reach of one (feature_memo.h).
#pragma once
#include "../parallel.h"
#include "roomsense/features.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace roomsense::detail {

// What the steps read of a storey besides their parameters: the grid, the levels, and per column the ceiling,
// the walls and the room (or its inside).
struct StoreyColumns {
  const VoxelGrid& grid;
  const FloorCeiling& levels;
  const std::vector<int>& ceiling;
  const std::vector<std::uint8_t>& walls;
  const std::vector<std::uint8_t>& room;
};

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
      : in_{grid, levels, ceiling, walls, room}, y_end_(y_end), rough_(rough_levels), headroom_(headroom_levels) {}
  std::uint8_t operator()(std::size_t col) const;

 private:
  StoreyColumns in_;
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

// F (Alg. 1) of `normals`, detect_wall_normals's result for these levels and reach on a grid and entries that
// differ from these at the `changed` columns alone: derived again where a wall's run reads one of them.
void update_wall_normals(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<int>& ceiling, int reach,
                         const std::vector<std::uint8_t>& walls, const std::vector<std::uint8_t>& room,
                         const std::vector<int>& furniture, std::span<const std::uint32_t> changed,
                         std::vector<std::uint8_t>& normals);

// The wall openings of `blocked`, detect_wall_openings's result for these levels, walls, labels and parameters
// on a grid and inside that differ from these at the `changed` columns alone: derived again near them.
void update_wall_openings(const VoxelGrid& grid, const FloorCeiling& levels, const std::vector<std::uint8_t>& walls,
                          const std::vector<std::uint8_t>& room, int recess_voxels, int max_opening_voxels,
                          const LabelGrid& labels, std::span<const std::uint32_t> changed,
                          std::vector<std::uint8_t>& blocked);

// Derives a local step's voxels again near a change: each column within `reach` (at least 1) of a `changed`
// column along the x or the z axis has its voxels in `voxels` cleared, then redo(x, z) sets them.
template <class Redo>
void redo_along_axes(const GridSpec& s, std::span<const std::uint32_t> changed, int reach,
                     std::vector<std::uint8_t>& voxels, const Redo& redo) {
  reach = std::max(reach, 1);
  std::vector<std::uint8_t> again(s.column_count(), 0);
  for (const std::uint32_t c : changed) {
    const int x = int(c % std::uint32_t(s.nx)), z = int(c / std::uint32_t(s.nx));
    for (int k = std::max(0, x - reach); k <= std::min(s.nx - 1, x + reach); ++k) again[s.column(k, z)] = 1;
    for (int k = std::max(0, z - reach); k <= std::min(s.nz - 1, z + reach); ++k) again[s.column(x, k)] = 1;
  }
  const auto ny = std::size_t(s.ny);
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x)
      if (again[s.column(x, z)]) {
        std::fill_n(voxels.begin() + std::ptrdiff_t(s.column(x, z) * ny), ny, std::uint8_t{0});
        redo(x, z);
      }
}

// `step` of every column, as a vector, by slices of columns on up to `threads` threads: detect_features runs three
// such steps as tasks beside the room split on two threads, and a thread whose task has ended takes the others'
// slices rather than wait (as three whole tasks, one thread ran two of them on the hall: 8.2 M instructions
// against 6.6 M shared evenly).
template <class Value, class Step>
std::vector<Value> every_column(std::size_t columns, const Step& step, unsigned threads = 1) {
  std::vector<Value> out(columns);
  parallel_for(columns, threads, kColumnGrain, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t col = begin; col < end; ++col) out[col] = step(col);
  });
  return out;
}

}  // namespace roomsense::detail
