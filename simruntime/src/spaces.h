// Where spaces are in the world. World = LOCAL = STAGE (the room file's frame); VIEW is the fixed head pose.
#pragma once
#include "pose_math.h"
#include "runtime.h"

namespace roomsense::sim {

bool is_reference_space_type(XrReferenceSpaceType type);  // a value the spec defines
bool is_supported_reference_space(XrReferenceSpaceType type);
Rigid reference_in_world(const Config& config, XrReferenceSpaceType type);
// Looks the space's session and instance up; false on a broken chain and for action spaces (never located).
// Call under the lock.
bool space_in_world(const SpaceState& space, Rigid& out);

}  // namespace roomsense::sim
