// The one system: a head-mounted display with a stereo view configuration that never renders.
#include "functions.h"
#include "runtime.h"
#include "validate.h"
#include "roomsense/xr/ext/XR_ANDROID_scene_meshing.h"

#include <cstring>

namespace roomsense::sim {
namespace {


// Common prologue: a live instance and our system id.
XrResult check_system(XrInstance instance, XrSystemId systemId) {
  if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
  return systemId == kSystemId ? XR_SUCCESS : XR_ERROR_SYSTEM_INVALID;
}

}  // namespace

XrResult XRAPI_CALL xrGetSystem(XrInstance instance, const XrSystemGetInfo* getInfo, XrSystemId* systemId) {
  return guarded("xrGetSystem", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(getInfo, XR_TYPE_SYSTEM_GET_INFO) || systemId == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    // Any other value, defined or not, is a form factor this runtime does not support (the CTS asks for this
    // code for XR_FORM_FACTOR_MAX_ENUM too).
    if (getInfo->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY) return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
    *systemId = kSystemId;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetSystemProperties(XrInstance instance, XrSystemId systemId, XrSystemProperties* properties) {
  return guarded("xrGetSystemProperties", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (XrResult r = check_system(instance, systemId); r != XR_SUCCESS) return r;
    if (!has_type(properties, XR_TYPE_SYSTEM_PROPERTIES)) return XR_ERROR_VALIDATION_FAILURE;
    properties->systemId = kSystemId;
    properties->vendorId = 0x5253;  // "RS"
    std::strncpy(properties->systemName, kSystemName, XR_MAX_SYSTEM_NAME_SIZE - 1);
    properties->systemName[XR_MAX_SYSTEM_NAME_SIZE - 1] = '\0';
    // Headless sessions have no swapchains, but the limits are the system's: the spec's minimum of 16 layers,
    // and images at least as large as the views' maximum image rectangles.
    properties->graphicsProperties = {kMaxSwapchainImageSize, kMaxSwapchainImageSize, kMaxLayerCount};
    properties->trackingProperties = {XR_TRUE, XR_TRUE};
    if (auto* meshing = find_next<XrSystemSceneMeshingPropertiesANDROID>(properties->next, XR_TYPE_SYSTEM_SCENE_MESHING_PROPERTIES_ANDROID))
      meshing->supportsSceneMeshing = runtime().instance(instance)->has(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME) ? XR_TRUE : XR_FALSE;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrEnumerateEnvironmentBlendModes(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                                     uint32_t capacity, uint32_t* countOutput, XrEnvironmentBlendMode* modes) {
  return guarded("xrEnumerateEnvironmentBlendModes", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (XrResult r = check_system(instance, systemId); r != XR_SUCCESS) return r;
    if (!is_view_configuration_type(type)) return XR_ERROR_VALIDATION_FAILURE;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    return two_call(capacity, countOutput, modes, std::vector<XrEnvironmentBlendMode>{XR_ENVIRONMENT_BLEND_MODE_OPAQUE});
  });
}

XrResult XRAPI_CALL xrEnumerateViewConfigurations(XrInstance instance, XrSystemId systemId, uint32_t capacity,
                                                  uint32_t* countOutput, XrViewConfigurationType* types) {
  return guarded("xrEnumerateViewConfigurations", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (XrResult r = check_system(instance, systemId); r != XR_SUCCESS) return r;
    return two_call(capacity, countOutput, types, std::vector<XrViewConfigurationType>{XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO});
  });
}

XrResult XRAPI_CALL xrGetViewConfigurationProperties(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                                     XrViewConfigurationProperties* properties) {
  return guarded("xrGetViewConfigurationProperties", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (XrResult r = check_system(instance, systemId); r != XR_SUCCESS) return r;
    if (!has_type(properties, XR_TYPE_VIEW_CONFIGURATION_PROPERTIES) || !is_view_configuration_type(type)) return XR_ERROR_VALIDATION_FAILURE;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    properties->viewConfigurationType = type;
    properties->fovMutable = XR_FALSE;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrEnumerateViewConfigurationViews(XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
                                                      uint32_t capacity, uint32_t* countOutput, XrViewConfigurationView* views) {
  return guarded("xrEnumerateViewConfigurationViews", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (XrResult r = check_system(instance, systemId); r != XR_SUCCESS) return r;
    if (!is_view_configuration_type(type)) return XR_ERROR_VALIDATION_FAILURE;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    return two_call_typed(capacity, countOutput, views, 2, XR_TYPE_VIEW_CONFIGURATION_VIEW, [](XrViewConfigurationView& v, std::size_t) {
      v.recommendedImageRectWidth = v.maxImageRectWidth = 1024;
      v.recommendedImageRectHeight = v.maxImageRectHeight = 1024;
      v.recommendedSwapchainSampleCount = v.maxSwapchainSampleCount = 1;
    });
  });
}

}  // namespace roomsense::sim
