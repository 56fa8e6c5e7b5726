// XR_MSFT_scene_understanding as HoloLens 2 serves it: observers compute scenes of the room (visual and
// collider meshes in spatial chunks with their own poses, and one plane per labelled object).
#pragma once
#include "served_extension.h"

namespace roomsense::sim {

const ServedExtension& msft_scene_understanding_extension();

}  // namespace roomsense::sim
