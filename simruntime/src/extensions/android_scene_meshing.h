// XR_ANDROID_scene_meshing as an Android XR headset serves it: a meshing tracker (with or without the default
// semantic label set and normals) makes snapshots of the scene mesh in a base space; each snapshot lists the
// room's chunks as submeshes (uuid stable across snapshots, pose in the base space) whose vertices, indices,
// normals and per-vertex labels an application reads with the two-call idiom.
#pragma once
#include "served_extension.h"

namespace roomsense::sim {

const ServedExtension& android_scene_meshing_extension();

}  // namespace roomsense::sim
