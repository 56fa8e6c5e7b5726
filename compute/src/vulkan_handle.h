// Move-only owners for Vulkan objects: a device child is destroyed with its device's destroy function,
// an instance or device with its own. No raw owning handles leave these wrappers.
#pragma once
#include "vulkan_functions.h"

#include <utility>

namespace roomsense::compute {

// Every vkDestroy*/vkFree* of a device child has this shape.
template <class Handle>
using DestroyDeviceChild = void(VKAPI_PTR*)(VkDevice, Handle, const VkAllocationCallbacks*);

template <class Handle>
class DeviceChild {
 public:
  DeviceChild() = default;
  DeviceChild(VkDevice device, Handle handle, DestroyDeviceChild<Handle> destroy)
      : device_(device), handle_(handle), destroy_(destroy) {}
  DeviceChild(DeviceChild&& other) noexcept { swap(other); }
  DeviceChild& operator=(DeviceChild&& other) noexcept {
    DeviceChild(std::move(other)).swap(*this);
    return *this;
  }
  DeviceChild(const DeviceChild&) = delete;
  DeviceChild& operator=(const DeviceChild&) = delete;
  ~DeviceChild() {
    if (handle_ != VK_NULL_HANDLE && destroy_ != nullptr) destroy_(device_, handle_, nullptr);
  }

  Handle get() const { return handle_; }
  const Handle* address() const { return &handle_; }  // for calls taking an array of handles
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

 private:
  void swap(DeviceChild& other) noexcept {
    std::swap(device_, other.device_);
    std::swap(handle_, other.handle_);
    std::swap(destroy_, other.destroy_);
  }
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
  DestroyDeviceChild<Handle> destroy_ = nullptr;
};

// An owner for a handle destroyed by a call that takes only the handle (instance, device).
template <class Handle>
class RootObject {
 public:
  using Destroy = void(VKAPI_PTR*)(Handle, const VkAllocationCallbacks*);
  RootObject() = default;
  RootObject(Handle handle, Destroy destroy) : handle_(handle), destroy_(destroy) {}
  RootObject(RootObject&& other) noexcept
      : handle_(std::exchange(other.handle_, VK_NULL_HANDLE)), destroy_(other.destroy_) {}
  RootObject& operator=(RootObject&&) = delete;
  RootObject(const RootObject&) = delete;
  RootObject& operator=(const RootObject&) = delete;
  ~RootObject() {
    if (handle_ != VK_NULL_HANDLE && destroy_ != nullptr) destroy_(handle_, nullptr);
  }
  Handle get() const { return handle_; }

 private:
  Handle handle_ = VK_NULL_HANDLE;
  Destroy destroy_ = nullptr;
};

}  // namespace roomsense::compute
