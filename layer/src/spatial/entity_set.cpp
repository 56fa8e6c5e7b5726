#include "entity_set.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace roomsense::layer {
namespace {

constexpr double kMatchCos = 0.9659;     // cos 15°: the same plane seen again
constexpr double kMatchOffset = 0.15;    // m along the normal
constexpr double kMatchMargin = 0.3;     // m around the old extents
constexpr float kSameGeometry = 1e-3f;   // m: below this a new analysis changed nothing

XrSpatialPlaneAlignmentEXT alignment_of(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Ceiling: return XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT;
    case SurfaceKind::Wall: return XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT;
    default: return XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT;
  }
}

// The spec's labels are FLOOR, CEILING, WALL, TABLE; any other furniture top is UNCATEGORIZED.
XrSpatialPlaneSemanticLabelEXT label_of(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Floor: return XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT;
    case SurfaceKind::Ceiling: return XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT;
    case SurfaceKind::Wall: return XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT;
    case SurfaceKind::Table: return XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT;
    case SurfaceKind::Furniture: return XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT;
  }
  return XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT;
}

ServedEntity plane_of(const Surface& s) {
  ServedEntity e;
  e.kind = EntityKind::Plane;
  const glm::quat q = s.orientation();
  e.pose = {glm::dquat(q.w, q.x, q.y, q.z), glm::dvec3(s.center)};
  e.extents = {s.extents.x, s.extents.y};
  e.alignment = alignment_of(s.kind);
  e.label = label_of(s.kind);
  e.location = {s.storey, s.room == kNoRoom ? XR_ROOM_INDEX_NONE_EXTX : std::uint32_t(s.room)};
  e.polygon.reserve(s.polygon.size());
  for (const glm::vec2& p : s.polygon) e.polygon.push_back({p.x, p.y});
  // MESH_2D: the outline's own vertices, triangulated; its UINT16 indices reach 65535 vertices, far beyond an outline.
  if (s.polygon.size() <= 0xFFFF) {
    e.mesh_vertices = e.polygon;
    e.mesh_indices.assign(s.triangles.begin(), s.triangles.end());
  }
  return e;
}

ServedEntity area_of(const XrRoomAreaEXTX& a, const XrRoomAreaLocationEXTX& location) {
  ServedEntity e;
  e.kind = EntityKind::Area;
  e.location = {location.storeyIndex, location.roomIndex};
  e.pose = xr::to_rigid(a.pose);
  e.extents = a.extents;
  e.area = {a.areaType, a.size, a.interaction, a.extents, a.volumeHeight, a.categoryFlags};
  return e;
}

glm::dvec3 normal_of(const ServedEntity& e) { return e.pose.rotation * glm::dvec3(0, 0, 1); }

bool same_class(const ServedEntity& a, const ServedEntity& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == EntityKind::Plane) return a.label == b.label && a.alignment == b.alignment;
  if (a.kind == EntityKind::Area) return a.area.areaType == b.area.areaType && a.area.size == b.area.size;
  return true;
}

// How well `now` continues `before`: a distance (smaller is better), or a negative number for no match.
double match_cost(const ServedEntity& before, const ServedEntity& now) {
  if (!same_class(before, now)) return -1.0;
  if (now.kind == EntityKind::Room) return 0.0;
  const glm::dvec3 n0 = normal_of(before), n1 = normal_of(now);
  if (glm::dot(n0, n1) < kMatchCos) return -1.0;
  const glm::dvec3 d = now.pose.translation - before.pose.translation;
  if (std::fabs(glm::dot(d, n0)) > kMatchOffset) return -1.0;
  // The new centre, in the old plane's frame, inside the old rectangle grown by the margin.
  const glm::dvec3 local = glm::conjugate(before.pose.rotation) * d;
  if (std::fabs(local.x) > before.extents.width / 2 + kMatchMargin || std::fabs(local.y) > before.extents.height / 2 + kMatchMargin)
    return -1.0;
  return glm::length(d);
}

bool near(float a, float b) { return std::fabs(a - b) <= kSameGeometry; }
bool near(const XrVector2f& a, const XrVector2f& b) { return near(a.x, b.x) && near(a.y, b.y); }
bool near(const XrVector3f& a, const XrVector3f& b) { return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z); }

template <typename T>
bool near_all(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!near(a[i], b[i])) return false;
  return true;
}

bool same_entity(const ServedEntity& a, const ServedEntity& b) {
  return a.id == b.id && same_class(a, b) && glm::length(a.pose.translation - b.pose.translation) <= kSameGeometry &&
         std::fabs(glm::dot(a.pose.rotation, b.pose.rotation)) >= 1.0 - 1e-7 && near(a.extents.width, b.extents.width) &&
         near(a.extents.height, b.extents.height) && near_all(a.polygon, b.polygon) && a.mesh_indices == b.mesh_indices &&
         a.area.interaction == b.area.interaction && a.area.categoryFlags == b.area.categoryFlags &&
         near(a.area.volumeHeight, b.area.volumeHeight) && near_all(a.room_vertices, b.room_vertices) &&
         a.room_indices == b.room_indices && a.location.storeyIndex == b.location.storeyIndex &&
         a.location.roomIndex == b.location.roomIndex;
}

}  // namespace

bool ServedEntity::has(XrSpatialComponentTypeEXT component) const {
  switch (kind) {
    case EntityKind::Plane:
      return component == XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT || component == XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT ||
             component == XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT || component == XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT ||
             component == XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT ||
             component == XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX;
    case EntityKind::Area:
      return component == XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT || component == XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX ||
             component == XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX;
    case EntityKind::Room: return component == XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT;
  }
  return false;
}

XrSpatialCapabilityEXT ServedEntity::capability() const {
  return kind == EntityKind::Plane ? XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT : XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX;
}

const ServedEntity* EntitySet::find(XrSpatialEntityIdEXT id) const {
  const auto it = std::lower_bound(entities.begin(), entities.end(), id,
                                   [](const ServedEntity& e, XrSpatialEntityIdEXT wanted) { return e.id < wanted; });
  return it != entities.end() && it->id == id ? &*it : nullptr;
}

EntitySet build_entity_set(const RoomResult& result, const EntitySet& previous) {
  std::vector<ServedEntity> fresh;
  const std::vector<Surface>& surfaces = result.surfaces();
  fresh.reserve(surfaces.size() + result.areas.size() + 1);
  for (const Surface& s : surfaces) fresh.push_back(plane_of(s));
  for (std::size_t i = 0; i < result.areas.size(); ++i) fresh.push_back(area_of(result.areas[i], result.area_locations[i]));
  if (!result.bounds_indices.empty()) {
    ServedEntity room;
    room.kind = EntityKind::Room;
    room.room_vertices = result.bounds_vertices;
    room.room_indices = result.bounds_indices;
    room.extents = {result.bounds_max.x - result.bounds_min.x, result.bounds_max.z - result.bounds_min.z};
    fresh.push_back(std::move(room));
  }

  // Ids: the best-matching old entity of each new one, closest pairs first, each old id used once.
  struct Pair {
    double cost;
    std::size_t now, before;
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < fresh.size(); ++i)
    for (std::size_t j = 0; j < previous.entities.size(); ++j)
      if (const double c = match_cost(previous.entities[j], fresh[i]); c >= 0.0) pairs.push_back({c, i, j});
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.cost < b.cost; });
  std::vector<bool> old_used(previous.entities.size(), false);
  for (const Pair& p : pairs)
    if (fresh[p.now].id == XR_NULL_SPATIAL_ENTITY_ID_EXT && !old_used[p.before]) {
      fresh[p.now].id = previous.entities[p.before].id;
      old_used[p.before] = true;
    }
  EntitySet set;
  set.next_id = previous.next_id;
  for (ServedEntity& e : fresh)
    if (e.id == XR_NULL_SPATIAL_ENTITY_ID_EXT) e.id = set.next_id++;
  std::sort(fresh.begin(), fresh.end(), [](const ServedEntity& a, const ServedEntity& b) { return a.id < b.id; });
  set.entities = std::move(fresh);
  return set;
}

bool same_entities(const EntitySet& a, const EntitySet& b) {
  if (a.entities.size() != b.entities.size()) return false;
  for (std::size_t i = 0; i < a.entities.size(); ++i)
    if (!same_entity(a.entities[i], b.entities[i])) return false;
  return true;
}

}  // namespace roomsense::layer
