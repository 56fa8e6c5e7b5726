// Quest's scene model: XR_FB_spatial_entity (spaces with components, async request ids),
// XR_FB_spatial_entity_query (finding them), XR_FB_scene (labels, bounds, room layout),
// XR_FB_spatial_entity_container and XR_META_spatial_entity_mesh (the room's global mesh as one space).
// A room is served as one room anchor (layout and container of the others), one GLOBAL_MESH anchor whose
// triangle mesh is the whole room in the anchor's own space (a yaw and an offset from LOCAL), and, for
// Quest captures, one anchor per labelled plane or volume top. Anchors are runtime spaces, located by
// xrLocateSpace like any other.
#pragma once
#include "served_extension.h"

namespace roomsense::sim {

const ServedExtension& fb_spatial_entity_extension();
const ServedExtension& fb_spatial_entity_query_extension();
const ServedExtension& fb_scene_extension();
const ServedExtension& fb_spatial_entity_container_extension();
const ServedExtension& meta_spatial_entity_mesh_extension();

}  // namespace roomsense::sim
