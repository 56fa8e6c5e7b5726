// Action sets, actions, suggested bindings and attachment (spec chapter 11), with the spec's validation of
// names, paths and the order of calls. No device is ever bound, so bindings are checked and then forgotten.
#include "actions.h"

#include "action_paths.h"
#include "functions.h"
#include "interaction_profiles.h"
#include "runtime.h"
#include "validate.h"

#include <algorithm>
#include <cstring>
#include <string_view>

namespace roomsense::sim {
namespace {

// A name that becomes a path component: lowercase ASCII letters, digits, '-', '_' and '.'.
bool is_path_component(std::string_view name) {
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
  });
}

// The checks xrCreateActionSet and xrCreateAction share, on fixed-size name fields that hold a terminator.
XrResult check_names(const char* name, const char* localized_name) {
  if (name[0] == '\0') return XR_ERROR_NAME_INVALID;
  if (localized_name[0] == '\0') return XR_ERROR_LOCALIZED_NAME_INVALID;
  return is_path_component(name) ? XR_SUCCESS : XR_ERROR_PATH_FORMAT_INVALID;
}

bool is_action_type(XrActionType type) {
  return type == XR_ACTION_TYPE_BOOLEAN_INPUT || type == XR_ACTION_TYPE_FLOAT_INPUT || type == XR_ACTION_TYPE_VECTOR2F_INPUT ||
         type == XR_ACTION_TYPE_POSE_INPUT || type == XR_ACTION_TYPE_VIBRATION_OUTPUT;
}

}  // namespace

void ActionSystem::destroy_action_set(std::uint64_t id) {
  std::erase_if(actions, [id](const auto& entry) { return entry.second->action_set == id; });
  action_sets.erase(id);
}

void ActionSystem::forget_session(std::uint64_t session) {
  attached_sessions.erase(session);
  for (auto& [id, set] : action_sets) set->sessions.erase(session);
}

void ActionSystem::forget_instance(std::uint64_t instance) {
  std::vector<std::uint64_t> owned;
  for (const auto& [id, set] : action_sets)
    if (set->instance == instance) owned.push_back(id);
  for (std::uint64_t id : owned) destroy_action_set(id);
  frozen_instances.erase(instance);
}

bool ActionSystem::attached(const ActionState& action, std::uint64_t session) const {
  const auto it = action_sets.find(action.action_set);
  return it != action_sets.end() && it->second->sessions.count(session) != 0;
}

XrResult XRAPI_CALL xrCreateActionSet(XrInstance instance, const XrActionSetCreateInfo* createInfo, XrActionSet* actionSet) {
  return guarded("xrCreateActionSet", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_ACTION_SET_CREATE_INFO) || actionSet == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (!terminated(createInfo->actionSetName, sizeof createInfo->actionSetName) ||
        !terminated(createInfo->localizedActionSetName, sizeof createInfo->localizedActionSetName))
      return XR_ERROR_VALIDATION_FAILURE;
    if (XrResult r = check_names(createInfo->actionSetName, createInfo->localizedActionSetName); r != XR_SUCCESS) return r;
    ActionSystem& input = runtime().input;
    const std::uint64_t owner = id_of(instance);
    for (const auto& [id, set] : input.action_sets) {
      if (set->instance != owner) continue;
      if (set->name == createInfo->actionSetName) return XR_ERROR_NAME_DUPLICATED;
      if (set->localized_name == createInfo->localizedActionSetName) return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
    }
    auto state = std::make_unique<ActionSetState>();
    state->instance = owner;
    state->name = createInfo->actionSetName;
    state->localized_name = createInfo->localizedActionSetName;
    const std::uint64_t id = runtime().new_id();
    input.action_sets.emplace(id, std::move(state));
    *actionSet = handle_of<XrActionSet>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroyActionSet(XrActionSet actionSet) {
  return guarded("xrDestroyActionSet", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    ActionSystem& input = runtime().input;
    if (input.action_sets.count(id_of(actionSet)) == 0) return XR_ERROR_HANDLE_INVALID;
    input.destroy_action_set(id_of(actionSet));  // its actions go with it; action spaces stay valid
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCreateAction(XrActionSet actionSet, const XrActionCreateInfo* createInfo, XrAction* action) {
  return guarded("xrCreateAction", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    ActionSystem& input = runtime().input;
    const ActionSetState* set = Runtime::find(input.action_sets, id_of(actionSet));
    if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_ACTION_CREATE_INFO) || action == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (!terminated(createInfo->actionName, sizeof createInfo->actionName) ||
        !terminated(createInfo->localizedActionName, sizeof createInfo->localizedActionName))
      return XR_ERROR_VALIDATION_FAILURE;
    if (!is_action_type(createInfo->actionType)) return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->countSubactionPaths > 0 && createInfo->subactionPaths == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (!set->sessions.empty()) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    if (XrResult r = check_names(createInfo->actionName, createInfo->localizedActionName); r != XR_SUCCESS) return r;
    const InstanceState& owner = *runtime().instance(handle_of<XrInstance>(set->instance));
    std::vector<XrPath> subaction_paths;
    for (uint32_t i = 0; i < createInfo->countSubactionPaths; ++i) {
      const XrPath path = createInfo->subactionPaths[i];
      if (XrResult r = check_subaction_path(owner, path); r != XR_SUCCESS) return r;
      if (std::find(subaction_paths.begin(), subaction_paths.end(), path) != subaction_paths.end()) return XR_ERROR_PATH_UNSUPPORTED;
      subaction_paths.push_back(path);
    }
    for (const auto& [id, other] : input.actions) {
      if (other->action_set != id_of(actionSet)) continue;
      if (other->name == createInfo->actionName) return XR_ERROR_NAME_DUPLICATED;
      if (other->localized_name == createInfo->localizedActionName) return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
    }
    auto state = std::make_unique<ActionState>();
    state->action_set = id_of(actionSet);
    state->instance = set->instance;
    state->type = createInfo->actionType;
    state->name = createInfo->actionName;
    state->localized_name = createInfo->localizedActionName;
    state->subaction_paths = std::move(subaction_paths);
    const std::uint64_t id = runtime().new_id();
    input.actions.emplace(id, std::move(state));
    *action = handle_of<XrAction>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroyAction(XrAction action) {
  return guarded("xrDestroyAction", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    return runtime().input.actions.erase(id_of(action)) == 1 ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
  });
}

XrResult XRAPI_CALL xrSuggestInteractionProfileBindings(XrInstance instance, const XrInteractionProfileSuggestedBinding* suggestedBindings) {
  return guarded("xrSuggestInteractionProfileBindings", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const InstanceState* owner = runtime().instance(instance);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(suggestedBindings, XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING)) return XR_ERROR_VALIDATION_FAILURE;
    if (suggestedBindings->countSuggestedBindings == 0 || suggestedBindings->suggestedBindings == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    const ActionSystem& input = runtime().input;
    for (uint32_t i = 0; i < suggestedBindings->countSuggestedBindings; ++i) {
      const ActionState* action = Runtime::find(input.actions, id_of(suggestedBindings->suggestedBindings[i].action));
      if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (action->instance != id_of(instance)) return XR_ERROR_VALIDATION_FAILURE;
    }
    if (input.frozen_instances.count(id_of(instance)) != 0) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    const std::string* profile_path = path_string(*owner, suggestedBindings->interactionProfile);
    if (profile_path == nullptr) return XR_ERROR_PATH_INVALID;
    const InteractionProfile* profile = find_interaction_profile(*profile_path);
    if (profile == nullptr) return XR_ERROR_PATH_UNSUPPORTED;
    for (uint32_t i = 0; i < suggestedBindings->countSuggestedBindings; ++i) {
      const std::string* binding = path_string(*owner, suggestedBindings->suggestedBindings[i].binding);
      if (binding == nullptr) return XR_ERROR_PATH_INVALID;
      if (!profile_binds(*profile, *binding)) return XR_ERROR_PATH_UNSUPPORTED;
    }
    // Valid, and replaces the previous suggestion for the profile; with no device, nothing is ever bound.
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrAttachSessionActionSets(XrSession session, const XrSessionActionSetsAttachInfo* attachInfo) {
  return guarded("xrAttachSessionActionSets", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SessionState* state = runtime().session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(attachInfo, XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    if (attachInfo->countActionSets == 0 || attachInfo->actionSets == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    ActionSystem& input = runtime().input;
    std::vector<ActionSetState*> sets;
    for (uint32_t i = 0; i < attachInfo->countActionSets; ++i) {
      ActionSetState* set = Runtime::find(input.action_sets, id_of(attachInfo->actionSets[i]));
      if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (set->instance != state->instance) return XR_ERROR_VALIDATION_FAILURE;
      sets.push_back(set);
    }
    if (input.attached_sessions.count(id_of(session)) != 0) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    for (ActionSetState* set : sets) set->sessions.insert(id_of(session));
    input.attached_sessions.insert(id_of(session));
    input.frozen_instances.insert(state->instance);
    // The current interaction profile stays XR_NULL_PATH (no device): no XrEventDataInteractionProfileChanged.
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim
