// A headless OpenXR session through the Khronos loader, for the layer's benchmarks (layer_overhead.cpp,
// layer_compute.cpp): instance (XR_MND_headless and the given extensions), system, session and a LOCAL space.
// Failures throw with the call and its XrResult.
#pragma once
#include <openxr/openxr.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace roomsense::bench {

inline void check(XrResult r, const char* what) {
  if (XR_FAILED(r)) throw std::runtime_error(std::string(what) + " returned " + std::to_string(r));
}

struct HeadlessSession {
  XrInstance instance = XR_NULL_HANDLE;
  XrSession session = XR_NULL_HANDLE;
  XrSpace local = XR_NULL_HANDLE;

  explicit HeadlessSession(std::vector<const char*> extensions) {
    extensions.insert(extensions.begin(), XR_MND_HEADLESS_EXTENSION_NAME);
    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO, nullptr, 0, {}, 0, nullptr,
                              static_cast<uint32_t>(extensions.size()), extensions.data()};
    std::strcpy(info.applicationInfo.applicationName, "roomsense_bench_layer");
    info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    check(xrCreateInstance(&info, &instance), "xrCreateInstance");
    try {
      XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO, nullptr, XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY};
      XrSystemId system = XR_NULL_SYSTEM_ID;
      check(xrGetSystem(instance, &system_info, &system), "xrGetSystem");
      XrSessionCreateInfo session_info{XR_TYPE_SESSION_CREATE_INFO, nullptr, 0, system};
      check(xrCreateSession(instance, &session_info, &session), "xrCreateSession");
      local = reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
    } catch (...) {
      xrDestroyInstance(instance);
      throw;
    }
  }
  ~HeadlessSession() { xrDestroyInstance(instance); }  // the session and spaces with it
  HeadlessSession(const HeadlessSession&) = delete;
  HeadlessSession& operator=(const HeadlessSession&) = delete;

  XrSpace reference_space(XrReferenceSpaceType type) const {
    XrReferenceSpaceCreateInfo info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO, nullptr, type, {{0, 0, 0, 1}, {0, 0, 0}}};
    XrSpace space = XR_NULL_HANDLE;
    check(xrCreateReferenceSpace(session, &info, &space), "xrCreateReferenceSpace");
    return space;
  }
  template <typename F>
  F proc(const char* name) const {
    PFN_xrVoidFunction f = nullptr;
    check(xrGetInstanceProcAddr(instance, name, &f), name);
    return reinterpret_cast<F>(f);
  }
};

}  // namespace roomsense::bench
