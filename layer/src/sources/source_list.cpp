// The mesh sources the layer knows, best first. A new runtime extension is one file pair in this folder and
// one line here.
#include "android_scene_meshing.h"
#include "ext_spatial_plane_tracking.h"
#include "meta_spatial_entity_mesh.h"
#include "ml_world_mesh_detection.h"
#include "msft_scene_understanding.h"

namespace roomsense::layer {

const std::vector<const SourceInfo*>& mesh_sources() {
  static const std::vector<const SourceInfo*> list = {
      &meta_spatial_entity_mesh_source(),
      &msft_scene_understanding_source(),
      &android_scene_meshing_source(),
      &ml_world_mesh_detection_source(),
      &ext_spatial_plane_tracking_source(),
  };
  return list;
}

}  // namespace roomsense::layer
