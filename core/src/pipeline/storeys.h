// Storeys of a scan (internal to the pipeline): the main floor/ceiling pair and the others, beyond the thesis.
#pragma once
#include "roomsense/voxelize.h"

#include <cstdint>
#include <span>
#include <vector>

namespace roomsense::detail {

// Per level, the voxels with an empty voxel right above or right below: horizontal surfaces. A wall's voxels
// stack up in their column, so they count only where the wall ends. The same on any number of threads.
std::vector<std::uint32_t> horizontal_counts(const VoxelGrid& grid, unsigned threads = 1);
// The same from `previous`'s counts `before`, counted again in the columns `changed` marks (where `grid` and
// `previous`, of one spec, differ).
std::vector<std::uint32_t> horizontal_counts(const VoxelGrid& grid, const VoxelGrid& previous,
                                             std::vector<std::uint32_t> before, const std::vector<std::uint8_t>& changed);

struct StoreyLevels {
  FloorCeiling main;                 // the voxel stage's pair, or the storey of it that holds its fuller level
  std::vector<FloorCeiling> others;  // bottom to top
};

// Eq. 3.9/3.10 pick the two fullest levels, which in a house can be the ground floor and the top ceiling.
// A pair is split at each slab between them: levels at least `min_separation` from both ends whose horizontal
// count is at least a quarter of the ends' (walls hardly count there, furniture rarely covers a quarter of the
// floor); levels closer than `min_separation` to each other are one slab, the lower storey's ceiling its lowest
// level and the upper storey's floor its highest. Further pairs are searched above and below, among levels
// holding at least a quarter of the stage's floor count, and split the same way.
StoreyLevels find_storeys(std::span<const std::uint32_t> level_counts, std::span<const std::uint32_t> horizontal,
                          const FloorCeiling& stage_pair, int min_separation);

}  // namespace roomsense::detail
