// XR_EXT_spatial_entity with XR_EXT_spatial_plane_tracking, as OpenXR 1.1.49 ratified them (Android XR and other
// OpenXR 1.1 runtimes): spatial contexts and discovery snapshots through XR_EXT_future, the room's planes as
// entities with BOUNDED_2D, PLANE_ALIGNMENT, POLYGON_2D, MESH_2D and PLANE_SEMANTIC_LABEL components, polygons
// and meshes in spatial buffers.
#pragma once
#include "served_extension.h"

namespace roomsense::sim {

const ServedExtension& ext_spatial_entity_extension();
const ServedExtension& ext_spatial_plane_tracking_extension();  // no functions: the plane tracking capability

}  // namespace roomsense::sim
