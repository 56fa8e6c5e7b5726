// The demo's XrInstance, destroyed (with its sessions and spaces) when its owner goes.
#pragma once
#include <openxr/openxr.h>

namespace roomsense::demo {

struct Instance {
  XrInstance handle = XR_NULL_HANDLE;
  Instance() = default;
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;
  ~Instance() {
    if (handle != XR_NULL_HANDLE) xrDestroyInstance(handle);
  }
};

}  // namespace roomsense::demo
