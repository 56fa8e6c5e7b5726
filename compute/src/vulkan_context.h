// Instance, debug messenger, chosen physical device, logical device and compute queue: everything the voxel
// stage needs from Vulkan before it builds pipelines. Members are declared in destruction order.
#pragma once
#include "roomsense/vulkan_voxel_stage.h"
#include "vulkan_functions.h"
#include "vulkan_handle.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace roomsense::compute {

using LogFn = std::function<void(std::string_view)>;

struct ContextOptions {
  bool validation = false;
  bool require_validation = false;
  bool create_device = true;  // false: stop after choosing the physical device (probing)
  LogFn log;
};

class VulkanContext {
 public:
  // nullptr with the reason in *why_not; never throws for a missing or broken Vulkan.
  static std::unique_ptr<VulkanContext> create(const ContextOptions& options, std::string* why_not);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  const DeviceFunctions& vk() const { return device_fns_; }
  VkDevice device() const { return device_ ? device_->get() : VK_NULL_HANDLE; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceMemoryProperties& memory() const { return memory_; }
  std::uint32_t timestamp_valid_bits() const { return timestamp_valid_bits_; }
  const VulkanDeviceInfo& info() const { return info_; }
  bool validation_enabled() const { return validation_enabled_; }
  std::uint64_t validation_messages() const { return validation_messages_.load(); }
  void log(std::string_view line) const;

 private:
  VulkanContext() = default;
  void init(const ContextOptions& options);
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                          VkDebugUtilsMessageTypeFlagsEXT types,
                                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                          void* user);
  VkDebugUtilsMessengerCreateInfoEXT messenger_info();

  LogFn log_;
  std::atomic<std::uint64_t> validation_messages_{0};
  bool validation_enabled_ = false;
  InstanceFunctions instance_fns_;
  DeviceFunctions device_fns_;
  std::optional<RootObject<VkInstance>> instance_;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;  // destroyed in ~VulkanContext, before the instance
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  std::uint32_t queue_family_ = 0;
  std::uint32_t timestamp_valid_bits_ = 0;
  VulkanDeviceInfo info_;
  std::optional<RootObject<VkDevice>> device_;
  VkQueue queue_ = VK_NULL_HANDLE;  // owned by the device
};

GpuKind gpu_kind(VkPhysicalDeviceType type);

}  // namespace roomsense::compute
