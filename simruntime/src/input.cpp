// Reading input with no device: xrSyncActions, action states, haptics, the current interaction profile,
// bound sources and their names. Every action is inactive and every state zero; nothing is ever bound.
#include "action_paths.h"
#include "actions.h"
#include "functions.h"
#include "runtime.h"
#include "validate.h"

#include <vector>

namespace roomsense::sim {
namespace {

// What a query on one action of a session resolves to, once its handles, attachment, type and subaction path
// are checked (in that order).
struct ActionQuery {
  const SessionState* session = nullptr;
  const ActionState* action = nullptr;
};

XrResult resolve(XrSession session, XrAction action, XrPath subaction_path, XrActionType type, ActionQuery& out) {
  Runtime& rt = runtime();
  out.session = rt.session(session);
  if (out.session == nullptr) return XR_ERROR_HANDLE_INVALID;
  out.action = Runtime::find(rt.input.actions, id_of(action));
  if (out.action == nullptr) return XR_ERROR_HANDLE_INVALID;
  if (out.action->instance != out.session->instance) return XR_ERROR_VALIDATION_FAILURE;
  if (!rt.input.attached(*out.action, id_of(session))) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
  if (out.action->type != type) return XR_ERROR_ACTION_TYPE_MISMATCH;
  const InstanceState& owner = *Runtime::find(rt.instances, out.session->instance);
  return check_query_subaction_path(owner, out.action->subaction_paths, subaction_path);
}

// The four state queries: check, then report an inactive action (the state structure zeroed past its header).
template <typename State>
XrResult inactive_state(const char* function, XrSession session, const XrActionStateGetInfo* getInfo, State* state,
                        XrStructureType state_type, XrActionType action_type) {
  return guarded(function, [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(getInfo, XR_TYPE_ACTION_STATE_GET_INFO) || !has_type(state, state_type)) return XR_ERROR_VALIDATION_FAILURE;
    ActionQuery query;
    if (XrResult r = resolve(session, getInfo->action, getInfo->subactionPath, action_type, query); r != XR_SUCCESS) return r;
    void* const next = state->next;
    *state = State{};
    state->type = state_type;
    state->next = next;
    return XR_SUCCESS;  // isActive false: no device provides the action
  });
}

bool focused(const SessionState& session) { return session.state == XR_SESSION_STATE_FOCUSED; }

// xrApplyHapticFeedback and xrStopHapticFeedback: checked, then ignored (there is nothing to vibrate).
XrResult haptic(XrSession session, const XrHapticActionInfo* info) {
  ActionQuery query;
  if (XrResult r = resolve(session, info->action, info->subactionPath, XR_ACTION_TYPE_VIBRATION_OUTPUT, query); r != XR_SUCCESS)
    return r;
  return focused(*query.session) ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
}

}  // namespace

XrResult XRAPI_CALL xrSyncActions(XrSession session, const XrActionsSyncInfo* syncInfo) {
  return guarded("xrSyncActions", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Runtime& rt = runtime();
    const SessionState* state = rt.session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(syncInfo, XR_TYPE_ACTIONS_SYNC_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    if (syncInfo->countActiveActionSets > 0 && syncInfo->activeActionSets == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const InstanceState& owner = *Runtime::find(rt.instances, state->instance);
    for (uint32_t i = 0; i < syncInfo->countActiveActionSets; ++i) {
      const XrActiveActionSet& active = syncInfo->activeActionSets[i];
      const ActionSetState* set = Runtime::find(rt.input.action_sets, id_of(active.actionSet));
      if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (set->instance != state->instance) return XR_ERROR_VALIDATION_FAILURE;
      if (active.subactionPath != XR_NULL_PATH)
        if (XrResult r = check_subaction_path(owner, active.subactionPath); r != XR_SUCCESS) return r;
      if (set->sessions.count(id_of(session)) == 0) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    }
    return focused(*state) ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  });
}

XrResult XRAPI_CALL xrGetActionStateBoolean(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateBoolean* state) {
  return inactive_state("xrGetActionStateBoolean", session, getInfo, state, XR_TYPE_ACTION_STATE_BOOLEAN, XR_ACTION_TYPE_BOOLEAN_INPUT);
}

XrResult XRAPI_CALL xrGetActionStateFloat(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateFloat* state) {
  return inactive_state("xrGetActionStateFloat", session, getInfo, state, XR_TYPE_ACTION_STATE_FLOAT, XR_ACTION_TYPE_FLOAT_INPUT);
}

XrResult XRAPI_CALL xrGetActionStateVector2f(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateVector2f* state) {
  return inactive_state("xrGetActionStateVector2f", session, getInfo, state, XR_TYPE_ACTION_STATE_VECTOR2F, XR_ACTION_TYPE_VECTOR2F_INPUT);
}

XrResult XRAPI_CALL xrGetActionStatePose(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStatePose* state) {
  return inactive_state("xrGetActionStatePose", session, getInfo, state, XR_TYPE_ACTION_STATE_POSE, XR_ACTION_TYPE_POSE_INPUT);
}

XrResult XRAPI_CALL xrApplyHapticFeedback(XrSession session, const XrHapticActionInfo* hapticActionInfo,
                                          const XrHapticBaseHeader* hapticFeedback) {
  return guarded("xrApplyHapticFeedback", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(hapticActionInfo, XR_TYPE_HAPTIC_ACTION_INFO) || !has_type(hapticFeedback, XR_TYPE_HAPTIC_VIBRATION))
      return XR_ERROR_VALIDATION_FAILURE;
    return haptic(session, hapticActionInfo);
  });
}

XrResult XRAPI_CALL xrStopHapticFeedback(XrSession session, const XrHapticActionInfo* hapticActionInfo) {
  return guarded("xrStopHapticFeedback", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(hapticActionInfo, XR_TYPE_HAPTIC_ACTION_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    return haptic(session, hapticActionInfo);
  });
}

XrResult XRAPI_CALL xrGetCurrentInteractionProfile(XrSession session, XrPath topLevelUserPath,
                                                   XrInteractionProfileState* interactionProfile) {
  return guarded("xrGetCurrentInteractionProfile", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Runtime& rt = runtime();
    const SessionState* state = rt.session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(interactionProfile, XR_TYPE_INTERACTION_PROFILE_STATE)) return XR_ERROR_VALIDATION_FAILURE;
    if (rt.input.attached_sessions.count(id_of(session)) == 0) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (XrResult r = check_subaction_path(*Runtime::find(rt.instances, state->instance), topLevelUserPath); r != XR_SUCCESS) return r;
    interactionProfile->interactionProfile = XR_NULL_PATH;  // no device, so no profile
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrEnumerateBoundSourcesForAction(XrSession session, const XrBoundSourcesForActionEnumerateInfo* enumerateInfo,
                                                     uint32_t sourceCapacityInput, uint32_t* sourceCountOutput, XrPath* sources) {
  return guarded("xrEnumerateBoundSourcesForAction", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Runtime& rt = runtime();
    const SessionState* state = rt.session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(enumerateInfo, XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    const ActionState* action = Runtime::find(rt.input.actions, id_of(enumerateInfo->action));
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (action->instance != state->instance) return XR_ERROR_VALIDATION_FAILURE;
    if (!rt.input.attached(*action, id_of(session))) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    return two_call(sourceCapacityInput, sourceCountOutput, sources, std::vector<XrPath>{});
  });
}

XrResult XRAPI_CALL xrGetInputSourceLocalizedName(XrSession session, const XrInputSourceLocalizedNameGetInfo* getInfo,
                                                  uint32_t bufferCapacityInput, uint32_t* bufferCountOutput, char* buffer) {
  return guarded("xrGetInputSourceLocalizedName", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Runtime& rt = runtime();
    const SessionState* state = rt.session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(getInfo, XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    if (bufferCountOutput == nullptr || (bufferCapacityInput > 0 && buffer == nullptr)) return XR_ERROR_VALIDATION_FAILURE;
    constexpr XrInputSourceLocalizedNameFlags kAll = XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT |
                                                     XR_INPUT_SOURCE_LOCALIZED_NAME_INTERACTION_PROFILE_BIT |
                                                     XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT;
    if (getInfo->whichComponents == 0 || (getInfo->whichComponents & ~kAll) != 0) return XR_ERROR_VALIDATION_FAILURE;
    if (path_string(*Runtime::find(rt.instances, state->instance), getInfo->sourcePath) == nullptr) return XR_ERROR_PATH_INVALID;
    if (rt.input.attached_sessions.count(id_of(session)) == 0) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    // A source is a path xrEnumerateBoundSourcesForAction returned, and with no device it returns none.
    return XR_ERROR_PATH_UNSUPPORTED;
  });
}

}  // namespace roomsense::sim
