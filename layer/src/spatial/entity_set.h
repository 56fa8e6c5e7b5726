// What the layer serves through XR_EXT_spatial_entity, built from one analysis: a plane per surface
// (roomsense/surfaces.h) for XR_EXT_spatial_plane_tracking, an entity per placement area and one room entity
// with the bounds mesh for XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX. Entity ids are stable: an entity that is
// still there after a new analysis keeps the id it had, so content anchored to it does not jump.
#pragma once
#include "../results.h"
#include "spatial_declarations.h"

#include "roomsense/xr/rigid.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace roomsense::layer {

enum class EntityKind : std::uint8_t { Plane, Area, Room };

struct ServedEntity {
  XrSpatialEntityIdEXT id = XR_NULL_SPATIAL_ENTITY_ID_EXT;
  EntityKind kind = EntityKind::Plane;
  xr::Rigid pose;  // in the analysis's base space; planes and areas: +Z the normal into free space
  XrExtent2Df extents{0, 0};
  // Planes
  XrSpatialPlaneAlignmentEXT alignment = XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT;
  XrSpatialPlaneSemanticLabelEXT label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT;
  std::vector<XrVector2f> polygon;          // CCW seen from +Z, in the pose's XY
  std::vector<XrVector2f> mesh_vertices;    // MESH_2D: the polygon triangulated
  std::vector<std::uint16_t> mesh_indices;  // UINT16, as the spec serves MESH_2D
  // Planes and areas: where they lie
  XrSpatialRoomLocationDataEXTX location{0, XR_ROOM_INDEX_NONE_EXTX};
  // Areas
  XrSpatialPlacementAreaDataEXTX area{};
  // The room: the bounds mesh, in the pose's frame (the identity: the base space itself)
  std::vector<XrVector3f> room_vertices;
  std::vector<std::uint32_t> room_indices;

  bool has(XrSpatialComponentTypeEXT component) const;
  XrSpatialCapabilityEXT capability() const;
};

struct EntitySet {
  std::vector<ServedEntity> entities;  // by id
  XrSpatialEntityIdEXT next_id = 1;    // the next id never handed out

  const ServedEntity* find(XrSpatialEntityIdEXT id) const;
};

// The entities of `result`, with the ids of `previous` kept for the entities that match one of it (same kind
// and label, normal within 15°, on the same plane within 0.15 m, centre inside the old extents grown by 0.3 m);
// new ids continue after previous.next_id. The room entity keeps its id.
EntitySet build_entity_set(const RoomResult& result, const EntitySet& previous);

// True when both hold the same entities with the same ids and geometry to within a millimetre: a new analysis
// that changes nothing recommends no new discovery.
bool same_entities(const EntitySet& a, const EntitySet& b);

}  // namespace roomsense::layer
