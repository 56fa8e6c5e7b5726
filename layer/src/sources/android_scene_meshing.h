// XR_ANDROID_scene_meshing (Android XR headsets): a meshing tracker (with the default semantic label set where
// the runtime offers it), one snapshot of the scene mesh in the base space, every submesh read and moved into
// the base space with its pose, and per-triangle labels from the runtime's per-vertex labels; the submeshes an
// application reads itself are captured as it reads them.
#pragma once
#include "mesh_source.h"

namespace roomsense::layer {

const SourceInfo& android_scene_meshing_source();

}  // namespace roomsense::layer
