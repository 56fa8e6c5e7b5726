// Choosing the voxel-stage backend: `--backend`, ROOMSENSE_BACKEND, or the extension's create info. The choice
// is core's; the Vulkan stage it may pick lives in compute/ (voxel_stage_choice.h: make_voxel_stage).
#pragma once
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

// Auto picks Vulkan only on a discrete or integrated GPU and for grids of at least this many voxels; below
// it, or on lavapipe, the CPU path is faster (measured: compute/README.md). Past the default grid budget
// (kDefaultVoxelBudget), which the analysis refuses, it probes no device.
inline constexpr std::size_t kVulkanCrossoverVoxels = std::size_t{1} << 21;

// The voxel count of the grid a scan's finite extents need, before outlier rejection: the size hint for
// make_voxel_stage's Auto choice. 0 for a scan without finite vertices.
std::size_t estimated_voxel_count(const Scan& scan, float voxel_size);

}  // namespace roomsense
