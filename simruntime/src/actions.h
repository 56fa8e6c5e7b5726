// The action system's objects (action sets, actions, attachments). The simulated headset has no input
// devices: everything an app creates is validated and kept, and every action stays inactive. Lives in
// Runtime, behind its one mutex.
#pragma once
#include <openxr/openxr.h>

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace roomsense::sim {

struct ActionSetState {
  std::uint64_t instance = 0;
  std::string name, localized_name;
  std::set<std::uint64_t> sessions;  // attached to; an action set attached anywhere takes no more actions
};

struct ActionState {
  std::uint64_t action_set = 0;
  std::uint64_t instance = 0;
  XrActionType type = XR_ACTION_TYPE_BOOLEAN_INPUT;
  std::string name, localized_name;
  std::vector<XrPath> subaction_paths;
};

struct ActionSystem {
  std::unordered_map<std::uint64_t, std::unique_ptr<ActionSetState>> action_sets;
  std::unordered_map<std::uint64_t, std::unique_ptr<ActionState>> actions;
  std::set<std::uint64_t> attached_sessions;  // sessions that called xrAttachSessionActionSets
  std::set<std::uint64_t> frozen_instances;   // instances with an attachment: no more suggested bindings

  void destroy_action_set(std::uint64_t id);
  // A session or instance going away (called by the runtime's destruction cascade, under its lock).
  void forget_session(std::uint64_t session);
  void forget_instance(std::uint64_t instance);
  // Whether the action's set is attached to the session.
  bool attached(const ActionState& action, std::uint64_t session) const;
};

}  // namespace roomsense::sim
