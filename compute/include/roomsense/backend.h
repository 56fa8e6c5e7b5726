// Choosing the voxel-stage backend: `--backend`, ROOMSENSE_BACKEND, or the extension's create info.
#pragma once
#include "roomsense/scan.h"
#include "roomsense/voxelize.h"

#include <cstddef>
#include <memory>
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

// The stage for `backend`. `problem_size_hint` is the grid's voxel count (GridSpec::voxel_count), used by
// Auto. Never returns nullptr: when Vulkan is asked for but unavailable, it returns the CPU stage and says
// why in *note (also set to a one-line account of the choice otherwise).
// The voxel count of the grid a scan's finite extents need, before outlier rejection: the size hint for
// make_voxel_stage's Auto choice. 0 for a scan without finite vertices.
std::size_t estimated_voxel_count(const Scan& scan, float voxel_size);

std::unique_ptr<VoxelStage> make_voxel_stage(Backend backend, std::size_t problem_size_hint,
                                             std::string* note = nullptr);

}  // namespace roomsense
