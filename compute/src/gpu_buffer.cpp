#include "gpu_buffer.h"

#include "vulkan_error.h"

#include <stdexcept>

namespace roomsense::compute {

int find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t type_bits, VkMemoryPropertyFlags wanted) {
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return int(i);
  return -1;
}

GpuBuffer::GpuBuffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                     std::initializer_list<VkMemoryPropertyFlags> preferences)
    : size_(size) {
  const DeviceFunctions& vk = ctx.vk();
  VkBufferCreateInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bi.size = size;
  bi.usage = usage;
  bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vk.vkCreateBuffer(ctx.device(), &bi, nullptr, &buffer), "vkCreateBuffer");
  buffer_ = DeviceChild<VkBuffer>(ctx.device(), buffer, vk.vkDestroyBuffer);

  VkMemoryRequirements req{};
  vk.vkGetBufferMemoryRequirements(ctx.device(), buffer, &req);
  int type = -1;
  VkMemoryPropertyFlags flags = 0;
  for (VkMemoryPropertyFlags wanted : preferences) {
    type = find_memory_type(ctx.memory(), req.memoryTypeBits, wanted);
    if (type >= 0) {
      flags = ctx.memory().memoryTypes[type].propertyFlags;
      break;
    }
  }
  if (type < 0) throw std::runtime_error("no suitable Vulkan memory type for a buffer");
  VkMemoryAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = std::uint32_t(type);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vk.vkAllocateMemory(ctx.device(), &ai, nullptr, &memory), "vkAllocateMemory");
  memory_ = DeviceChild<VkDeviceMemory>(ctx.device(), memory, vk.vkFreeMemory);
  check(vk.vkBindBufferMemory(ctx.device(), buffer, memory, 0), "vkBindBufferMemory");
  // Host-visible memory is only ever used coherent (see the preferences of the stage), so no flushes.
  if ((flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) != 0)
    check(vk.vkMapMemory(ctx.device(), memory, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
}

}  // namespace roomsense::compute
