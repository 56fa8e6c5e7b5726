// Vulkan failures inside the backend are thrown as VulkanError and caught at the stage's boundary, where
// they become a "why not" string (creation) or a fallback to the CPU (a run).
#pragma once
#include "vulkan_functions.h"

#include <stdexcept>
#include <string>

namespace roomsense::compute {

const char* result_name(VkResult result);

class VulkanError : public std::runtime_error {
 public:
  VulkanError(VkResult result, const std::string& what)
      : std::runtime_error(what + " failed: " + result_name(result)), result_(result) {}
  VkResult result() const noexcept { return result_; }

 private:
  VkResult result_;
};

inline void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw VulkanError(result, what);
}

}  // namespace roomsense::compute
