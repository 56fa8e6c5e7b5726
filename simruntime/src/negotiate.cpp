// Loader negotiation (the library's only exported symbol) and xrGetInstanceProcAddr.
#include "extensions/served_extension.h"
#include "process_state.h"
#include "functions.h"
#include "roomsense/platform.h"
#include "roomsense/xr/loader_interface.h"
#include "runtime.h"
#include "validate.h"

#include <cstring>
#include <string_view>
#include <unordered_map>

namespace roomsense::sim {
namespace {

// A stub with any PFN's signature that reports the function as unsupported.
template <typename PFN>
struct Unsupported;
template <typename... Args>
struct Unsupported<XrResult(XRAPI_PTR*)(Args...)> {
  static XrResult XRAPI_CALL call(Args...) { return XR_ERROR_FUNCTION_UNSUPPORTED; }
};

struct Entry {
  PFN_xrVoidFunction function;
  const char* extension;  // null for core functions
};

const std::unordered_map<std::string_view, Entry>& function_table() {
  static const std::unordered_map<std::string_view, Entry> table = [] {
    std::unordered_map<std::string_view, Entry> t;
#define SIM_CORE(name) t.emplace(#name, Entry{reinterpret_cast<PFN_xrVoidFunction>(&sim::name), nullptr});
#define SIM_UNSUPPORTED(name) \
  t.emplace(#name, Entry{reinterpret_cast<PFN_xrVoidFunction>(&Unsupported<PFN_##name>::call), nullptr});
    SIM_CORE_FUNCTIONS(SIM_CORE)
    SIM_UNSUPPORTED_CORE_FUNCTIONS(SIM_UNSUPPORTED)
    for (const ServedExtension* e : served_extensions())
      for (const ServedFunction& f : e->functions) t.emplace(f.name, Entry{f.function, e->name});
#undef SIM_CORE
#undef SIM_UNSUPPORTED
    return t;
  }();
  return table;
}

}  // namespace

XrResult XRAPI_CALL xrGetInstanceProcAddr(XrInstance instance, const char* name, PFN_xrVoidFunction* function) {
  return guarded("xrGetInstanceProcAddr", [&]() -> XrResult {
    if (function == nullptr || name == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *function = nullptr;
    const std::string_view wanted(name);
    if (instance == XR_NULL_HANDLE) {
      // The only functions callable before an instance exists.
      if (wanted != "xrEnumerateInstanceExtensionProperties" && wanted != "xrEnumerateApiLayerProperties" &&
          wanted != "xrCreateInstance")
        return XR_ERROR_HANDLE_INVALID;
      *function = function_table().at(wanted).function;
      return XR_SUCCESS;
    }
    std::lock_guard lock(runtime().mutex);
    const InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    const auto it = function_table().find(wanted);
    if (it == function_table().end()) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (it->second.extension != nullptr && !state->has(it->second.extension)) return XR_ERROR_FUNCTION_UNSUPPORTED;
    *function = it->second.function;
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim

extern "C" ROOMSENSE_PLUGIN_EXPORT XrResult XRAPI_CALL
xrNegotiateLoaderRuntimeInterface(const XrNegotiateLoaderInfo* loaderInfo, XrNegotiateRuntimeRequest* runtimeRequest) {
  if (loaderInfo == nullptr || runtimeRequest == nullptr) return XR_ERROR_INITIALIZATION_FAILED;
  if (loaderInfo->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      loaderInfo->structVersion != XR_LOADER_INFO_STRUCT_VERSION || loaderInfo->structSize != sizeof(XrNegotiateLoaderInfo))
    return XR_ERROR_INITIALIZATION_FAILED;
  if (runtimeRequest->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
      runtimeRequest->structVersion != XR_RUNTIME_INFO_STRUCT_VERSION ||
      runtimeRequest->structSize != sizeof(XrNegotiateRuntimeRequest))
    return XR_ERROR_INITIALIZATION_FAILED;
  // We speak loader interface 1 and OpenXR 1.0.
  constexpr uint32_t kInterface = 1;
  if (loaderInfo->minInterfaceVersion > kInterface || loaderInfo->maxInterfaceVersion < kInterface)
    return XR_ERROR_INITIALIZATION_FAILED;
  const XrVersion api = XR_MAKE_VERSION(1, 0, XR_VERSION_PATCH(XR_CURRENT_API_VERSION));
  if (XR_VERSION_MAJOR(loaderInfo->minApiVersion) > 1 || XR_VERSION_MAJOR(loaderInfo->maxApiVersion) < 1)
    return XR_ERROR_INITIALIZATION_FAILED;
  roomsense::sim::ProcessState::holder();  // made before any API layer's first call: process_state.h says why
  runtimeRequest->runtimeInterfaceVersion = kInterface;
  runtimeRequest->runtimeApiVersion = api;
  runtimeRequest->getInstanceProcAddr = &roomsense::sim::xrGetInstanceProcAddr;
  return XR_SUCCESS;
}
