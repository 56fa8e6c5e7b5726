// The Vulkan loader (libvulkan.so.1, vulkan-1.dll: platform.h), opened once per process. The handle is the
// backend's only global: the loader stays mapped for the life of the process, so instances created by several
// stages share it.
#pragma once
#include "vulkan_functions.h"

#include "roomsense/platform.h"

#include <string>

namespace roomsense::compute {

class VulkanLibrary {
 public:
  // The process-wide library, or nullptr with the reason in *why (no Vulkan loader, no entry point, or a
  // loader older than Vulkan 1.1).
  static const VulkanLibrary* get(std::string* why);

  const GlobalFunctions& functions() const { return functions_; }

  VulkanLibrary(const VulkanLibrary&) = delete;
  VulkanLibrary& operator=(const VulkanLibrary&) = delete;
  ~VulkanLibrary() = default;

 private:
  VulkanLibrary();  // opens the library; error_ says why not
  platform::SharedLibrary library_;
  GlobalFunctions functions_;
  std::string error_;
};

}  // namespace roomsense::compute
