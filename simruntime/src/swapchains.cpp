// Swapchains in a headless session (XR_MND_headless): there are no formats, so no swapchain can be created,
// and every call on a swapchain handle finds none. Each answer is one the spec allows for the function.
#include "functions.h"
#include "runtime.h"
#include "validate.h"

#include <vector>

namespace roomsense::sim {

XrResult XRAPI_CALL xrEnumerateSwapchainFormats(XrSession session, uint32_t formatCapacityInput, uint32_t* formatCountOutput,
                                                int64_t* formats) {
  return guarded("xrEnumerateSwapchainFormats", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    return two_call(formatCapacityInput, formatCountOutput, formats, std::vector<int64_t>{});  // headless: none
  });
}

XrResult XRAPI_CALL xrCreateSwapchain(XrSession session, const XrSwapchainCreateInfo* createInfo, XrSwapchain* swapchain) {
  return guarded("xrCreateSwapchain", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_SWAPCHAIN_CREATE_INFO) || swapchain == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;  // whatever the format, it is not among the (zero) enumerated ones
  });
}

// No swapchain handle is ever valid.
XrResult XRAPI_CALL xrDestroySwapchain(XrSwapchain) {
  return guarded("xrDestroySwapchain", [] { return XR_ERROR_HANDLE_INVALID; });
}

XrResult XRAPI_CALL xrEnumerateSwapchainImages(XrSwapchain, uint32_t, uint32_t*, XrSwapchainImageBaseHeader*) {
  return guarded("xrEnumerateSwapchainImages", [] { return XR_ERROR_HANDLE_INVALID; });
}

XrResult XRAPI_CALL xrAcquireSwapchainImage(XrSwapchain, const XrSwapchainImageAcquireInfo*, uint32_t*) {
  return guarded("xrAcquireSwapchainImage", [] { return XR_ERROR_HANDLE_INVALID; });
}

XrResult XRAPI_CALL xrWaitSwapchainImage(XrSwapchain, const XrSwapchainImageWaitInfo*) {
  return guarded("xrWaitSwapchainImage", [] { return XR_ERROR_HANDLE_INVALID; });
}

XrResult XRAPI_CALL xrReleaseSwapchainImage(XrSwapchain, const XrSwapchainImageReleaseInfo*) {
  return guarded("xrReleaseSwapchainImage", [] { return XR_ERROR_HANDLE_INVALID; });
}

}  // namespace roomsense::sim
