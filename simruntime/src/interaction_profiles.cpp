// The OpenXR 1.0 core interaction profiles and their input/output paths, as the registry (xr.xml) lists
// them for XR_VERSION_1_0 with no extension enabled.
#include "interaction_profiles.h"

#include <algorithm>
#include <string>
#include <vector>

namespace roomsense::sim {

// Component paths (relative to each user path of the group) that a group of user paths has.
struct UserPathGroup {
  std::vector<std::string_view> user_paths;
  std::vector<std::string_view> components;
};

struct InteractionProfile {
  std::string_view path;
  std::vector<UserPathGroup> groups;
};

namespace {

const std::vector<InteractionProfile>& profiles() {
  static const std::vector<InteractionProfile> table{
      {"/interaction_profiles/khr/simple_controller",
       {
           {{"/user/hand/right", "/user/hand/left"},
            {"input/select/click", "input/menu/click", "input/grip/pose", "input/aim/pose", "output/haptic"}},
       }},
      {"/interaction_profiles/google/daydream_controller",
       {
           {{"/user/hand/right", "/user/hand/left"},
            {"input/select/click", "input/trackpad", "input/trackpad/x", "input/trackpad/y",
             "input/trackpad/click", "input/trackpad/touch", "input/grip/pose", "input/aim/pose"}},
       }},
      {"/interaction_profiles/htc/vive_controller",
       {
           {{"/user/hand/right", "/user/hand/left"},
            {"input/system/click", "input/squeeze/click", "input/menu/click", "input/trigger/click",
             "input/trigger/value", "input/trackpad", "input/trackpad/x", "input/trackpad/y",
             "input/trackpad/click", "input/trackpad/touch", "input/grip/pose", "input/aim/pose",
             "output/haptic"}},
       }},
      {"/interaction_profiles/htc/vive_pro",
       {
           {{"/user/head"},
            {"input/system/click", "input/volume_up/click", "input/volume_down/click", "input/mute_mic/click"}},
       }},
      {"/interaction_profiles/microsoft/motion_controller",
       {
           {{"/user/hand/right", "/user/hand/left"},
            {"input/menu/click", "input/squeeze/click", "input/trigger/value", "input/thumbstick",
             "input/thumbstick/x", "input/thumbstick/y", "input/thumbstick/click", "input/trackpad",
             "input/trackpad/x", "input/trackpad/y", "input/trackpad/click", "input/trackpad/touch",
             "input/grip/pose", "input/aim/pose", "output/haptic"}},
       }},
      {"/interaction_profiles/microsoft/xbox_controller",
       {
           {{"/user/gamepad"},
            {"input/menu/click", "input/view/click", "input/a/click", "input/b/click", "input/x/click",
             "input/y/click", "input/dpad_down/click", "input/dpad_right/click", "input/dpad_up/click",
             "input/dpad_left/click", "input/shoulder_left/click", "input/shoulder_right/click",
             "input/thumbstick_left/click", "input/thumbstick_right/click", "input/trigger_left/value",
             "input/trigger_right/value", "input/thumbstick_left", "input/thumbstick_left/x",
             "input/thumbstick_left/y", "input/thumbstick_right", "input/thumbstick_right/x",
             "input/thumbstick_right/y", "output/haptic_left", "output/haptic_right",
             "output/haptic_left_trigger", "output/haptic_right_trigger"}},
       }},
      {"/interaction_profiles/oculus/go_controller",
       {
           {{"/user/hand/right", "/user/hand/left"},
            {"input/system/click", "input/trigger/click", "input/back/click", "input/trackpad",
             "input/trackpad/x", "input/trackpad/y", "input/trackpad/click", "input/trackpad/touch",
             "input/grip/pose", "input/aim/pose"}},
       }},
      {"/interaction_profiles/oculus/touch_controller",
       {
           {{"/user/hand/right", "/user/hand/left"},
            {"input/squeeze/value", "input/trigger/value", "input/trigger/touch", "input/thumbstick",
             "input/thumbstick/x", "input/thumbstick/y", "input/thumbstick/click", "input/thumbstick/touch",
             "input/thumbrest/touch", "input/grip/pose", "input/aim/pose", "output/haptic"}},
           {{"/user/hand/right"},
            {"input/a/click", "input/a/touch", "input/b/click", "input/b/touch", "input/system/click"}},
           {{"/user/hand/left"},
            {"input/x/click", "input/x/touch", "input/y/click", "input/y/touch", "input/menu/click"}},
       }},
      {"/interaction_profiles/valve/index_controller",
       {
           {{"/user/hand/right", "/user/hand/left"},
            {"input/system/click", "input/system/touch", "input/a/click", "input/a/touch", "input/b/click",
             "input/b/touch", "input/squeeze/value", "input/squeeze/force", "input/trigger/click",
             "input/trigger/value", "input/trigger/touch", "input/thumbstick", "input/thumbstick/x",
             "input/thumbstick/y", "input/thumbstick/click", "input/thumbstick/touch", "input/trackpad",
             "input/trackpad/x", "input/trackpad/y", "input/trackpad/force", "input/trackpad/touch",
             "input/grip/pose", "input/aim/pose", "output/haptic"}},
       }},
  };
  return table;
}

}  // namespace

const InteractionProfile* find_interaction_profile(std::string_view path) {
  const auto& all = profiles();
  const auto it = std::find_if(all.begin(), all.end(), [&](const InteractionProfile& p) { return p.path == path; });
  return it == all.end() ? nullptr : &*it;
}

bool profile_binds(const InteractionProfile& profile, std::string_view binding) {
  for (const UserPathGroup& group : profile.groups)
    for (std::string_view user : group.user_paths) {
      if (binding.size() <= user.size() + 1 || !binding.starts_with(user) || binding[user.size()] != '/') continue;
      const std::string_view rest = binding.substr(user.size() + 1);
      for (std::string_view component : group.components) {
        if (component == rest) return true;
        // ".../input/<identifier>" names the identifier, whose component the runtime chooses.
        const bool identifier = rest.starts_with("input/") && rest.find('/', 6) == std::string_view::npos;
        if (identifier && component.size() > rest.size() && component.starts_with(rest) && component[rest.size()] == '/')
          return true;
      }
    }
  return false;
}

bool is_top_level_user_path(std::string_view path) {
  return path == "/user/hand/left" || path == "/user/hand/right" || path == "/user/head" || path == "/user/gamepad" ||
         path == "/user/treadmill";
}

}  // namespace roomsense::sim
