// The triangle pass's further work. The device runs every triangle's first chunk of kChunkVoxels box voxels,
// counts the boxes' tests and lists the triangles whose boxes are bigger (shaders/voxelize_triangles.comp);
// the host turns that list into an item (triangle, chunk) per further chunk, here, for a second dispatch.
// That spreads a big triangle over many invocations and bounds every invocation's loop (lavapipe ends an
// invocation silently after 65535 loop iterations), while the host does no work per triangle: listing every
// triangle on the host cost more than all the GPU passes together (compute/README.md).
#pragma once
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace roomsense::compute {

inline constexpr std::uint32_t kChunkVoxels = 512;  // kChunkVoxels in shaders/voxelize_triangles.comp

// Appends (t, k) word pairs, k = 1 .. the last chunk of t's box, for each triangle t of `big`, in that order.
// Boxes follow voxelize_cpu.cpp exactly (box_index: floor, then clamp into the grid), as the shader's do.
void list_extra_chunks(std::span<const glm::vec3> grid_vertices, std::span<const std::uint32_t> indices, int nx,
                       int ny, int nz, std::span<const std::uint32_t> big, std::vector<std::uint32_t>& extra);

}  // namespace roomsense::compute
