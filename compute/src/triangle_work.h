// The triangle pass's work list, built on the host: one item (triangle, chunk) per kChunkVoxels voxels of
// each triangle's bounding box. It spreads a big triangle over many GPU invocations and bounds every
// invocation's loop (lavapipe ends an invocation silently after 65535 loop iterations).
#pragma once
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace roomsense::compute {

inline constexpr std::uint32_t kChunkVoxels = 512;  // kChunkVoxels in shaders/voxelize_triangles.comp

// The triangle-voxel tests of the triangle pass: the voxels of every box of more than one voxel.
std::uint64_t count_box_tests(std::span<const glm::vec3> grid_vertices, std::span<const std::uint32_t> indices, int nx,
                              int ny, int nz);

// Appends the items as word pairs to `out`. Bounding boxes follow voxelize_cpu.cpp exactly (floor, then
// clamp into the grid); a box of a single voxel gets one item, which marks it without a test, as the CPU does.
void build_triangle_work(std::span<const glm::vec3> grid_vertices, std::span<const std::uint32_t> indices, int nx,
                         int ny, int nz, std::vector<std::uint32_t>& out);

}  // namespace roomsense::compute
