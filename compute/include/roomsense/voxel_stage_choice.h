// The voxel stage for a backend choice (roomsense/backend.h): the CPU stage, or the Vulkan one where it is
// asked for, or where Auto finds a real GPU and a workload past the crossover.
#pragma once
#include "roomsense/backend.h"
#include "roomsense/voxelize.h"

#include <cstddef>
#include <memory>
#include <string>

namespace roomsense {

// The stage for `backend`. Auto weighs `workload` (estimate_voxel_workload before there is a grid) against
// kVulkanCrossoverTriangles. Never returns nullptr: when Vulkan is asked for but unavailable, it returns the
// CPU stage and says why in *note (also set to a one-line account of the choice otherwise).
std::unique_ptr<VoxelStage> make_voxel_stage(Backend backend, const VoxelWorkload& workload,
                                             std::string* note = nullptr);

}  // namespace roomsense
