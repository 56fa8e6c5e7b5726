// The frame loop of a headless session: paced at 90 Hz, never asks to render, accepts and ignores layers
// (there are no swapchains to compose). Also xrLocateViews, so an app can ask where the eyes are.
#include "functions.h"
#include "runtime.h"
#include "spaces.h"
#include "validate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace roomsense::sim {
namespace {

constexpr XrDuration kFramePeriod = 11111111;  // ns, 90 Hz
constexpr float kHalfIpd = 0.032f;

}  // namespace

XrResult XRAPI_CALL xrWaitFrame(XrSession session, const XrFrameWaitInfo* frameWaitInfo, XrFrameState* frameState) {
  return guarded("xrWaitFrame", [&]() -> XrResult {
    XrTime display = 0;
    {
      std::lock_guard lock(runtime().mutex);
      SessionState* state = runtime().session(session);
      if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (frameWaitInfo != nullptr && frameWaitInfo->type != XR_TYPE_FRAME_WAIT_INFO) return XR_ERROR_VALIDATION_FAILURE;
      if (!has_type(frameState, XR_TYPE_FRAME_STATE)) return XR_ERROR_VALIDATION_FAILURE;
      if (!state->running) return XR_ERROR_SESSION_NOT_RUNNING;
      display = std::max(state->next_display_time, now_time() + kFramePeriod);
      state->next_display_time = display + kFramePeriod;
      ++state->frames_waited;
      frameState->predictedDisplayTime = display;
      frameState->predictedDisplayPeriod = kFramePeriod;
      frameState->shouldRender = XR_FALSE;  // headless: nothing is ever displayed
    }
    // Throttle like a compositor would, without holding the lock.
    const XrTime wake = display - kFramePeriod;
    const XrTime now = now_time();
    if (wake > now) std::this_thread::sleep_for(std::chrono::nanoseconds(wake - now));
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrBeginFrame(XrSession session, const XrFrameBeginInfo* frameBeginInfo) {
  return guarded("xrBeginFrame", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    SessionState* state = runtime().session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (frameBeginInfo != nullptr && frameBeginInfo->type != XR_TYPE_FRAME_BEGIN_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (!state->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (state->frames_waited == 0) return XR_ERROR_CALL_ORDER_INVALID;
    --state->frames_waited;
    if (state->frame_begun) return XR_FRAME_DISCARDED;  // the previous frame never ended
    state->frame_begun = true;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrEndFrame(XrSession session, const XrFrameEndInfo* frameEndInfo) {
  return guarded("xrEndFrame", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    SessionState* state = runtime().session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(frameEndInfo, XR_TYPE_FRAME_END_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    if (frameEndInfo->layerCount > 0 && frameEndInfo->layers == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (!state->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!state->frame_begun) return XR_ERROR_CALL_ORDER_INVALID;
    if (frameEndInfo->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    const XrEnvironmentBlendMode blend = frameEndInfo->environmentBlendMode;
    if (blend != XR_ENVIRONMENT_BLEND_MODE_OPAQUE && blend != XR_ENVIRONMENT_BLEND_MODE_ADDITIVE &&
        blend != XR_ENVIRONMENT_BLEND_MODE_ALPHA_BLEND)
      return XR_ERROR_VALIDATION_FAILURE;
    if (blend != XR_ENVIRONMENT_BLEND_MODE_OPAQUE) return XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED;
    // Headless: nothing is composed, so the layers' contents (swapchains, views) are ignored; only what the
    // spec asks of every runtime is checked.
    if (frameEndInfo->layerCount > kMaxLayerCount) return XR_ERROR_LAYER_LIMIT_EXCEEDED;
    for (uint32_t i = 0; i < frameEndInfo->layerCount; ++i) {
      const XrCompositionLayerBaseHeader* layer = frameEndInfo->layers[i];
      if (layer == nullptr) return XR_ERROR_LAYER_INVALID;
      if (layer->type != XR_TYPE_COMPOSITION_LAYER_PROJECTION && layer->type != XR_TYPE_COMPOSITION_LAYER_QUAD)
        return XR_ERROR_LAYER_INVALID;
    }
    state->frame_begun = false;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrLocateViews(XrSession session, const XrViewLocateInfo* viewLocateInfo, XrViewState* viewState,
                                  uint32_t capacity, uint32_t* countOutput, XrView* views) {
  return guarded("xrLocateViews", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(viewLocateInfo, XR_TYPE_VIEW_LOCATE_INFO) || !has_type(viewState, XR_TYPE_VIEW_STATE))
      return XR_ERROR_VALIDATION_FAILURE;
    const SpaceState* base = runtime().space(viewLocateInfo->space);
    if (base == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (base->session != id_of(session)) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_view_configuration_type(viewLocateInfo->viewConfigurationType)) return XR_ERROR_VALIDATION_FAILURE;
    if (viewLocateInfo->viewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
      return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (viewLocateInfo->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    if (base->action != 0) {
      // An action space is never located, so neither are the views in it.
      viewState->viewStateFlags = 0;
      return two_call_typed(capacity, countOutput, views, 2, XR_TYPE_VIEW, [](XrView& v, std::size_t) {
        v.pose = {{0, 0, 0, 1}, {0, 0, 0}};
        v.fov = {};
      });
    }
    Rigid base_world;
    if (!space_in_world(*base, base_world)) return XR_ERROR_HANDLE_INVALID;
    const InstanceState* owner = Runtime::find(runtime().instances, runtime().session(session)->instance);
    const Rigid head = base_world.inverse() * reference_in_world(owner->config, XR_REFERENCE_SPACE_TYPE_VIEW);
    const XrResult result = two_call_typed(capacity, countOutput, views, 2, XR_TYPE_VIEW, [&](XrView& v, std::size_t i) {
      Rigid eye;
      eye.translation = {i == 0 ? -kHalfIpd : kHalfIpd, 0.0, 0.0};
      v.pose = to_pose(head * eye);
      const float a = static_cast<float>(std::atan(1.0));  // 45 degrees each way
      v.fov = {-a, a, a, -a};
    });
    if (result == XR_SUCCESS)
      viewState->viewStateFlags = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
                                  XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT;
    return result;
  });
}

}  // namespace roomsense::sim
