#include "device_choice.h"

namespace roomsense::compute {

int device_type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

bool device_qualifies(const DeviceCandidate& c) {
  return c.api_version >= VK_API_VERSION_1_1 && c.has_compute_queue &&
         c.max_storage_buffers_per_stage >= kStorageBuffersUsed;
}

int choose_device(std::span<const DeviceCandidate> candidates) {
  int best = -1;
  for (int i = 0; i < int(candidates.size()); ++i) {
    const DeviceCandidate& c = candidates[std::size_t(i)];
    if (!device_qualifies(c)) continue;
    if (best < 0 || device_type_rank(c.type) < device_type_rank(candidates[std::size_t(best)].type)) best = i;
  }
  return best;
}

}  // namespace roomsense::compute
