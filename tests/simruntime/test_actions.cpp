// The action system of a headset with no controllers: everything an app creates is validated as the spec
// says, attachment rules hold, and every action stays inactive.
#include "input_harness.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

using namespace simtest;

void begin_session(App& app) {
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  ASSERT_EQ(xrBeginSession(app.session, &begin), XR_SUCCESS);  // FOCUSED at once: there is no compositor to wait for
}

TEST(SimActions, NamesAreValidated) {
  App app;
  XrActionSet set = XR_NULL_HANDLE, other = XR_NULL_HANDLE;
  EXPECT_EQ(create_action_set(app.instance, "", "Empty", &other), XR_ERROR_NAME_INVALID);
  EXPECT_EQ(create_action_set(app.instance, "empty", "", &other), XR_ERROR_LOCALIZED_NAME_INVALID);
  EXPECT_EQ(create_action_set(app.instance, "Not A Path", "Spaces", &other), XR_ERROR_PATH_FORMAT_INVALID);
  ASSERT_EQ(create_action_set(app.instance, "menu", "Menu", &set), XR_SUCCESS);
  EXPECT_EQ(create_action_set(app.instance, "menu", "Menu 2", &other), XR_ERROR_NAME_DUPLICATED);
  EXPECT_EQ(create_action_set(app.instance, "menu2", "Menu", &other), XR_ERROR_LOCALIZED_NAME_DUPLICATED);

  XrAction action = XR_NULL_HANDLE, second = XR_NULL_HANDLE;
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "", "Empty", &second), XR_ERROR_NAME_INVALID);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "ok", "", &second), XR_ERROR_LOCALIZED_NAME_INVALID);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "UPPER", "Upper", &second), XR_ERROR_PATH_FORMAT_INVALID);
  EXPECT_EQ(create_action(set, static_cast<XrActionType>(7), "odd", "Odd", &second), XR_ERROR_VALIDATION_FAILURE);
  ASSERT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "confirm", "Confirm", &action), XR_SUCCESS);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_FLOAT_INPUT, "confirm", "Confirm 2", &second), XR_ERROR_NAME_DUPLICATED);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_FLOAT_INPUT, "confirm2", "Confirm", &second), XR_ERROR_LOCALIZED_NAME_DUPLICATED);
  // A name is free again once its owner is destroyed.
  ASSERT_EQ(xrDestroyAction(action), XR_SUCCESS);
  EXPECT_EQ(xrDestroyAction(action), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_FLOAT_INPUT, "confirm", "Confirm", &action), XR_SUCCESS);

  // Subaction paths: top-level user paths only, each once.
  const XrPath head = path(app.instance, "/user/head");
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_POSE_INPUT, "p1", "P1", &second, {head, head}), XR_ERROR_PATH_UNSUPPORTED);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_POSE_INPUT, "p1", "P1", &second, {path(app.instance, "/user/hand")}),
            XR_ERROR_PATH_UNSUPPORTED);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_POSE_INPUT, "p1", "P1", &second, {XrPath{0x7777}}), XR_ERROR_PATH_INVALID);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_POSE_INPUT, "p1", "P1", &second, {head}), XR_SUCCESS);

  // Destroying a set destroys its actions.
  ASSERT_EQ(xrDestroyActionSet(set), XR_SUCCESS);
  EXPECT_EQ(xrDestroyAction(second), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(xrDestroyActionSet(set), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "late", "Late", &second), XR_ERROR_HANDLE_INVALID);
}

TEST(SimActions, SuggestedBindingsAreValidated) {
  App app;
  XrActionSet set = XR_NULL_HANDLE;
  XrAction button = XR_NULL_HANDLE, pose = XR_NULL_HANDLE;
  ASSERT_EQ(create_action_set(app.instance, "set", "Set", &set), XR_SUCCESS);
  ASSERT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "button", "Button", &button), XR_SUCCESS);
  ASSERT_EQ(create_action(set, XR_ACTION_TYPE_POSE_INPUT, "pose", "Pose", &pose), XR_SUCCESS);
  const XrInstance i = app.instance;
  const char* simple = "/interaction_profiles/khr/simple_controller";
  EXPECT_EQ(suggest(i, simple, {{button, path(i, "/user/hand/left/input/select/click")}}), XR_SUCCESS);
  EXPECT_EQ(suggest(i, simple, {{button, path(i, "/user/hand/left/input/select")}}), XR_SUCCESS);  // the runtime picks .../click
  EXPECT_EQ(suggest(i, simple, {{pose, path(i, "/user/hand/right/input/aim/pose")}}), XR_SUCCESS);
  EXPECT_EQ(suggest(i, "/interaction_profiles/oculus/touch_controller", {{button, path(i, "/user/hand/left/input/x/click")}}), XR_SUCCESS);
  EXPECT_EQ(suggest(i, "/interaction_profiles/microsoft/xbox_controller", {{button, path(i, "/user/gamepad/input/a/click")}}), XR_SUCCESS);
  EXPECT_EQ(suggest(i, "/interaction_profiles/valve/index_controller", {{button, path(i, "/user/hand/right/input/b/touch")}}), XR_SUCCESS);

  for (const char* bad : {"/user/hand/right", "/user/hand/right/input", "/user/hand/left/input/trigger/value",
                          "/user/hand/right/input/select/click/invalid", "/user/head/input/select/click",
                          "/user/hand/left/input/grip_surface/pose",       // XR_KHR_maintenance1 / 1.1 only
                          "/user/hand/left/input/palm_ext/pose"})         // XR_EXT_palm_pose only
    EXPECT_EQ(suggest(i, simple, {{button, path(i, bad)}}), XR_ERROR_PATH_UNSUPPORTED) << bad;
  // Touch controllers have X/Y on the left hand only.
  EXPECT_EQ(suggest(i, "/interaction_profiles/oculus/touch_controller", {{button, path(i, "/user/hand/right/input/x/click")}}),
            XR_ERROR_PATH_UNSUPPORTED);
  for (const char* bad : {"/interaction_profiles/khr/another_controller", "/interaction_profiles",
                          "/interaction_profiles/khr/simple_controller/invalid",
                          "/interaction_profiles/htc/vive_cosmos_controller"})  // an extension's profile
    EXPECT_EQ(suggest(i, bad, {{button, path(i, "/user/hand/left/input/select/click")}}), XR_ERROR_PATH_UNSUPPORTED) << bad;

  XrInteractionProfileSuggestedBinding empty{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  empty.interactionProfile = path(i, simple);
  EXPECT_EQ(xrSuggestInteractionProfileBindings(i, &empty), XR_ERROR_VALIDATION_FAILURE);  // no bindings
  const XrActionSuggestedBinding unknown_path{button, XrPath{0x7777}};
  empty.countSuggestedBindings = 1;
  empty.suggestedBindings = &unknown_path;
  EXPECT_EQ(xrSuggestInteractionProfileBindings(i, &empty), XR_ERROR_PATH_INVALID);
  EXPECT_EQ(suggest(i, simple, {{reinterpret_cast<XrAction>(uintptr_t{0x1234}), path(i, "/user/hand/left/input/select/click")}}),
            XR_ERROR_HANDLE_INVALID);

  // Once attached, bindings and the set's actions are fixed.
  ASSERT_EQ(attach(app.session, set), XR_SUCCESS);
  EXPECT_EQ(suggest(i, simple, {{button, path(i, "/user/hand/left/input/select/click")}}), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  XrAction late = XR_NULL_HANDLE;
  EXPECT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "late", "Late", &late), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
}

TEST(SimActions, AttachmentRules) {
  App app;
  XrActionSet set = XR_NULL_HANDLE, second = XR_NULL_HANDLE;
  XrAction button = XR_NULL_HANDLE;
  ASSERT_EQ(create_action_set(app.instance, "set", "Set", &set), XR_SUCCESS);
  ASSERT_EQ(create_action_set(app.instance, "second", "Second", &second), XR_SUCCESS);
  ASSERT_EQ(create_action(set, XR_ACTION_TYPE_BOOLEAN_INPUT, "button", "Button", &button), XR_SUCCESS);

  // Before attachment, every query of the session says so.
  EXPECT_EQ(sync(app.session, set), XR_ERROR_ACTIONSET_NOT_ATTACHED);
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = button;
  XrActionStateBoolean state{XR_TYPE_ACTION_STATE_BOOLEAN};
  EXPECT_EQ(xrGetActionStateBoolean(app.session, &get, &state), XR_ERROR_ACTIONSET_NOT_ATTACHED);
  XrInteractionProfileState profile{XR_TYPE_INTERACTION_PROFILE_STATE};
  const XrPath left = path(app.instance, "/user/hand/left");
  EXPECT_EQ(xrGetCurrentInteractionProfile(app.session, left, &profile), XR_ERROR_ACTIONSET_NOT_ATTACHED);

  XrSessionActionSetsAttachInfo none{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  EXPECT_EQ(xrAttachSessionActionSets(app.session, &none), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(attach(reinterpret_cast<XrSession>(uintptr_t{0x1234}), set), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(attach(app.session, reinterpret_cast<XrActionSet>(uintptr_t{0x1234})), XR_ERROR_HANDLE_INVALID);
  ASSERT_EQ(attach(app.session, set), XR_SUCCESS);
  EXPECT_EQ(attach(app.session, set), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  EXPECT_EQ(attach(app.session, second), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);  // once per session
  EXPECT_EQ(sync(app.session, second), XR_ERROR_ACTIONSET_NOT_ATTACHED);

  EXPECT_EQ(xrGetCurrentInteractionProfile(app.session, left, &profile), XR_SUCCESS);
  EXPECT_EQ(profile.interactionProfile, XrPath{XR_NULL_PATH});  // no controller
  EXPECT_EQ(xrGetCurrentInteractionProfile(app.session, path(app.instance, "/user/hand/left/input"), &profile),
            XR_ERROR_PATH_UNSUPPORTED);

  // A new session of the same instance may attach the same set again.
  ASSERT_EQ(xrDestroySession(app.session), XR_SUCCESS);
  app.start_session();
  EXPECT_EQ(attach(app.session, set), XR_SUCCESS);
}

TEST(SimActions, EveryActionIsInactive) {
  App app;
  const Input input(app);
  XrAction value = XR_NULL_HANDLE, stick = XR_NULL_HANDLE, haptic = XR_NULL_HANDLE;
  XrActionSet other = XR_NULL_HANDLE;
  ASSERT_EQ(create_action_set(app.instance, "other", "Other", &other), XR_SUCCESS);
  ASSERT_EQ(create_action(other, XR_ACTION_TYPE_FLOAT_INPUT, "value", "Value", &value), XR_SUCCESS);
  ASSERT_EQ(create_action(other, XR_ACTION_TYPE_VECTOR2F_INPUT, "stick", "Stick", &stick), XR_SUCCESS);
  ASSERT_EQ(create_action(other, XR_ACTION_TYPE_VIBRATION_OUTPUT, "buzz", "Buzz", &haptic, {input.left}), XR_SUCCESS);

  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = input.select;
  XrActionStateBoolean boolean{XR_TYPE_ACTION_STATE_BOOLEAN};
  EXPECT_EQ(sync(app.session, input.set), XR_SESSION_NOT_FOCUSED);  // not begun yet: a success code
  begin_session(app);
  ASSERT_EQ(sync(app.session, input.set), XR_SUCCESS);
  boolean.currentState = XR_TRUE;
  boolean.isActive = XR_TRUE;
  ASSERT_EQ(xrGetActionStateBoolean(app.session, &get, &boolean), XR_SUCCESS);
  EXPECT_EQ(boolean.isActive, XR_FALSE);
  EXPECT_EQ(boolean.currentState, XR_FALSE);
  EXPECT_EQ(boolean.changedSinceLastSync, XR_FALSE);
  get.subactionPath = input.right;
  EXPECT_EQ(xrGetActionStateBoolean(app.session, &get, &boolean), XR_SUCCESS);
  get.subactionPath = path(app.instance, "/user/gamepad");  // not one of the action's
  EXPECT_EQ(xrGetActionStateBoolean(app.session, &get, &boolean), XR_ERROR_PATH_UNSUPPORTED);
  get.subactionPath = XrPath{0x7777};
  EXPECT_EQ(xrGetActionStateBoolean(app.session, &get, &boolean), XR_ERROR_PATH_INVALID);
  get.subactionPath = XR_NULL_PATH;

  XrActionStatePose pose{XR_TYPE_ACTION_STATE_POSE};
  XrActionStateFloat number{XR_TYPE_ACTION_STATE_FLOAT};
  EXPECT_EQ(xrGetActionStateFloat(app.session, &get, &number), XR_ERROR_ACTION_TYPE_MISMATCH);
  EXPECT_EQ(xrGetActionStatePose(app.session, &get, &pose), XR_ERROR_ACTION_TYPE_MISMATCH);
  get.action = input.grip;
  pose.isActive = XR_TRUE;
  ASSERT_EQ(xrGetActionStatePose(app.session, &get, &pose), XR_SUCCESS);
  EXPECT_EQ(pose.isActive, XR_FALSE);
  get.action = value;  // its set was never attached
  EXPECT_EQ(xrGetActionStateFloat(app.session, &get, &number), XR_ERROR_ACTIONSET_NOT_ATTACHED);
  get.action = reinterpret_cast<XrAction>(uintptr_t{0x1234});
  EXPECT_EQ(xrGetActionStateFloat(app.session, &get, &number), XR_ERROR_HANDLE_INVALID);

  // Haptics are accepted and go nowhere; the wrong action type is still an error.
  XrHapticActionInfo haptic_info{XR_TYPE_HAPTIC_ACTION_INFO};
  haptic_info.action = input.select;
  XrHapticVibration vibration{XR_TYPE_HAPTIC_VIBRATION};
  vibration.amplitude = 1;
  vibration.duration = XR_MIN_HAPTIC_DURATION;
  vibration.frequency = XR_FREQUENCY_UNSPECIFIED;
  const auto* feedback = reinterpret_cast<const XrHapticBaseHeader*>(&vibration);
  EXPECT_EQ(xrApplyHapticFeedback(app.session, &haptic_info, feedback), XR_ERROR_ACTION_TYPE_MISMATCH);
  EXPECT_EQ(xrStopHapticFeedback(app.session, &haptic_info), XR_ERROR_ACTION_TYPE_MISMATCH);
  haptic_info.action = haptic;
  EXPECT_EQ(xrApplyHapticFeedback(app.session, &haptic_info, feedback), XR_ERROR_ACTIONSET_NOT_ATTACHED);

  // Bound sources: none; so no source has a localized name.
  XrBoundSourcesForActionEnumerateInfo sources_info{XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO};
  sources_info.action = input.select;
  uint32_t count = 99;
  EXPECT_EQ(xrEnumerateBoundSourcesForAction(app.session, &sources_info, 0, &count, nullptr), XR_SUCCESS);
  EXPECT_EQ(count, 0u);
  XrInputSourceLocalizedNameGetInfo name_info{XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO};
  name_info.sourcePath = path(app.instance, "/user/hand/left/input/select/click");
  name_info.whichComponents = XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT;
  EXPECT_EQ(xrGetInputSourceLocalizedName(app.session, &name_info, 0, &count, nullptr), XR_ERROR_PATH_UNSUPPORTED);
  name_info.whichComponents = 0;
  EXPECT_EQ(xrGetInputSourceLocalizedName(app.session, &name_info, 0, &count, nullptr), XR_ERROR_VALIDATION_FAILURE);
}

TEST(SimActions, HapticsOnAFocusedSession) {
  App app;
  XrActionSet set = XR_NULL_HANDLE;
  XrAction buzz = XR_NULL_HANDLE;
  ASSERT_EQ(create_action_set(app.instance, "set", "Set", &set), XR_SUCCESS);
  ASSERT_EQ(create_action(set, XR_ACTION_TYPE_VIBRATION_OUTPUT, "buzz", "Buzz", &buzz), XR_SUCCESS);
  ASSERT_EQ(suggest(app.instance, "/interaction_profiles/khr/simple_controller",
                    {{buzz, path(app.instance, "/user/hand/left/output/haptic")}}),
            XR_SUCCESS);
  ASSERT_EQ(attach(app.session, set), XR_SUCCESS);
  XrHapticActionInfo info{XR_TYPE_HAPTIC_ACTION_INFO};
  info.action = buzz;
  XrHapticVibration vibration{XR_TYPE_HAPTIC_VIBRATION};
  vibration.duration = XR_MIN_HAPTIC_DURATION;
  const auto* feedback = reinterpret_cast<const XrHapticBaseHeader*>(&vibration);
  EXPECT_EQ(xrApplyHapticFeedback(app.session, &info, feedback), XR_SESSION_NOT_FOCUSED);
  begin_session(app);
  EXPECT_EQ(xrApplyHapticFeedback(app.session, &info, feedback), XR_SUCCESS);
  EXPECT_EQ(xrStopHapticFeedback(app.session, &info), XR_SUCCESS);
  info.subactionPath = path(app.instance, "/user/hand/left");  // the action has no subaction paths
  EXPECT_EQ(xrStopHapticFeedback(app.session, &info), XR_ERROR_PATH_UNSUPPORTED);
  XrActionStateGetInfo wrong{XR_TYPE_ACTION_STATE_GET_INFO};  // not a haptic feedback structure
  info.subactionPath = XR_NULL_PATH;
  EXPECT_EQ(xrApplyHapticFeedback(app.session, &info, reinterpret_cast<const XrHapticBaseHeader*>(&wrong)),
            XR_ERROR_VALIDATION_FAILURE);
}

TEST(SimActions, ActionSpacesAreNeverLocated) {
  App app;
  const Input input(app);
  XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
  XrSpaceVelocity velocity{XR_TYPE_SPACE_VELOCITY};
  location.next = &velocity;
  velocity.velocityFlags = XR_SPACE_VELOCITY_LINEAR_VALID_BIT;
  ASSERT_EQ(xrLocateSpace(input.grip_space, app.local, app.now(), &location), XR_SUCCESS);
  EXPECT_EQ(location.locationFlags, 0u);
  EXPECT_EQ(velocity.velocityFlags, 0u);
  ASSERT_EQ(xrLocateSpace(app.local, input.grip_space, app.now(), &location), XR_SUCCESS);  // as the base, too
  EXPECT_EQ(location.locationFlags, 0u);

  XrViewLocateInfo views_info{XR_TYPE_VIEW_LOCATE_INFO, nullptr, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, app.now(), input.grip_space};
  XrViewState view_state{XR_TYPE_VIEW_STATE};
  std::vector<XrView> views(2, {XR_TYPE_VIEW});
  uint32_t count = 0;
  ASSERT_EQ(xrLocateViews(app.session, &views_info, &view_state, 2, &count, views.data()), XR_SUCCESS);
  EXPECT_EQ(view_state.viewStateFlags, 0u);

  XrActionSpaceCreateInfo info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  info.action = input.select;  // not a pose
  info.poseInActionSpace.orientation.w = 1;
  XrSpace space = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateActionSpace(app.session, &info, &space), XR_ERROR_ACTION_TYPE_MISMATCH);
  info.action = input.grip;
  info.subactionPath = path(app.instance, "/user/head");
  EXPECT_EQ(xrCreateActionSpace(app.session, &info, &space), XR_ERROR_PATH_UNSUPPORTED);
  info.subactionPath = XR_NULL_PATH;
  info.poseInActionSpace.orientation.w = 0;
  EXPECT_EQ(xrCreateActionSpace(app.session, &info, &space), XR_ERROR_POSE_INVALID);
  info.poseInActionSpace.orientation.w = 1;
  info.type = XR_TYPE_ACTIONS_SYNC_INFO;
  EXPECT_EQ(xrCreateActionSpace(app.session, &info, &space), XR_ERROR_VALIDATION_FAILURE);
  info.type = XR_TYPE_ACTION_SPACE_CREATE_INFO;
  ASSERT_EQ(xrCreateActionSpace(app.session, &info, &space), XR_SUCCESS);
  // The space outlives its action set, and goes with xrDestroySpace.
  ASSERT_EQ(xrDestroyActionSet(input.set), XR_SUCCESS);
  EXPECT_EQ(xrLocateSpace(space, app.local, app.now(), &location), XR_SUCCESS);
  EXPECT_EQ(xrDestroySpace(space), XR_SUCCESS);
  EXPECT_EQ(xrDestroySpace(input.grip_space), XR_SUCCESS);
}

}  // namespace
