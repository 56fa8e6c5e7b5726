// The planes XR_EXT_spatial_plane_tracking serves: one per labelled object of a room (Quest captures), or, for
// a plain mesh (OBJ files, the built-in synthetic rooms), the large flat regions of the mesh: triangles grouped
// by normal (horizontal up, horizontal down, vertical by direction) and plane offset, split into connected
// regions on a 10 cm raster, each kept when it covers at least 0.25 m².
#pragma once
#include "../pose_math.h"
#include "../room_source.h"

#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <cstdint>
#include <vector>

namespace roomsense::sim {

struct ServedPlane {
  Rigid pose;                          // world space: centre, +Z the normal into free space, +Y up for walls
  XrExtent2Df extents{};               // width (X) x height (Y)
  XrSpatialPlaneAlignmentEXT alignment = XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT;
  XrSpatialPlaneSemanticLabelEXT label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT;
  std::vector<XrVector2f> polygon;     // outline, counter-clockwise in the plane's XY (seen from +Z)
  std::vector<XrVector2f> vertices;    // MESH_2D, in the plane's XY
  std::vector<std::uint32_t> indices;  // counter-clockwise triangles
};

// Every plane of the room, in a stable order (the entity ids are their positions + 1).
std::vector<ServedPlane> extract_planes(const Room& room);

// The spec's label for a Quest scene label (FLOOR, CEILING, WALL_FACE, TABLE; UNCATEGORIZED otherwise).
XrSpatialPlaneSemanticLabelEXT plane_label_for(const std::string& label);

}  // namespace roomsense::sim
