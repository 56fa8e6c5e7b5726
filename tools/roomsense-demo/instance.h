// The demo's XrInstance, destroyed when its owner goes: with it the session, spaces, analyzer, contexts and
// snapshots made from it.
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
