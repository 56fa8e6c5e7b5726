// XR_ML_world_mesh_detection (Magic Leap 2): a world mesh detector reports the mesh blocks around the base
// space through a future (XR_EXT_future), a runtime-allocated buffer receives every block's vertices and uint16
// indices through a second future, and each block is moved into the base space with its pose; the blocks an
// application requests itself are captured as it receives them.
#pragma once
#include "mesh_source.h"

namespace roomsense::layer {

const SourceInfo& ml_world_mesh_detection_source();

}  // namespace roomsense::layer
