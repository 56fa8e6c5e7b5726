// Choosing the voxel-stage backend: `--backend`, ROOMSENSE_BACKEND, or the extension's create info. The choice
// is core's; the Vulkan stage it may pick lives in compute/ (voxel_stage_choice.h: make_voxel_stage).
#pragma once
#include "roomsense/grid.h"
#include "roomsense/scan.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace roomsense {

enum class Backend { Auto, Cpu, Vulkan };

// "auto", "cpu" or "vulkan" (any case). Throws Error(BadParameter) with one clear line otherwise.
Backend parse_backend(std::string_view text);
const char* to_string(Backend backend);

// ROOMSENSE_BACKEND when it is set and valid, else `fallback`. An invalid value is ignored with a line in
// *note, so a typo in the environment cannot stop an app.
Backend backend_from_environment(Backend fallback = Backend::Auto, std::string* note = nullptr);

// What a voxel stage will have to do, known before there is a grid: Auto's input.
struct VoxelWorkload {
  std::size_t voxels = 0;     // the grid's voxel count (GridSpec::voxel_count, or estimated from the scan)
  std::size_t triangles = 0;  // triangles to voxelize; 0 in vertex mode
};

// Auto picks Vulkan only on a discrete or integrated GPU, and only where it wins end to end with its start
// included: the CLI starts a stage for each run, the layer one for each analyzer. Measured on an H100 (NVIDIA
// driver 580; compute/README.md): a stage starts in 310-370 ms, then voxelizes 2M triangles in 4.9 ms,
// transfers included, where the CPU path takes 44 ms on two threads: about 20 ns saved per triangle. So
// Vulkan wins past about 16-18M triangles. Vertex mode never gets there within the grid budget (about 5 ms
// per million voxels on the CPU), and past the budget (kDefaultVoxelBudget), which the analysis refuses,
// Auto probes no device.
inline constexpr std::size_t kVulkanCrossoverTriangles = std::size_t{1} << 24;

// The workload side of Auto's rule; the device side is a discrete or integrated GPU.
inline bool auto_may_pick_vulkan(const VoxelWorkload& w) {
  return w.voxels <= kDefaultVoxelBudget && w.triangles >= kVulkanCrossoverTriangles;
}

// The workload of analysing `scan` at `voxel_size` in triangle mode: the voxel count of the grid its finite
// extents need, before outlier rejection (0 for a scan without finite vertices), and its triangles.
VoxelWorkload estimate_voxel_workload(const Scan& scan, float voxel_size);
// The same from the finite vertices' bounds (lo > hi: none) and the triangle count, as a caller that keeps them
// per mesh has them.
VoxelWorkload voxel_workload(const glm::vec3& lo, const glm::vec3& hi, std::size_t triangles, float voxel_size);

}  // namespace roomsense
