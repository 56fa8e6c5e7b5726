#include "checked_calls.h"

#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <cstdint>

namespace roomsense::demo {
namespace {

// The results this app can meet, by name: the loader's xrResultToString needs an instance, and the runtime
// underneath may not know the extensions' values.
const char* known_result_name(XrResult r) {
  switch (static_cast<int64_t>(r)) {  // the extensions' values are not members of 1.0.20's XrResult
#define RS_RESULT(name) \
  case name:            \
    return #name;
    RS_RESULT(XR_SUCCESS)
    RS_RESULT(XR_TIMEOUT_EXPIRED)
    RS_RESULT(XR_SESSION_LOSS_PENDING)
    RS_RESULT(XR_EVENT_UNAVAILABLE)
    RS_RESULT(XR_ERROR_VALIDATION_FAILURE)
    RS_RESULT(XR_ERROR_RUNTIME_FAILURE)
    RS_RESULT(XR_ERROR_OUT_OF_MEMORY)
    RS_RESULT(XR_ERROR_API_VERSION_UNSUPPORTED)
    RS_RESULT(XR_ERROR_INITIALIZATION_FAILED)
    RS_RESULT(XR_ERROR_FUNCTION_UNSUPPORTED)
    RS_RESULT(XR_ERROR_FEATURE_UNSUPPORTED)
    RS_RESULT(XR_ERROR_EXTENSION_NOT_PRESENT)
    RS_RESULT(XR_ERROR_LIMIT_REACHED)
    RS_RESULT(XR_ERROR_SIZE_INSUFFICIENT)
    RS_RESULT(XR_ERROR_HANDLE_INVALID)
    RS_RESULT(XR_ERROR_INSTANCE_LOST)
    RS_RESULT(XR_ERROR_SESSION_RUNNING)
    RS_RESULT(XR_ERROR_SESSION_NOT_RUNNING)
    RS_RESULT(XR_ERROR_SESSION_LOST)
    RS_RESULT(XR_ERROR_SYSTEM_INVALID)
    RS_RESULT(XR_ERROR_FORM_FACTOR_UNSUPPORTED)
    RS_RESULT(XR_ERROR_FORM_FACTOR_UNAVAILABLE)
    RS_RESULT(XR_ERROR_API_LAYER_NOT_PRESENT)
    RS_RESULT(XR_ERROR_CALL_ORDER_INVALID)
    RS_RESULT(XR_ERROR_GRAPHICS_DEVICE_INVALID)
    RS_RESULT(XR_ERROR_POSE_INVALID)
    RS_RESULT(XR_ERROR_TIME_INVALID)
    RS_RESULT(XR_ERROR_REFERENCE_SPACE_UNSUPPORTED)
    RS_RESULT(XR_ERROR_NAME_INVALID)
    RS_RESULT(XR_ERROR_RUNTIME_UNAVAILABLE)
    RS_RESULT(XR_ERROR_FUTURE_PENDING_EXT)
    RS_RESULT(XR_ERROR_FUTURE_INVALID_EXT)
    RS_RESULT(XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT)
    RS_RESULT(XR_ERROR_SPATIAL_ENTITY_ID_INVALID_EXT)
    RS_RESULT(XR_ERROR_SPATIAL_BUFFER_ID_INVALID_EXT)
    RS_RESULT(XR_ERROR_SPATIAL_COMPONENT_UNSUPPORTED_FOR_CAPABILITY_EXT)
    RS_RESULT(XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT)
    RS_RESULT(XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT)
#undef RS_RESULT
    default:
      return nullptr;
  }
}

}  // namespace

std::string result_name(XrInstance instance, XrResult r) {
  if (const char* name = known_result_name(r)) return name;
  char text[XR_MAX_RESULT_STRING_SIZE] = {};
  if (instance != XR_NULL_HANDLE && XR_SUCCEEDED(xrResultToString(instance, r, text))) return text;
  return "XrResult " + std::to_string(static_cast<int>(r));
}

}  // namespace roomsense::demo
