// XR_MSFT_scene_understanding (HoloLens 2, Windows Mixed Reality, Snapdragon Spaces): visual meshes (collider
// meshes where a runtime has no visual ones) of a new scene around the base space, each component located
// in the base space; the application's own scenes are watched as it reads their mesh buffers.
#pragma once
#include "mesh_source.h"

namespace roomsense::layer {

const SourceInfo& msft_scene_understanding_source();

}  // namespace roomsense::layer
