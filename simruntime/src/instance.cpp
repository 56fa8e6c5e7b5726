// Instance creation and properties, extension enumeration, XR_KHR_convert_timespec_time.
#include "extensions/served_extension.h"
#include "functions.h"
#include "log.h"
#include "runtime.h"
#include "validate.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

namespace roomsense::sim {
namespace {

// The extensions this instance may advertise and enable (ROOMSENSE_SIM_EXTENSIONS); a bad value advertises
// none of the scene extensions and fails xrCreateInstance with one line.
std::vector<const ServedExtension*> advertised_or_base() {
  try {
    return advertised_extensions();
  } catch (const std::invalid_argument&) {
    std::vector<const ServedExtension*> base;
    for (const ServedExtension* e : served_extensions())
      if (!e->scene) base.push_back(e);
    return base;
  }
}

}  // namespace

XrResult XRAPI_CALL xrEnumerateApiLayerProperties(uint32_t capacity, uint32_t* countOutput, XrApiLayerProperties* properties) {
  return guarded("xrEnumerateApiLayerProperties", [&] {
    // Layers are the loader's business; a runtime has none of its own.
    return two_call_typed(capacity, countOutput, properties, 0, XR_TYPE_API_LAYER_PROPERTIES, [](XrApiLayerProperties&, std::size_t) {});
  });
}

XrResult XRAPI_CALL xrEnumerateInstanceExtensionProperties(const char* layerName, uint32_t capacity, uint32_t* countOutput,
                                                           XrExtensionProperties* properties) {
  return guarded("xrEnumerateInstanceExtensionProperties", [&]() -> XrResult {
    if (layerName != nullptr && *layerName != '\0') return XR_ERROR_API_LAYER_NOT_PRESENT;
    const std::vector<const ServedExtension*> extensions = advertised_or_base();
    return two_call_typed(capacity, countOutput, properties, extensions.size(), XR_TYPE_EXTENSION_PROPERTIES,
                          [&](XrExtensionProperties& p, std::size_t i) {
                            std::strncpy(p.extensionName, extensions[i]->name, XR_MAX_EXTENSION_NAME_SIZE - 1);
                            p.extensionName[XR_MAX_EXTENSION_NAME_SIZE - 1] = '\0';
                            p.extensionVersion = extensions[i]->version;
                          });
  });
}

XrResult XRAPI_CALL xrCreateInstance(const XrInstanceCreateInfo* createInfo, XrInstance* instance) {
  return guarded("xrCreateInstance", [&]() -> XrResult {
    if (!has_type(createInfo, XR_TYPE_INSTANCE_CREATE_INFO) || instance == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->createFlags != 0) return XR_ERROR_VALIDATION_FAILURE;
    const XrApplicationInfo& app = createInfo->applicationInfo;
    if (!terminated(app.applicationName, sizeof app.applicationName) || !terminated(app.engineName, sizeof app.engineName))
      return XR_ERROR_VALIDATION_FAILURE;
    if (app.applicationName[0] == '\0') return XR_ERROR_NAME_INVALID;
    if (XR_VERSION_MAJOR(app.apiVersion) != 1 || XR_VERSION_MINOR(app.apiVersion) != 0) return XR_ERROR_API_VERSION_UNSUPPORTED;
    if (createInfo->enabledExtensionCount > 0 && createInfo->enabledExtensionNames == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    // Layers were resolved by the loader; their names are not ours to check.

    std::vector<const ServedExtension*> advertised;
    try {
      advertised = advertised_extensions();
    } catch (const std::invalid_argument& e) {
      log_error(e.what());
      return XR_ERROR_INITIALIZATION_FAILED;
    }
    auto state = std::make_unique<InstanceState>();
    for (uint32_t i = 0; i < createInfo->enabledExtensionCount; ++i) {
      const char* name = createInfo->enabledExtensionNames[i];
      if (name == nullptr) return XR_ERROR_VALIDATION_FAILURE;
      if (std::none_of(advertised.begin(), advertised.end(), [&](const ServedExtension* e) { return std::strcmp(e->name, name) == 0; }))
        return XR_ERROR_EXTENSION_NOT_PRESENT;
      state->extensions.insert(name);
    }
    try {
      state->config = config_from_environment();
    } catch (const std::invalid_argument& e) {
      log_error(e.what());
      return XR_ERROR_INITIALIZATION_FAILED;
    }
    if (!state->config.scene_path.empty()) {
      // Loaded now, so a wrong path fails loudly at the first call rather than at the first scene compute.
      try {
        state->room = load_room(state->config.scene_path);
      } catch (const std::exception& e) {
        log_error(std::string("ROOMSENSE_SIM_SCENE: ") + e.what());
        return XR_ERROR_INITIALIZATION_FAILED;
      }
      if (state->config.scan_seconds > 0.0) {
        const XrVector3f& head = state->config.head_pose.position;
        state->scan = std::make_shared<ScanProgress>(state->room, state->config.chunk_size, glm::dvec3(head.x, head.y, head.z),
                                                     state->config.scan_seconds, now_time());
      }
    }
    std::lock_guard lock(runtime().mutex);
    const std::uint64_t id = runtime().new_id();
    runtime().instances.emplace(id, std::move(state));
    *instance = handle_of<XrInstance>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroyInstance(XrInstance instance) {
  return guarded("xrDestroyInstance", [&]() -> XrResult {
    Runtime::Graveyard graveyard;  // destroyed after the lock is released (joins compute threads)
    std::lock_guard lock(runtime().mutex);
    if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    runtime().destroy_instance(id_of(instance), graveyard);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetInstanceProperties(XrInstance instance, XrInstanceProperties* properties) {
  return guarded("xrGetInstanceProperties", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(properties, XR_TYPE_INSTANCE_PROPERTIES)) return XR_ERROR_VALIDATION_FAILURE;
    properties->runtimeVersion = XR_MAKE_VERSION(0, 1, 0);
    std::strncpy(properties->runtimeName, kRuntimeName, XR_MAX_RUNTIME_NAME_SIZE - 1);
    properties->runtimeName[XR_MAX_RUNTIME_NAME_SIZE - 1] = '\0';
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrConvertTimespecTimeToTimeKHR(XrInstance instance, const struct timespec* timespecTime, XrTime* time) {
  return guarded("xrConvertTimespecTimeToTimeKHR", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (timespecTime == nullptr || time == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (timespecTime->tv_sec < 0 || timespecTime->tv_nsec < 0 || timespecTime->tv_nsec >= 1000000000) return XR_ERROR_TIME_INVALID;
    *time = static_cast<XrTime>(timespecTime->tv_sec) * 1000000000 + timespecTime->tv_nsec;  // XrTime is CLOCK_MONOTONIC ns
    return *time > 0 ? XR_SUCCESS : XR_ERROR_TIME_INVALID;
  });
}

XrResult XRAPI_CALL xrConvertTimeToTimespecTimeKHR(XrInstance instance, XrTime time, struct timespec* timespecTime) {
  return guarded("xrConvertTimeToTimespecTimeKHR", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (timespecTime == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (time <= 0) return XR_ERROR_TIME_INVALID;
    timespecTime->tv_sec = static_cast<time_t>(time / 1000000000);
    timespecTime->tv_nsec = static_cast<long>(time % 1000000000);
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim
