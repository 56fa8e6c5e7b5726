// xrPollEvent: session state changes, queued per instance in the order they happened, then the scene
// extensions' events.
#include "functions.h"
#include "runtime.h"
#include "validate.h"

#include <cstring>

namespace roomsense::sim {

XrResult XRAPI_CALL xrPollEvent(XrInstance instance, XrEventDataBuffer* eventData) {
  return guarded("xrPollEvent", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(eventData, XR_TYPE_EVENT_DATA_BUFFER)) return XR_ERROR_VALIDATION_FAILURE;
    if (state->events.empty()) {
      if (state->extension_events.empty()) return XR_EVENT_UNAVAILABLE;
      std::memcpy(static_cast<void*>(eventData), &state->extension_events.front(), sizeof(XrEventDataBuffer));
      state->extension_events.pop_front();
      return XR_SUCCESS;
    }
    const SessionEvent event = state->events.front();
    state->events.pop_front();
    XrEventDataSessionStateChanged changed{};
    changed.type = XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED;
    changed.session = handle_of<XrSession>(event.session);
    changed.state = event.state;
    changed.time = event.time;
    static_assert(sizeof changed <= sizeof(XrEventDataBuffer));
    std::memcpy(static_cast<void*>(eventData), &changed, sizeof changed);
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim
