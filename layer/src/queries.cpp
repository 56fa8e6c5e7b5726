// XR_EXTX_room_understanding's queries (spec version 2): the spec's validation, then core's RoomQueries on the
// latest result (results.h). Order of checks, as in OpenXR: handle, then structure types and pointers and values,
// then state (call order).
#include "analyzer.h"
#include "functions.h"
#include "guard.h"

#include "roomsense/error.h"
#include "roomsense/xr/rigid.h"

#include <cmath>

namespace roomsense::layer {
namespace {

using xr::vec3_of;
using xr::xr_vector;

constexpr XrRoomSurfaceFlagsEXTX kAllSurfaces = XR_ROOM_SURFACE_WALL_BIT_EXTX | XR_ROOM_SURFACE_FLOOR_BIT_EXTX |
                                                XR_ROOM_SURFACE_CEILING_BIT_EXTX | XR_ROOM_SURFACE_FURNITURE_BIT_EXTX;
// The extension's surface bits are core's SurfaceBits.
static_assert(XR_ROOM_SURFACE_WALL_BIT_EXTX == kOnWall && XR_ROOM_SURFACE_FLOOR_BIT_EXTX == kOnFloor &&
              XR_ROOM_SURFACE_CEILING_BIT_EXTX == kOnCeiling && XR_ROOM_SURFACE_FURNITURE_BIT_EXTX == kOnFurniture);

bool finite(const XrVector3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The latest result of a valid analyzer, or why there is none.
XrResult latest_of(XrRoomAnalyzerEXTX handle, std::shared_ptr<const RoomResult>& out) {
  const std::shared_ptr<Analyzer> a = find_analyzer(handle);
  if (!a) return XR_ERROR_HANDLE_INVALID;
  out = a->latest();
  return XR_SUCCESS;
}

// Core refuses what the spec calls invalid with Error(BadParameter): the one list of limits (queries.h).
template <typename Query>
XrResult validated(Query&& query) {
  try {
    return query();
  } catch (const Error& e) {
    if (e.code() != ErrorCode::BadParameter) throw;
    return XR_ERROR_VALIDATION_FAILURE;
  }
}

}  // namespace

XrResult XRAPI_CALL xrFindRoomPlacementsEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomPlacementQueryEXTX* query,
                                             XrRoomPlacementsEXTX* placements) {
  return guarded("xrFindRoomPlacementsEXTX", [&]() -> XrResult {
    std::shared_ptr<const RoomResult> result;
    if (const XrResult r = latest_of(analyzer, result); XR_FAILED(r)) return r;
    if (!has_type(query, XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX) || !has_type(placements, XR_TYPE_ROOM_PLACEMENTS_EXTX))
      return XR_ERROR_VALIDATION_FAILURE;
    if (placements->placementCapacityInput > 0 && placements->placements == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (uint32_t i = 0; i < placements->placementCapacityInput; ++i)
      if (placements->placements[i].type != XR_TYPE_ROOM_PLACEMENT_EXTX) return XR_ERROR_VALIDATION_FAILURE;
    if ((query->surfaces & ~kAllSurfaces) != 0 || query->surfaces == 0) return XR_ERROR_VALIDATION_FAILURE;
    if (query->reach != XR_ROOM_REACH_FILTER_ANY_EXTX && query->reach != XR_ROOM_REACH_FILTER_CLOSE_EXTX &&
        query->reach != XR_ROOM_REACH_FILTER_DISTANCE_EXTX)
      return XR_ERROR_VALIDATION_FAILURE;
    PlacementQuery q;
    q.size = vec3_of(query->objectSize);
    q.surfaces = static_cast<std::uint32_t>(query->surfaces);
    q.clearance = query->clearance;
    q.clearance_above = query->clearanceAbove;
    q.edge_distance = query->edgeDistance;
    q.reach = static_cast<ReachFilter>(query->reach);
    if (query->hasUserPosition) q.user_position = vec3_of(query->userPosition);
    if (query->userReach != 0.0f) q.user_reach = query->userReach;
    if (query->hasNearPoint) q.near = vec3_of(query->nearPoint);
    q.face_direction = vec3_of(query->faceDirection);
    q.max_count = query->maxPlacements;
    q.allow_overlap = query->allowOverlap != XR_FALSE;
    q.seed = query->seed;
    return validated([&]() -> XrResult {
      // Checked before the call order, so an invalid query fails the same way with or without a result.
      const PlacementResult found = (result ? result->queries() : RoomQueries()).find_placements(q);
      if (!result) return XR_ERROR_CALL_ORDER_INVALID;
      const auto count = static_cast<uint32_t>(found.placements.size());
      placements->placementCountOutput = count;
      placements->shortfall = static_cast<XrRoomPlacementShortfallEXTX>(found.shortfall);
      if (placements->placementCapacityInput == 0) return XR_SUCCESS;
      if (placements->placementCapacityInput < count) return XR_ERROR_SIZE_INSUFFICIENT;
      for (uint32_t i = 0; i < count; ++i) {
        const Placement& p = found.placements[i];
        XrRoomPlacementEXTX& out = placements->placements[i];
        out.pose.orientation = xr::xr_quaternion(p.orientation());
        out.pose.position = xr_vector(p.center);
        out.extents = {p.footprint.x, p.footprint.y};
        // The core's enums carry the extension's values (areas.h).
        out.surfaceType = static_cast<XrRoomAreaTypeEXTX>(p.surface);
        out.interaction = static_cast<XrRoomInteractionEXTX>(p.reach);
        out.storeyIndex = p.storey;
        out.margin = p.margin;
      }
      return XR_SUCCESS;
    });
  });
}

XrResult XRAPI_CALL xrRaycastRoomEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomRaycastInfoEXTX* info,
                                      XrRoomRaycastHitEXTX* hit) {
  return guarded("xrRaycastRoomEXTX", [&]() -> XrResult {
    std::shared_ptr<const RoomResult> result;
    if (const XrResult r = latest_of(analyzer, result); XR_FAILED(r)) return r;
    if (!has_type(info, XR_TYPE_ROOM_RAYCAST_INFO_EXTX) || !has_type(hit, XR_TYPE_ROOM_RAYCAST_HIT_EXTX))
      return XR_ERROR_VALIDATION_FAILURE;
    if (!finite(info->origin) || !finite(info->direction) || !std::isfinite(info->maxDistance) || info->maxDistance < 0.0f)
      return XR_ERROR_VALIDATION_FAILURE;
    const float max_distance = info->maxDistance == 0.0f ? INFINITY : info->maxDistance;
    return validated([&]() -> XrResult {
      const std::optional<RayHit> h =
          (result ? result->queries() : RoomQueries()).raycast(vec3_of(info->origin), vec3_of(info->direction), max_distance);
      if (!result) return XR_ERROR_CALL_ORDER_INVALID;
      hit->hit = h ? XR_TRUE : XR_FALSE;
      const RayHit none{};
      const RayHit& v = h ? *h : none;
      hit->position = xr_vector(v.position);
      hit->normal = xr_vector(h ? v.normal : glm::vec3(0.0f));
      hit->distance = h ? v.distance : 0.0f;
      hit->surfaceType = h ? static_cast<XrRoomAreaTypeEXTX>(v.surface) : static_cast<XrRoomAreaTypeEXTX>(0);
      hit->scanned = h && v.scanned ? XR_TRUE : XR_FALSE;
      return XR_SUCCESS;
    });
  });
}

XrResult XRAPI_CALL xrGetRoomRandomPointEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomRandomPointInfoEXTX* info,
                                             XrRoomPointEXTX* point) {
  return guarded("xrGetRoomRandomPointEXTX", [&]() -> XrResult {
    std::shared_ptr<const RoomResult> result;
    if (const XrResult r = latest_of(analyzer, result); XR_FAILED(r)) return r;
    if (!has_type(info, XR_TYPE_ROOM_RANDOM_POINT_INFO_EXTX) || !has_type(point, XR_TYPE_ROOM_POINT_EXTX))
      return XR_ERROR_VALIDATION_FAILURE;
    if ((info->surfaces & ~kAllSurfaces) != 0) return XR_ERROR_VALIDATION_FAILURE;
    return validated([&]() -> XrResult {
      const RoomQueries& queries = result ? result->queries() : RoomQueries();
      std::optional<SurfacePoint> found;
      if (info->surfaces != 0) {
        found = queries.random_point_on_surface(static_cast<std::uint32_t>(info->surfaces), info->distance, info->seed);
      } else if (const std::optional<glm::vec3> p = queries.random_point_in_room(info->distance, info->seed)) {
        found = SurfacePoint{*p, glm::vec3(0.0f), static_cast<AreaType>(0)};
      }
      if (!result) return XR_ERROR_CALL_ORDER_INVALID;
      point->found = found ? XR_TRUE : XR_FALSE;
      point->position = xr_vector(found ? found->position : glm::vec3(0.0f));
      point->normal = xr_vector(found ? found->normal : glm::vec3(0.0f));
      point->surfaceType = static_cast<XrRoomAreaTypeEXTX>(found ? found->surface : static_cast<AreaType>(0));
      return XR_SUCCESS;
    });
  });
}

XrResult XRAPI_CALL xrLocateRoomPointEXTX(XrRoomAnalyzerEXTX analyzer, const XrVector3f* point,
                                          XrRoomPointLocationEXTX* location) {
  return guarded("xrLocateRoomPointEXTX", [&]() -> XrResult {
    std::shared_ptr<const RoomResult> result;
    if (const XrResult r = latest_of(analyzer, result); XR_FAILED(r)) return r;
    if (point == nullptr || !finite(*point) || !has_type(location, XR_TYPE_ROOM_POINT_LOCATION_EXTX))
      return XR_ERROR_VALIDATION_FAILURE;
    if (!result) return XR_ERROR_CALL_ORDER_INVALID;
    const RoomLocation where = result->queries().locate(vec3_of(*point));
    location->insideRoom = where.inside ? XR_TRUE : XR_FALSE;
    location->inFreeSpace = where.free ? XR_TRUE : XR_FALSE;
    location->storeyIndex = where.storey;
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::layer
