// Headless sessions (XR_MND_headless) and the session state machine:
// create: IDLE, READY; begin: SYNCHRONIZED, VISIBLE, FOCUSED; request exit: VISIBLE, SYNCHRONIZED, STOPPING;
// end: IDLE, then EXITING when the application asked to exit.
#include "functions.h"
#include "log.h"
#include "runtime.h"
#include "validate.h"

namespace roomsense::sim {
namespace {

// Graphics bindings of the 1.0 registry: this runtime has no graphics at all.
bool is_graphics_binding(XrStructureType type) {
  switch (static_cast<int>(type)) {
    case 1000023000: case 1000023001: case 1000023002: case 1000023003:  // OpenGL Win32/Xlib/Xcb/Wayland
    case 1000024001:                                                      // OpenGL ES Android
    case 1000025000:                                                      // Vulkan
    case 1000027000: case 1000028000:                                     // D3D11, D3D12
    case 1000048004:                                                      // EGL (MNDX)
      return true;
    default:
      return false;
  }
}

}  // namespace

XrResult XRAPI_CALL xrCreateSession(XrInstance instance, const XrSessionCreateInfo* createInfo, XrSession* session) {
  return guarded("xrCreateSession", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    InstanceState* owner = runtime().instance(instance);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_SESSION_CREATE_INFO) || session == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->createFlags != 0) return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    for (auto* s = static_cast<const XrBaseInStructure*>(createInfo->next); s != nullptr; s = s->next)
      if (is_graphics_binding(s->type)) {
        log_error("xrCreateSession: this runtime is headless and supports no graphics binding");
        return XR_ERROR_GRAPHICS_DEVICE_INVALID;
      }
    if (!owner->has(XR_MND_HEADLESS_EXTENSION_NAME)) {
      log_error("xrCreateSession: enable XR_MND_headless to create a session without a graphics binding");
      return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    }
    const std::uint64_t id = runtime().new_id();
    auto state = std::make_unique<SessionState>();
    state->instance = id_of(instance);
    SessionState& created = *state;
    runtime().sessions.emplace(id, std::move(state));
    runtime().push_state(created, id, XR_SESSION_STATE_IDLE);
    runtime().push_state(created, id, XR_SESSION_STATE_READY);
    *session = handle_of<XrSession>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySession(XrSession session) {
  return guarded("xrDestroySession", [&]() -> XrResult {
    Runtime::Graveyard graveyard;  // destroyed after the lock is released (joins compute threads)
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    runtime().destroy_session(id_of(session), graveyard);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrBeginSession(XrSession session, const XrSessionBeginInfo* beginInfo) {
  return guarded("xrBeginSession", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    SessionState* state = runtime().session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(beginInfo, XR_TYPE_SESSION_BEGIN_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    const XrViewConfigurationType view = beginInfo->primaryViewConfigurationType;
    if (!is_view_configuration_type(view)) return XR_ERROR_VALIDATION_FAILURE;
    if (view != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (state->running) return XR_ERROR_SESSION_RUNNING;
    if (state->state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
    state->running = true;
    state->frames_waited = 0;
    state->frame_begun = false;
    for (XrSessionState next : {XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_FOCUSED})
      runtime().push_state(*state, id_of(session), next);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrRequestExitSession(XrSession session) {
  return guarded("xrRequestExitSession", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    SessionState* state = runtime().session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!state->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (state->exit_requested) return XR_SUCCESS;
    state->exit_requested = true;
    for (XrSessionState next : {XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_STOPPING})
      runtime().push_state(*state, id_of(session), next);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrEndSession(XrSession session) {
  return guarded("xrEndSession", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    SessionState* state = runtime().session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!state->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (state->state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
    state->running = false;
    runtime().push_state(*state, id_of(session), XR_SESSION_STATE_IDLE);
    if (state->exit_requested) runtime().push_state(*state, id_of(session), XR_SESSION_STATE_EXITING);
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim
