// XR_ML_world_mesh_detection as a Magic Leap 2 serves it: a detector reports the room's mesh blocks (the room's
// chunks, split further where one would pass the 65535 vertices a uint16 index can reach) through a future,
// then fills a runtime-allocated buffer with the requested blocks' vertices (in each block's space) and uint16
// indices through a second future (XR_EXT_future).
#pragma once
#include "served_extension.h"

namespace roomsense::sim {

const ServedExtension& ml_world_mesh_detection_extension();

}  // namespace roomsense::sim
