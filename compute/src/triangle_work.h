// The triangle pass's work, sized on the host. Every triangle is one item of the pass (its box's first
// kChunkVoxels voxels); a box of more voxels gets an extra item (triangle, chunk) per further kChunkVoxels,
// listed here. That spreads a big triangle over many GPU invocations and bounds every invocation's loop
// (lavapipe ends an invocation silently after 65535 loop iterations), while the list stays as short as the
// big triangles: an item per triangle on the host cost more than the whole GPU pass (compute/README.md).
#pragma once
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace roomsense::compute {

inline constexpr std::uint32_t kChunkVoxels = 512;  // kChunkVoxels in shaders/voxelize_triangles.comp

struct TriangleWork {
  std::uint64_t tests = 0;           // triangle-voxel tests of every box of more than one voxel
  std::vector<std::uint32_t> extra;  // (triangle, chunk >= 1) word pairs, in triangle order
};

// Fills `work` (its vector's capacity is reused). Bounding boxes follow voxelize_cpu.cpp exactly (floor,
// then clamp into the grid). Returns false, with the list incomplete, as soon as the tests pass `budget`:
// hostile boxes must not make the list itself gigabytes. Past 128k triangles per thread the triangles are
// split over up to `max_threads` threads (0: the hardware's, at most 8); the list does not depend on it.
bool build_triangle_work(std::span<const glm::vec3> grid_vertices, std::span<const std::uint32_t> indices, int nx,
                         int ny, int nz, std::uint64_t budget, TriangleWork& work, unsigned max_threads = 0);

}  // namespace roomsense::compute
