// XR_EXT_spatial_entity with XR_EXT_spatial_plane_tracking (OpenXR 1.1 runtimes, Android XR): the planes of a
// discovery snapshot in the base space, as triangles from their 2D meshes (else polygons, else bounds), with the
// runtime's plane labels; the planes an application reads itself are captured. The least preferred source:
// planes are coarser than any scene mesh.
#pragma once
#include "mesh_source.h"

namespace roomsense::layer {

const SourceInfo& ext_spatial_plane_tracking_source();

}  // namespace roomsense::layer
