// Which columns of a voxel grid changed between two versions of it: what the incremental features and bounds
// derive again (issue 19).
#pragma once
#include "roomsense/grid.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace roomsense::detail {

// 1 for each column whose voxels differ between `a` and `b`: the cells of grids of `ny` levels and one size,
// column after column.
std::vector<std::uint8_t> changed_columns(std::size_t ny, std::span<const std::uint8_t> a, std::span<const std::uint8_t> b);
// The same for two grids of one GridSpec.
std::vector<std::uint8_t> changed_columns(const VoxelGrid& a, const VoxelGrid& b);
// Copies the columns of `from` that `which` marks (1 per column) into `to`, grids of `ny` levels and one size.
void copy_columns(std::size_t ny, std::span<const std::uint8_t> from, std::span<std::uint8_t> to,
                  std::span<const std::uint8_t> which);

}  // namespace roomsense::detail
