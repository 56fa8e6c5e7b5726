// Every core OpenXR function the runtime answers, one line each, so the supported set reads as a list.
// xrGetInstanceProcAddr is generated from these lists (negotiate.cpp) and the served extensions' own
// (extensions/).
#pragma once
#include <openxr/openxr.h>
#include <time.h>
#include <openxr/openxr_platform.h>  // XR_KHR_convert_timespec_time (XR_USE_TIMESPEC is set by the build)

#include <type_traits>

// Core functions that are implemented.
#define SIM_CORE_FUNCTIONS(_)                                                                               \
  _(xrGetInstanceProcAddr) _(xrEnumerateApiLayerProperties) _(xrEnumerateInstanceExtensionProperties)        \
  _(xrCreateInstance) _(xrDestroyInstance) _(xrGetInstanceProperties) _(xrPollEvent) _(xrResultToString)     \
  _(xrStructureTypeToString) _(xrGetSystem) _(xrGetSystemProperties) _(xrEnumerateEnvironmentBlendModes)     \
  _(xrCreateSession) _(xrDestroySession) _(xrEnumerateReferenceSpaces) _(xrCreateReferenceSpace)             \
  _(xrGetReferenceSpaceBoundsRect) _(xrLocateSpace) _(xrDestroySpace) _(xrEnumerateViewConfigurations)       \
  _(xrGetViewConfigurationProperties) _(xrEnumerateViewConfigurationViews) _(xrBeginSession) _(xrEndSession) \
  _(xrRequestExitSession) _(xrWaitFrame) _(xrBeginFrame) _(xrEndFrame) _(xrLocateViews) _(xrStringToPath)    \
  _(xrPathToString) SIM_SWAPCHAIN_FUNCTIONS(_) SIM_ACTION_FUNCTIONS(_)

// Swapchains of a headless session (swapchains.cpp): zero formats, so none can be created.
#define SIM_SWAPCHAIN_FUNCTIONS(_)                                                                          \
  _(xrEnumerateSwapchainFormats) _(xrCreateSwapchain) _(xrDestroySwapchain) _(xrEnumerateSwapchainImages)    \
  _(xrAcquireSwapchainImage) _(xrWaitSwapchainImage) _(xrReleaseSwapchainImage)

// The action system (actions.cpp, input.cpp, action_spaces.cpp): with no device, every action is inactive.
#define SIM_ACTION_FUNCTIONS(_)                                                                             \
  _(xrCreateActionSet) _(xrDestroyActionSet) _(xrCreateAction) _(xrDestroyAction)                            \
  _(xrSuggestInteractionProfileBindings) _(xrAttachSessionActionSets) _(xrGetCurrentInteractionProfile)     \
  _(xrGetActionStateBoolean) _(xrGetActionStateFloat) _(xrGetActionStateVector2f) _(xrGetActionStatePose)    \
  _(xrSyncActions) _(xrEnumerateBoundSourcesForAction) _(xrGetInputSourceLocalizedName)                      \
  _(xrApplyHapticFeedback) _(xrStopHapticFeedback) _(xrCreateActionSpace)

// Core functions that answer XR_ERROR_FUNCTION_UNSUPPORTED: none (every OpenXR 1.0 function is served).
#define SIM_UNSUPPORTED_CORE_FUNCTIONS(_)

// XR_KHR_convert_timespec_time.
#define SIM_TIMESPEC_FUNCTIONS(_) _(xrConvertTimespecTimeToTimeKHR) _(xrConvertTimeToTimespecTimeKHR)

namespace roomsense::sim {
// Declares each implemented function with exactly its PFN's signature.
#define SIM_DECLARE(name) extern std::remove_pointer_t<PFN_##name> name;
SIM_CORE_FUNCTIONS(SIM_DECLARE)
SIM_TIMESPEC_FUNCTIONS(SIM_DECLARE)
#undef SIM_DECLARE
}  // namespace roomsense::sim
