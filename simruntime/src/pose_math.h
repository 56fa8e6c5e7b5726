// The shared rigid-transform math (roomsense/xr/rigid.h), in the runtime's namespace.
#pragma once
#include "roomsense/xr/rigid.h"

namespace roomsense::sim {

using xr::is_valid_pose;
using xr::Rigid;
using xr::to_pose;
using xr::to_rigid;

}  // namespace roomsense::sim
