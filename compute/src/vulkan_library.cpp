#include "vulkan_library.h"

namespace roomsense::compute {

VulkanLibrary::VulkanLibrary() : library_(platform::vulkan_loader_name()) {
  const std::string name = platform::vulkan_loader_name();
  if (!library_.loaded()) {
    error_ = "cannot load " + name + " (is a Vulkan loader installed?): " + library_.error();
    return;
  }
  auto& f = functions_;
  f.vkGetInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(library_.symbol("vkGetInstanceProcAddr"));
  if (f.vkGetInstanceProcAddr == nullptr) {
    error_ = name + " has no vkGetInstanceProcAddr";
    return;
  }
#define ROOMSENSE_VK_LOAD(name) f.name = reinterpret_cast<PFN_##name>(f.vkGetInstanceProcAddr(VK_NULL_HANDLE, #name));
  ROOMSENSE_VK_GLOBAL_FUNCTIONS(ROOMSENSE_VK_LOAD)
#undef ROOMSENSE_VK_LOAD
  // vkEnumerateInstanceVersion is missing only from a Vulkan 1.0 loader; the shaders need 1.1.
  if (f.vkCreateInstance == nullptr || f.vkEnumerateInstanceVersion == nullptr)
    error_ = "the Vulkan loader is older than Vulkan 1.1";
}

const VulkanLibrary* VulkanLibrary::get(std::string* why) {
  // Opened on first use, thread-safely (a function-local static), and reported the same way every time.
  static const VulkanLibrary library;
  if (!library.error_.empty()) {
    if (why != nullptr) *why = library.error_;
    return nullptr;
  }
  return &library;
}

}  // namespace roomsense::compute
