// XR_EXTX_room_understanding's queries (spec version 2) through the loader: the same answers as core's RoomQueries
// on the same meshes (submitted meshes reach the pipeline bit for bit), the two-call idiom, and the spec's
// validation and call order.
#include "layer_harness.h"
#include "roomsense/analysis.h"
#include "roomsense/queries.h"
#include "roomsense/synthetic.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace layertest;

struct Submitted {
  roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:default");
  App app;
  XrRoomAnalyzerEXTX analyzer = app.analyzer();
  void compute() {
    std::vector<XrVector3f> v;
    for (const glm::vec3& p : scan.vertices) v.push_back({p.x, p.y, p.z});
    app.submit(analyzer, v, scan.indices);
    ASSERT_EQ(app.compute(analyzer, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  }
};

XrRoomPlacementQueryEXTX query(XrRoomSurfaceFlagsEXTX surfaces, XrVector3f size, uint32_t count) {
  XrRoomPlacementQueryEXTX q{XR_TYPE_ROOM_PLACEMENT_QUERY_EXTX, nullptr};
  q.objectSize = size;
  q.surfaces = surfaces;
  q.maxPlacements = count;
  return q;
}

std::vector<XrRoomPlacementEXTX> place(const App& app, XrRoomAnalyzerEXTX a, const XrRoomPlacementQueryEXTX& q,
                                       XrRoomPlacementShortfallEXTX* shortfall = nullptr) {
  XrRoomPlacementsEXTX out{XR_TYPE_ROOM_PLACEMENTS_EXTX, nullptr};
  LT_CHECK(app.extx.place(a, &q, &out));
  std::vector<XrRoomPlacementEXTX> placements(out.placementCountOutput, {XR_TYPE_ROOM_PLACEMENT_EXTX, nullptr});
  out.placementCapacityInput = out.placementCountOutput;
  out.placements = placements.data();
  LT_CHECK(app.extx.place(a, &q, &out));
  if (shortfall) *shortfall = out.shortfall;
  return placements;
}

TEST(LayerQueries, PlacementsRaycastsAndPointsAreCoresOnTheSameMeshes) {
  Submitted s;
  s.compute();
  const roomsense::AnalysisResult analysis = roomsense::analyze(s.scan);
  const roomsense::RoomQueries core(analysis);

  for (const auto& [surfaces, size] : {std::pair{XR_ROOM_SURFACE_FURNITURE_BIT_EXTX, XrVector3f{0.3f, 0.3f, 0.3f}},
                                       std::pair{XR_ROOM_SURFACE_WALL_BIT_EXTX, XrVector3f{0.6f, 0.4f, 0.05f}},
                                       std::pair{XR_ROOM_SURFACE_FLOOR_BIT_EXTX | XR_ROOM_SURFACE_CEILING_BIT_EXTX,
                                                 XrVector3f{0.5f, 0.5f, 0.5f}}}) {
    XrRoomPlacementQueryEXTX q = query(surfaces, size, 5);
    q.seed = 42;
    XrRoomPlacementShortfallEXTX shortfall = XR_ROOM_PLACEMENT_SHORTFALL_MAX_ENUM_EXTX;
    const std::vector<XrRoomPlacementEXTX> got = place(s.app, s.analyzer, q, &shortfall);
    roomsense::PlacementQuery cq;
    cq.size = {size.x, size.y, size.z};
    cq.surfaces = static_cast<std::uint32_t>(surfaces);
    cq.max_count = 5;
    cq.seed = 42;
    const roomsense::PlacementResult want = core.find_placements(cq);
    ASSERT_EQ(got.size(), want.placements.size());
    EXPECT_EQ(int(shortfall), int(want.shortfall));
    ASSERT_FALSE(got.empty());
    for (std::size_t i = 0; i < got.size(); ++i) {
      const roomsense::Placement& w = want.placements[i];
      const glm::quat o = w.orientation();
      EXPECT_EQ(got[i].pose.position.x, w.center.x);
      EXPECT_EQ(got[i].pose.position.y, w.center.y);
      EXPECT_EQ(got[i].pose.position.z, w.center.z);
      EXPECT_EQ(got[i].pose.orientation.w, o.w);
      EXPECT_EQ(got[i].pose.orientation.y, o.y);
      EXPECT_EQ(int(got[i].surfaceType), int(w.surface));
      EXPECT_EQ(int(got[i].interaction), int(w.reach));
      EXPECT_EQ(got[i].extents.width, size.x);
      EXPECT_EQ(got[i].extents.height, size.y);
      EXPECT_EQ(got[i].next, nullptr);
    }
  }

  XrRoomRaycastInfoEXTX ray{XR_TYPE_ROOM_RAYCAST_INFO_EXTX, nullptr, {0.0f, 1.2f, 0.3f}, {1.0f, 0.0f, 0.0f}, 0.0f};
  XrRoomRaycastHitEXTX hit{XR_TYPE_ROOM_RAYCAST_HIT_EXTX, nullptr};
  LT_CHECK(s.app.extx.raycast(s.analyzer, &ray, &hit));
  const std::optional<roomsense::RayHit> want_hit = core.raycast({0.0f, 1.2f, 0.3f}, {1.0f, 0.0f, 0.0f});
  ASSERT_TRUE(want_hit);
  EXPECT_EQ(hit.hit, XR_TRUE);
  EXPECT_EQ(hit.position.x, want_hit->position.x);
  EXPECT_EQ(hit.normal.x, -1.0f);
  EXPECT_EQ(hit.surfaceType, XR_ROOM_AREA_TYPE_WALL_EXTX);
  EXPECT_EQ(hit.scanned, XR_TRUE);
  ray.maxDistance = 1.0f;  // the wall is 2.5 m away
  LT_CHECK(s.app.extx.raycast(s.analyzer, &ray, &hit));
  EXPECT_EQ(hit.hit, XR_FALSE);

  XrRoomRandomPointInfoEXTX info{XR_TYPE_ROOM_RANDOM_POINT_INFO_EXTX, nullptr, XR_ROOM_SURFACE_FLOOR_BIT_EXTX, 0.2f, 7};
  XrRoomPointEXTX point{XR_TYPE_ROOM_POINT_EXTX, nullptr};
  LT_CHECK(s.app.extx.random_point(s.analyzer, &info, &point));
  const std::optional<roomsense::SurfacePoint> want_point = core.random_point_on_surface(roomsense::kOnFloor, 0.2f, 7);
  ASSERT_TRUE(want_point);
  EXPECT_EQ(point.found, XR_TRUE);
  EXPECT_EQ(point.position.x, want_point->position.x);
  EXPECT_EQ(point.surfaceType, XR_ROOM_AREA_TYPE_FLOOR_EXTX);
  info.surfaces = 0;  // free space, 0.3 m from everything
  info.distance = 0.3f;
  LT_CHECK(s.app.extx.random_point(s.analyzer, &info, &point));
  EXPECT_EQ(point.found, XR_TRUE);
  EXPECT_EQ(point.position.y, core.random_point_in_room(0.3f, 7)->y);
  EXPECT_EQ(int(point.surfaceType), 0);

  XrRoomPointLocationEXTX where{XR_TYPE_ROOM_POINT_LOCATION_EXTX, nullptr};
  const XrVector3f inside{0.0f, 1.0f, 0.0f}, outside{0.0f, 5.0f, 0.0f};
  LT_CHECK(s.app.extx.locate(s.analyzer, &inside, &where));
  EXPECT_EQ(where.insideRoom, XR_TRUE);
  EXPECT_EQ(where.inFreeSpace, XR_TRUE);
  LT_CHECK(s.app.extx.locate(s.analyzer, &outside, &where));
  EXPECT_EQ(where.insideRoom, XR_FALSE);
}

TEST(LayerQueries, ValidationCallOrderAndTheTwoCallIdiom) {
  Submitted s;
  const Extx& x = s.app.extx;
  XrRoomPlacementQueryEXTX q = query(XR_ROOM_SURFACE_FLOOR_BIT_EXTX, {0.5f, 0.5f, 0.5f}, 4);
  XrRoomPlacementsEXTX out{XR_TYPE_ROOM_PLACEMENTS_EXTX, nullptr};
  // Before any result: call order; an invalid query is invalid whatever the state.
  EXPECT_EQ(x.place(s.analyzer, &q, &out), XR_ERROR_CALL_ORDER_INVALID);
  q.objectSize.x = NAN;
  EXPECT_EQ(x.place(s.analyzer, &q, &out), XR_ERROR_VALIDATION_FAILURE);
  q.objectSize.x = 0.5f;
  XrRoomPointLocationEXTX where{XR_TYPE_ROOM_POINT_LOCATION_EXTX, nullptr};
  const XrVector3f origin{0, 1, 0};
  EXPECT_EQ(x.locate(s.analyzer, &origin, &where), XR_ERROR_CALL_ORDER_INVALID);
  s.compute();

  EXPECT_EQ(x.place(XR_NULL_HANDLE, &q, &out), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(x.place(s.analyzer, nullptr, &out), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(x.place(s.analyzer, &q, nullptr), XR_ERROR_VALIDATION_FAILURE);
  const auto invalid = [&](auto change) {
    XrRoomPlacementQueryEXTX bad = q;
    change(bad);
    XrRoomPlacementsEXTX o{XR_TYPE_ROOM_PLACEMENTS_EXTX, nullptr};
    return x.place(s.analyzer, &bad, &o) == XR_ERROR_VALIDATION_FAILURE;
  };
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.type = XR_TYPE_ROOM_AREA_EXTX; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.surfaces = 0; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.surfaces = 0x10; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.reach = XrRoomReachFilterEXTX(9); }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.maxPlacements = 0; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.maxPlacements = 5000; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.clearance = -1.0f; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.objectSize.z = 0.0f; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.hasNearPoint = XR_TRUE, b.nearPoint.x = INFINITY; }));
  EXPECT_TRUE(invalid([](XrRoomPlacementQueryEXTX& b) { b.userReach = -0.5f; }));

  // Two calls: the count, then the placements; too small a capacity says so and sets the count.
  LT_CHECK(x.place(s.analyzer, &q, &out));
  ASSERT_EQ(out.placementCountOutput, 4u);
  EXPECT_EQ(out.shortfall, XR_ROOM_PLACEMENT_SHORTFALL_NONE_EXTX);
  std::vector<XrRoomPlacementEXTX> buffer(2, {XR_TYPE_ROOM_PLACEMENT_EXTX, nullptr});
  out.placementCapacityInput = 2;
  out.placements = buffer.data();
  EXPECT_EQ(x.place(s.analyzer, &q, &out), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(out.placementCountOutput, 4u);
  buffer.assign(4, {XR_TYPE_ROOM_PLACEMENT_EXTX, nullptr});
  buffer[3].type = XR_TYPE_ROOM_AREA_EXTX;
  out.placementCapacityInput = 4;
  out.placements = buffer.data();
  EXPECT_EQ(x.place(s.analyzer, &q, &out), XR_ERROR_VALIDATION_FAILURE);
  out.placements = nullptr;
  EXPECT_EQ(x.place(s.analyzer, &q, &out), XR_ERROR_VALIDATION_FAILURE);

  // What the room cannot hold is an answer, not an error.
  q.objectSize = {9.0f, 9.0f, 1.0f};
  out = {XR_TYPE_ROOM_PLACEMENTS_EXTX, nullptr};
  LT_CHECK(x.place(s.analyzer, &q, &out));
  EXPECT_EQ(out.placementCountOutput, 0u);
  EXPECT_EQ(out.shortfall, XR_ROOM_PLACEMENT_SHORTFALL_NO_SPACE_EXTX);

  XrRoomRaycastInfoEXTX ray{XR_TYPE_ROOM_RAYCAST_INFO_EXTX, nullptr, {-1.0f, 1.0f, 0.8f}, {0, 0, 0}, 0.0f};
  XrRoomRaycastHitEXTX hit{XR_TYPE_ROOM_RAYCAST_HIT_EXTX, nullptr};
  EXPECT_EQ(x.raycast(s.analyzer, &ray, &hit), XR_ERROR_VALIDATION_FAILURE);  // a zero direction
  ray.direction = {0, -1, 0};
  ray.maxDistance = -1.0f;
  EXPECT_EQ(x.raycast(s.analyzer, &ray, &hit), XR_ERROR_VALIDATION_FAILURE);
  ray.maxDistance = 0.0f;
  hit.type = XR_TYPE_ROOM_AREA_EXTX;
  EXPECT_EQ(x.raycast(s.analyzer, &ray, &hit), XR_ERROR_VALIDATION_FAILURE);
  hit.type = XR_TYPE_ROOM_RAYCAST_HIT_EXTX;
  LT_CHECK(x.raycast(s.analyzer, &ray, &hit));
  EXPECT_EQ(hit.surfaceType, XR_ROOM_AREA_TYPE_FLOOR_EXTX);

  XrRoomRandomPointInfoEXTX info{XR_TYPE_ROOM_RANDOM_POINT_INFO_EXTX, nullptr, 0x20, 0.0f, 1};
  XrRoomPointEXTX point{XR_TYPE_ROOM_POINT_EXTX, nullptr};
  EXPECT_EQ(x.random_point(s.analyzer, &info, &point), XR_ERROR_VALIDATION_FAILURE);
  info.surfaces = XR_ROOM_SURFACE_CEILING_BIT_EXTX;
  info.distance = NAN;
  EXPECT_EQ(x.random_point(s.analyzer, &info, &point), XR_ERROR_VALIDATION_FAILURE);
  info.distance = 50.0f;  // no ceiling 50 m from its edge: found is false
  LT_CHECK(x.random_point(s.analyzer, &info, &point));
  EXPECT_EQ(point.found, XR_FALSE);

  const XrVector3f nan_point{NAN, 0, 0};
  EXPECT_EQ(x.locate(s.analyzer, &nan_point, &where), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(x.locate(s.analyzer, nullptr, &where), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(x.locate(s.analyzer, &origin, nullptr), XR_ERROR_VALIDATION_FAILURE);
}

}  // namespace
