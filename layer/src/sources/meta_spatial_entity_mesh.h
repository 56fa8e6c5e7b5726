// XR_META_spatial_entity_mesh (Meta Quest 3 and later, with XR_FB_spatial_entity, XR_FB_spatial_entity_query and
// XR_FB_scene): the room's global mesh, a scene space whose triangle-mesh component holds the whole room in the
// space's own frame. The active query finds the spaces with that component, enables it where needed, locates
// each space in the base space and reads its mesh; a mesh an application reads itself is captured as it reads it.
#pragma once
#include "mesh_source.h"

namespace roomsense::layer {

const SourceInfo& meta_spatial_entity_mesh_source();

}  // namespace roomsense::layer
