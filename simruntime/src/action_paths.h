// Path lookups the action system shares: an XrPath's string, and the checks on subaction paths.
#pragma once
#include "interaction_profiles.h"
#include "runtime.h"

#include <algorithm>
#include <string>
#include <vector>

namespace roomsense::sim {

// The string of an interned path, or null for XR_NULL_PATH and values xrStringToPath never returned.
inline const std::string* path_string(const InstanceState& instance, XrPath path) {
  return path == XR_NULL_PATH || path > instance.paths.size() ? nullptr : &instance.paths[path - 1];
}

// A subaction path given to xrCreateAction or xrSyncActions: a path that exists, and a top-level user path.
inline XrResult check_subaction_path(const InstanceState& instance, XrPath path) {
  const std::string* text = path_string(instance, path);
  if (text == nullptr) return XR_ERROR_PATH_INVALID;
  return is_top_level_user_path(*text) ? XR_SUCCESS : XR_ERROR_PATH_UNSUPPORTED;
}

// The subaction path of a query on `action` (state, haptics, action space): XR_NULL_PATH, or one the action
// was created with.
inline XrResult check_query_subaction_path(const InstanceState& instance, const std::vector<XrPath>& action_paths, XrPath path) {
  if (path == XR_NULL_PATH) return XR_SUCCESS;
  if (path_string(instance, path) == nullptr) return XR_ERROR_PATH_INVALID;
  return std::find(action_paths.begin(), action_paths.end(), path) == action_paths.end() ? XR_ERROR_PATH_UNSUPPORTED : XR_SUCCESS;
}

}  // namespace roomsense::sim
