// The interaction profiles of OpenXR 1.0 core (spec section 6.4), for validating suggested bindings. The
// runtime enables none of the extensions that add profiles or input paths (XR_EXT_dpad_binding,
// XR_EXT_palm_pose, XR_KHR_maintenance1, vendor controllers...), so their paths are unsupported here.
#pragma once
#include <string_view>

namespace roomsense::sim {

struct InteractionProfile;

// The profile named by `path`, or null when it is not a 1.0 core profile.
const InteractionProfile* find_interaction_profile(std::string_view path);

// Whether `binding` is a path the profile binds: one of its input or output paths, or an identifier's
// path whose components the runtime picks (".../input/select" for ".../input/select/click").
bool profile_binds(const InteractionProfile& profile, std::string_view binding);

// The top-level user paths of the spec (section 6.3.1): subaction paths must be one of them.
bool is_top_level_user_path(std::string_view path);

}  // namespace roomsense::sim
