// The action setup every OpenXR app makes (an action set, a button and a hand pose, bindings for the Khronos
// simple controller, attachment, a grip space), for the action tests and the smoke app.
#pragma once
#include "xr_harness.h"

#include <cstring>

namespace simtest {

inline XrPath path(XrInstance instance, const char* text) {
  XrPath p = XR_NULL_PATH;
  check(xrStringToPath(instance, text, &p), text);
  return p;
}

inline XrResult create_action_set(XrInstance instance, const char* name, const char* localized, XrActionSet* set) {
  XrActionSetCreateInfo info{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strncpy(info.actionSetName, name, XR_MAX_ACTION_SET_NAME_SIZE - 1);
  std::strncpy(info.localizedActionSetName, localized, XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE - 1);
  return xrCreateActionSet(instance, &info, set);
}

inline XrResult create_action(XrActionSet set, XrActionType type, const char* name, const char* localized, XrAction* action,
                              const std::vector<XrPath>& subaction_paths = {}) {
  XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
  info.actionType = type;
  std::strncpy(info.actionName, name, XR_MAX_ACTION_NAME_SIZE - 1);
  std::strncpy(info.localizedActionName, localized, XR_MAX_LOCALIZED_ACTION_NAME_SIZE - 1);
  info.countSubactionPaths = static_cast<uint32_t>(subaction_paths.size());
  info.subactionPaths = subaction_paths.data();
  return xrCreateAction(set, &info, action);
}

inline XrResult suggest(XrInstance instance, const char* profile, const std::vector<XrActionSuggestedBinding>& bindings) {
  XrInteractionProfileSuggestedBinding suggested{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  suggested.interactionProfile = path(instance, profile);
  suggested.countSuggestedBindings = static_cast<uint32_t>(bindings.size());
  suggested.suggestedBindings = bindings.data();
  return xrSuggestInteractionProfileBindings(instance, &suggested);
}

inline XrResult attach(XrSession session, XrActionSet set) {
  XrSessionActionSetsAttachInfo info{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  info.countActionSets = 1;
  info.actionSets = &set;
  return xrAttachSessionActionSets(session, &info);
}

inline XrResult sync(XrSession session, XrActionSet set) {
  const XrActiveActionSet active{set, XR_NULL_PATH};
  XrActionsSyncInfo info{XR_TYPE_ACTIONS_SYNC_INFO};
  info.countActiveActionSets = 1;
  info.activeActionSets = &active;
  return xrSyncActions(session, &info);
}

// Both hands' select button and grip pose, bound to /interaction_profiles/khr/simple_controller and attached.
struct Input {
  XrActionSet set = XR_NULL_HANDLE;
  XrAction select = XR_NULL_HANDLE;
  XrAction grip = XR_NULL_HANDLE;
  XrSpace grip_space = XR_NULL_HANDLE;  // the left hand's
  XrPath left = XR_NULL_PATH, right = XR_NULL_PATH;

  explicit Input(App& app) {
    left = path(app.instance, "/user/hand/left");
    right = path(app.instance, "/user/hand/right");
    SIM_CHECK(create_action_set(app.instance, "gameplay", "Gameplay", &set));
    SIM_CHECK(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "select", "Select", &select, {left, right}));
    SIM_CHECK(create_action(set, XR_ACTION_TYPE_POSE_INPUT, "grip", "Grip", &grip, {left, right}));
    SIM_CHECK(suggest(app.instance, "/interaction_profiles/khr/simple_controller",
                      {{select, path(app.instance, "/user/hand/left/input/select/click")},
                       {select, path(app.instance, "/user/hand/right/input/select/click")},
                       {grip, path(app.instance, "/user/hand/left/input/grip/pose")},
                       {grip, path(app.instance, "/user/hand/right/input/grip/pose")}}));
    SIM_CHECK(attach(app.session, set));
    XrActionSpaceCreateInfo space_info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    space_info.action = grip;
    space_info.subactionPath = left;
    space_info.poseInActionSpace.orientation.w = 1;
    SIM_CHECK(xrCreateActionSpace(app.session, &space_info, &grip_space));
  }
};

}  // namespace simtest
