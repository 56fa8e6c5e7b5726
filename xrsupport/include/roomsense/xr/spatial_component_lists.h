// An application's side of xrQuerySpatialComponentDataEXT, for the demo and the tests: one list per component
// type it asks for, sized for the entities the first call announced, chained onto the result of the second.
// (spatial_query.h is the servers' side: the checks they put on such a chain.) Includes our extension's header
// for the placement-area list.
#pragma once
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <openxr/XR_EXTX_room_understanding.h>

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace roomsense::xr {

// What a query returns per entity: ids and states always, the others for the components asked for.
struct SpatialComponentData {
  std::vector<XrSpatialEntityIdEXT> ids;
  std::vector<XrSpatialEntityTrackingStateEXT> states;
  std::vector<XrSpatialBounded2DDataEXT> bounds;
  std::vector<XrSpatialPlaneAlignmentEXT> alignments;
  std::vector<XrSpatialPlaneSemanticLabelEXT> labels;
  std::vector<XrSpatialPolygon2DDataEXT> polygons;
  std::vector<XrSpatialMeshDataEXT> meshes2d;
  std::vector<XrSpatialMeshDataEXT> meshes3d;
  std::vector<XrSpatialPlacementAreaDataEXTX> areas;
  std::vector<XrSpatialRoomLocationDataEXTX> locations;
};

// Sizes `data` for `n` entities and points `result` at it: its id and state arrays, and a chain of one list
// per type of `components`. The result then points into this object, which must outlive the call it is used for.
class SpatialComponentLists {
 public:
  SpatialComponentLists(SpatialComponentData& data, std::uint32_t n,
                        const std::vector<XrSpatialComponentTypeEXT>& components,
                        XrSpatialComponentDataQueryResultEXT& result) {
    const auto want = [&](XrSpatialComponentTypeEXT c) {
      return std::find(components.begin(), components.end(), c) != components.end();
    };
    data.ids.resize(n);
    data.states.resize(n);
    void* chain = nullptr;
    const auto link = [&](XrSpatialComponentTypeEXT c, auto& vector, auto& list) {
      if (!want(c)) return;
      vector.resize(n);
      // Every list struct is {type, next, count, array}, with names of its own for the last two.
      list = std::remove_reference_t<decltype(list)>{list.type, chain, n, vector.data()};
      chain = &list;
    };
    link(XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, data.bounds, bounds_);
    link(XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT, data.alignments, alignments_);
    link(XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT, data.labels, labels_);
    link(XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT, data.polygons, polygons_);
    link(XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT, data.meshes2d, meshes2d_);
    link(XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT, data.meshes3d, meshes3d_);
    link(XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX, data.areas, areas_);
    link(XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX, data.locations, locations_);
    result.next = chain;
    result.entityIdCapacityInput = n;
    result.entityIds = data.ids.data();
    result.entityStateCapacityInput = n;
    result.entityStates = data.states.data();
  }
  SpatialComponentLists(const SpatialComponentLists&) = delete;
  SpatialComponentLists& operator=(const SpatialComponentLists&) = delete;

 private:
  XrSpatialComponentBounded2DListEXT bounds_{XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT};
  XrSpatialComponentPlaneAlignmentListEXT alignments_{XR_TYPE_SPATIAL_COMPONENT_PLANE_ALIGNMENT_LIST_EXT};
  XrSpatialComponentPlaneSemanticLabelListEXT labels_{XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT};
  XrSpatialComponentPolygon2DListEXT polygons_{XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT};
  XrSpatialComponentMesh2DListEXT meshes2d_{XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT};
  XrSpatialComponentMesh3DListEXT meshes3d_{XR_TYPE_SPATIAL_COMPONENT_MESH_3D_LIST_EXT};
  XrSpatialComponentPlacementAreaListEXTX areas_{XR_TYPE_SPATIAL_COMPONENT_PLACEMENT_AREA_LIST_EXTX};
  XrSpatialComponentRoomLocationListEXTX locations_{XR_TYPE_SPATIAL_COMPONENT_ROOM_LOCATION_LIST_EXTX};
};

}  // namespace roomsense::xr
