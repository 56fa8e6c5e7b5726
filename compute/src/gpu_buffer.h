// A VkBuffer with its own memory allocation, mapped for its whole life when host-visible. The stage owns a
// handful of these and grows them only when a larger grid arrives.
#pragma once
#include "vulkan_context.h"
#include "vulkan_handle.h"

#include <cstddef>
#include <initializer_list>

namespace roomsense::compute {

class GpuBuffer {
 public:
  GpuBuffer() = default;
  // Allocates from the first memory type (in the order of `preferences`) that has all the flags of a
  // preference; throws VulkanError or std::runtime_error when none fits.
  GpuBuffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
            std::initializer_list<VkMemoryPropertyFlags> preferences);

  VkBuffer get() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }  // nullptr unless host-visible
  explicit operator bool() const { return static_cast<bool>(buffer_); }

 private:
  // memory_ is declared first: the buffer is destroyed before its memory is freed.
  DeviceChild<VkDeviceMemory> memory_;
  DeviceChild<VkBuffer> buffer_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;  // freed with memory_ (vkFreeMemory unmaps)
};

// The first memory type allowed by `type_bits` with every flag of `wanted`, or -1.
int find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t type_bits, VkMemoryPropertyFlags wanted);

}  // namespace roomsense::compute
