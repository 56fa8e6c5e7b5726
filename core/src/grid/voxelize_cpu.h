// The CPU voxelizer's instruction choice (internal to core and its tests).
#pragma once
#include "roomsense/voxelize.h"

#include <cstdint>
#include <span>

namespace roomsense::detail {

// Which instructions the voxelizer's two hottest loops (each vertex's cell, the small triangles' pass) are
// compiled for. x86-64's baseline has SSE2 alone, which has no 32-bit integer minimum or maximum and no blend:
// each minimum or maximum of a triangle's corners' cells takes four instructions there, one in SSE4.1. Where
// the CPU has SSE4.1, a copy of those loops built for it runs (thesis-room1's voxelization 1.41 -> 1.24 ms on
// one thread, this project's VM); it marks the same voxels, as only integer lanes and selects change.
// Elsewhere (ARM, or a build for SSE4.1 and up) there is one copy.
enum class VoxelInstructions { Best, Baseline };
bool voxel_sse41_copy();  // whether Best runs a copy of its own on this CPU and build

// voxelize_cpu_into with the loops of `instructions` (tests compare the copies).
void voxelize_cpu_into(const VoxelizeRequest& request, VoxelGrid& grid, unsigned threads, std::uint64_t* tests_done,
                       VoxelInstructions instructions);

// to_grid_units into out[0, world.size()), which it need not find zeroed: an analysis maps a whole scan's vertices
// into memory it does not clear first (clearing a 76k-vertex scan's 0.9 MB took one thread some 0.05 ms while the
// other waited).
void to_grid_units_into(std::span<const glm::vec3> world, const GridSpec& spec, unsigned threads, glm::vec3* out);

// count_columns's counts and flags of the columns `which` marks (1 per column), counted again into counts and any,
// which hold the counts on these levels of a grid that differs from this one only there.
void count_columns_again(const VoxelGrid& grid, const FloorCeiling& levels, std::span<const std::uint8_t> which,
                         std::vector<std::uint32_t>& counts, std::vector<std::uint8_t>& any);

}  // namespace roomsense::detail
