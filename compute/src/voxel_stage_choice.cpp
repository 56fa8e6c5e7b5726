// The backend factory. Auto picks Vulkan only where it wins end to end, its start included: on a real GPU
// and past kVulkanCrossoverTriangles (roomsense/backend.h, compute/README.md); lavapipe never wins.
#include "roomsense/voxel_stage_choice.h"

#include "roomsense/vulkan_voxel_stage.h"

#include <string>

namespace roomsense {
namespace {

void set(std::string* note, std::string text) {
  if (note != nullptr) *note = std::move(text);
}

}  // namespace

std::unique_ptr<VoxelStage> make_voxel_stage(Backend backend, const VoxelWorkload& workload, std::string* note) {
  if (backend == Backend::Cpu) {
    set(note, "cpu: requested");
    return std::make_unique<CpuVoxelStage>();
  }
  if (backend == Backend::Auto) {
    if (!auto_may_pick_vulkan(workload)) {
      // A grid past the default budget is refused before any voxel stage runs (make_grid_spec): starting a GPU
      // driver in the app's process for it would be work, and driver state, for nothing.
      if (workload.voxels > kDefaultVoxelBudget)
        set(note, "cpu: auto, " + std::to_string(workload.voxels) + " voxels is past the grid budget of " +
                      std::to_string(kDefaultVoxelBudget) + ": no device probed");
      else
        set(note, "cpu: auto, " + std::to_string(workload.triangles) + " triangles is below the Vulkan crossover of " +
                      std::to_string(kVulkanCrossoverTriangles) + " (a Vulkan stage's start costs more than it saves)");
      return std::make_unique<CpuVoxelStage>();
    }
    std::string why;
    const std::optional<VulkanDeviceInfo> device = probe_vulkan_device(&why);
    if (!device) {
      set(note, "cpu: auto, Vulkan unavailable: " + why);
      return std::make_unique<CpuVoxelStage>();
    }
    if (device->kind != GpuKind::Discrete && device->kind != GpuKind::Integrated) {
      set(note, "cpu: auto, the best Vulkan device (" + device->name + ", " + to_string(device->kind) +
                    ") is slower than the CPU path");
      return std::make_unique<CpuVoxelStage>();
    }
  }
  std::string why;
  std::unique_ptr<VulkanVoxelStage> stage = VulkanVoxelStage::create({}, &why);
  if (!stage) {
    set(note, "cpu: Vulkan unavailable: " + why);
    return std::make_unique<CpuVoxelStage>();
  }
  set(note, std::string("vulkan: ") + (backend == Backend::Auto ? "auto" : "requested") + ", on " + stage->device().name +
                " (" + to_string(stage->device().kind) + ")");
  return stage;
}

}  // namespace roomsense
