// Which physical device runs the voxel stage: a discrete GPU first, then an integrated one, then a virtual
// one, then the CPU (lavapipe). Among equals the loader's order decides. A device qualifies when it speaks
// Vulkan 1.1 (the SPIR-V target), has a compute queue, and binds the four storage buffers the shaders use.
#pragma once
#include "vulkan_functions.h"

#include <cstdint>
#include <span>

namespace roomsense::compute {

struct DeviceCandidate {
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t api_version = 0;
  bool has_compute_queue = false;
  std::uint32_t max_storage_buffers_per_stage = 0;
};

inline constexpr std::uint32_t kStorageBuffersUsed = 4;

// Lower is better.
int device_type_rank(VkPhysicalDeviceType type);
bool device_qualifies(const DeviceCandidate& candidate);
// The index of the best qualifying candidate, or -1.
int choose_device(std::span<const DeviceCandidate> candidates);

}  // namespace roomsense::compute
