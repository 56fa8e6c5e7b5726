// Quest's scene model through the loader: XR_FB_spatial_entity, XR_FB_spatial_entity_query, XR_FB_scene,
// XR_FB_spatial_entity_container and XR_META_spatial_entity_mesh. Queries and their events, the global mesh
// (in its own space, located with xrLocateSpace), a capture's labelled anchors, validation, and a runtime that
// plays a Quest (ROOMSENSE_SIM_EXTENSIONS).
#include "rooms.h"
#include "roomsense/scanio.h"
#include "sim_env.h"
#include "xr_harness.h"

// The project's declarations of these extensions (Debian's OpenXR 1.0.20 headers lack them); this test
// target has scanio's and the test support's include paths only.
#include "roomsense/xr/ext/XR_FB_scene.h"
#include "roomsense/xr/ext/XR_FB_spatial_entity.h"
#include "roomsense/xr/ext/XR_META_spatial_entity_mesh.h"

#include <glm/gtc/quaternion.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

using simtest::proc;
using simtest::ScopedEnv;

const char* const kQuestExtensions = "XR_FB_spatial_entity,XR_FB_spatial_entity_query,XR_FB_scene,"
                                     "XR_FB_spatial_entity_container,XR_META_spatial_entity_mesh";

struct Quest : simtest::App {
  PFN_xrQuerySpacesFB query = nullptr;
  PFN_xrRetrieveSpaceQueryResultsFB retrieve = nullptr;
  PFN_xrEnumerateSpaceSupportedComponentsFB components = nullptr;
  PFN_xrGetSpaceComponentStatusFB getStatus = nullptr;
  PFN_xrSetSpaceComponentStatusFB setStatus = nullptr;
  PFN_xrGetSpaceUuidFB uuid = nullptr;
  PFN_xrCreateSpatialAnchorFB createAnchor = nullptr;
  PFN_xrGetSpaceSemanticLabelsFB labels = nullptr;
  PFN_xrGetSpaceBoundingBox2DFB box2d = nullptr;
  PFN_xrGetSpaceBoundingBox3DFB box3d = nullptr;
  PFN_xrGetSpaceBoundary2DFB boundary = nullptr;
  PFN_xrGetSpaceRoomLayoutFB layout = nullptr;
  PFN_xrGetSpaceContainerFB container = nullptr;
  PFN_xrGetSpaceTriangleMeshMETA mesh = nullptr;

  Quest()
      : simtest::App({XR_MND_HEADLESS_EXTENSION_NAME, XR_FB_SPATIAL_ENTITY_EXTENSION_NAME,
                      XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME, XR_FB_SCENE_EXTENSION_NAME,
                      XR_FB_SPATIAL_ENTITY_CONTAINER_EXTENSION_NAME, XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME}) {
    query = proc<PFN_xrQuerySpacesFB>(instance, "xrQuerySpacesFB");
    retrieve = proc<PFN_xrRetrieveSpaceQueryResultsFB>(instance, "xrRetrieveSpaceQueryResultsFB");
    components = proc<PFN_xrEnumerateSpaceSupportedComponentsFB>(instance, "xrEnumerateSpaceSupportedComponentsFB");
    getStatus = proc<PFN_xrGetSpaceComponentStatusFB>(instance, "xrGetSpaceComponentStatusFB");
    setStatus = proc<PFN_xrSetSpaceComponentStatusFB>(instance, "xrSetSpaceComponentStatusFB");
    uuid = proc<PFN_xrGetSpaceUuidFB>(instance, "xrGetSpaceUuidFB");
    createAnchor = proc<PFN_xrCreateSpatialAnchorFB>(instance, "xrCreateSpatialAnchorFB");
    labels = proc<PFN_xrGetSpaceSemanticLabelsFB>(instance, "xrGetSpaceSemanticLabelsFB");
    box2d = proc<PFN_xrGetSpaceBoundingBox2DFB>(instance, "xrGetSpaceBoundingBox2DFB");
    box3d = proc<PFN_xrGetSpaceBoundingBox3DFB>(instance, "xrGetSpaceBoundingBox3DFB");
    boundary = proc<PFN_xrGetSpaceBoundary2DFB>(instance, "xrGetSpaceBoundary2DFB");
    layout = proc<PFN_xrGetSpaceRoomLayoutFB>(instance, "xrGetSpaceRoomLayoutFB");
    container = proc<PFN_xrGetSpaceContainerFB>(instance, "xrGetSpaceContainerFB");
    mesh = proc<PFN_xrGetSpaceTriangleMeshMETA>(instance, "xrGetSpaceTriangleMeshMETA");
  }

  // Every event queued now (session state changes included).
  std::vector<XrEventDataBuffer> events() const {
    std::vector<XrEventDataBuffer> out;
    for (;;) {
      XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
      const XrResult r = xrPollEvent(instance, &e);
      if (r == XR_EVENT_UNAVAILABLE) return out;
      SIM_CHECK(r);
      out.push_back(e);
    }
  }

  XrAsyncRequestIdFB start_query(const XrSpaceFilterInfoBaseHeaderFB* filter) const {
    XrSpaceQueryInfoFB info{XR_TYPE_SPACE_QUERY_INFO_FB};
    info.queryAction = XR_SPACE_QUERY_ACTION_LOAD_FB;
    info.maxResultCount = 100;
    info.filter = filter;
    XrAsyncRequestIdFB request = 0;
    SIM_CHECK(query(session, reinterpret_cast<const XrSpaceQueryInfoBaseHeaderFB*>(&info), &request));
    return request;
  }

  std::vector<XrSpaceQueryResultFB> results(XrAsyncRequestIdFB request) const {
    XrSpaceQueryResultsFB r{XR_TYPE_SPACE_QUERY_RESULTS_FB};
    SIM_CHECK(retrieve(session, request, &r));
    std::vector<XrSpaceQueryResultFB> out(r.resultCountOutput);
    if (out.empty()) return out;
    r.resultCapacityInput = r.resultCountOutput;
    r.results = out.data();
    SIM_CHECK(retrieve(session, request, &r));
    return out;
  }

  // A query as an app runs it: start, wait for the events, retrieve.
  std::vector<XrSpaceQueryResultFB> find(const XrSpaceFilterInfoBaseHeaderFB* filter) const {
    const XrAsyncRequestIdFB request = start_query(filter);
    bool complete = false;
    for (const XrEventDataBuffer& e : events())
      if (e.type == XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB) {
        const auto& c = reinterpret_cast<const XrEventDataSpaceQueryCompleteFB&>(e);
        complete = complete || (c.requestId == request && c.result == XR_SUCCESS);
      }
    if (!complete) throw std::runtime_error("no query-complete event");
    return results(request);
  }

  std::vector<XrSpaceQueryResultFB> find_component(XrSpaceComponentTypeFB type) const {
    XrSpaceComponentFilterInfoFB filter{XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB};
    filter.componentType = type;
    return find(reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&filter));
  }

  std::string label_of(XrSpace space, const char* recognized = nullptr) const {
    XrSemanticLabelsFB l{XR_TYPE_SEMANTIC_LABELS_FB};
    XrSemanticLabelsSupportInfoFB support{XR_TYPE_SEMANTIC_LABELS_SUPPORT_INFO_FB};
    support.recognizedLabels = recognized;
    if (recognized != nullptr) l.next = &support;
    SIM_CHECK(labels(session, space, &l));
    std::string text(l.bufferCountOutput, '\0');
    l.bufferCapacityInput = l.bufferCountOutput;
    l.buffer = text.data();
    SIM_CHECK(labels(session, space, &l));
    text.resize(std::strlen(text.c_str()));
    return text;
  }

  bool enabled(XrSpace space, XrSpaceComponentTypeFB type) const {
    XrSpaceComponentStatusFB status{XR_TYPE_SPACE_COMPONENT_STATUS_FB};
    SIM_CHECK(getStatus(space, type, &status));
    return status.enabled == XR_TRUE;
  }

  XrPosef locate(XrSpace space) const {
    XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
    SIM_CHECK(xrLocateSpace(space, local, 1, &location));
    EXPECT_EQ(location.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT, XR_SPACE_LOCATION_POSITION_VALID_BIT);
    return location.pose;
  }
};

bool same_uuid(const XrUuidEXT& a, const XrUuidEXT& b) { return std::memcmp(a.data, b.data, sizeof a.data) == 0; }

glm::dvec3 apply(const XrPosef& p, const XrVector3f& v) {
  const glm::dquat q(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
  return q * glm::dvec3(v.x, v.y, v.z) + glm::dvec3(p.position.x, p.position.y, p.position.z);
}

TEST(MetaSpatialEntityMesh, QueryEventsAndTheGlobalMeshLocatedInLocalIsTheRoom) {
  const std::filesystem::path file = simtest::write_box_room("meta_global_mesh_box.obj");
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", file.string());
  Quest q;
  q.events();  // the session's own state changes
  XrSpaceComponentFilterInfoFB filter{XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB};
  filter.componentType = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
  const XrAsyncRequestIdFB request = q.start_query(reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&filter));
  // Results available, then complete, for this request.
  const auto events = q.events();
  ASSERT_EQ(events.size(), 2u);
  ASSERT_EQ(events[0].type, XR_TYPE_EVENT_DATA_SPACE_QUERY_RESULTS_AVAILABLE_FB);
  EXPECT_EQ(reinterpret_cast<const XrEventDataSpaceQueryResultsAvailableFB&>(events[0]).requestId, request);
  ASSERT_EQ(events[1].type, XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB);
  EXPECT_EQ(reinterpret_cast<const XrEventDataSpaceQueryCompleteFB&>(events[1]).requestId, request);
  EXPECT_EQ(reinterpret_cast<const XrEventDataSpaceQueryCompleteFB&>(events[1]).result, XR_SUCCESS);

  const auto found = q.results(request);
  ASSERT_EQ(found.size(), 1u);
  XrSpaceQueryResultsFB again{XR_TYPE_SPACE_QUERY_RESULTS_FB};
  EXPECT_EQ(q.retrieve(q.session, request, &again), XR_ERROR_VALIDATION_FAILURE);  // retrieved once only
  const XrSpace space = found[0].space;
  XrUuidEXT uuid{};
  SIM_CHECK(q.uuid(space, &uuid));
  EXPECT_TRUE(same_uuid(uuid, found[0].uuid));
  EXPECT_EQ(q.label_of(space), "GLOBAL_MESH");

  // The mesh component starts disabled, as on a device; enabling it completes with an event.
  XrSpaceTriangleMeshGetInfoMETA get{XR_TYPE_SPACE_TRIANGLE_MESH_GET_INFO_META};
  XrSpaceTriangleMeshMETA mesh{XR_TYPE_SPACE_TRIANGLE_MESH_META};
  EXPECT_EQ(q.mesh(space, &get, &mesh), XR_ERROR_SPACE_COMPONENT_NOT_ENABLED_FB);
  EXPECT_FALSE(q.enabled(space, XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META));
  EXPECT_TRUE(q.enabled(space, XR_SPACE_COMPONENT_TYPE_LOCATABLE_FB));
  XrSpaceComponentStatusSetInfoFB set{XR_TYPE_SPACE_COMPONENT_STATUS_SET_INFO_FB};
  set.componentType = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
  set.enabled = XR_TRUE;
  XrAsyncRequestIdFB set_request = 0;
  SIM_CHECK(q.setStatus(space, &set, &set_request));
  const auto set_events = q.events();
  ASSERT_EQ(set_events.size(), 1u);
  ASSERT_EQ(set_events[0].type, XR_TYPE_EVENT_DATA_SPACE_SET_STATUS_COMPLETE_FB);
  const auto& done = reinterpret_cast<const XrEventDataSpaceSetStatusCompleteFB&>(set_events[0]);
  EXPECT_EQ(done.requestId, set_request);
  EXPECT_EQ(done.result, XR_SUCCESS);
  EXPECT_EQ(done.space, space);
  EXPECT_EQ(done.enabled, XR_TRUE);
  EXPECT_TRUE(q.enabled(space, XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META));

  // Two calls: counts, then both arrays.
  SIM_CHECK(q.mesh(space, &get, &mesh));
  std::vector<XrVector3f> vertices(mesh.vertexCountOutput);
  std::vector<uint32_t> indices(mesh.indexCountOutput);
  mesh.vertexCapacityInput = mesh.vertexCountOutput;
  mesh.vertices = vertices.data();
  mesh.indexCapacityInput = mesh.indexCountOutput;
  mesh.indices = indices.data();
  SIM_CHECK(q.mesh(space, &get, &mesh));

  const roomsense::Scan room = roomsense::scanio::load_mesh_file(file.string());
  ASSERT_EQ(vertices.size(), room.vertices.size());
  EXPECT_EQ(indices, room.indices);
  const XrPosef pose = q.locate(space);
  double located = 0, raw = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const glm::dvec3 want(room.vertices[i]);
    located = std::max(located, glm::length(apply(pose, vertices[i]) - want));
    raw = std::max(raw, glm::length(glm::dvec3(vertices[i].x, vertices[i].y, vertices[i].z) - want));
  }
  EXPECT_LE(located, 1e-4);
  EXPECT_GT(raw, 0.1) << "the mesh must be served in the anchor's own space, not in LOCAL";

  XrRect3DfFB box{};
  SIM_CHECK(q.box3d(q.session, space, &box));
  EXPECT_GT(box.extent.width * box.extent.height * box.extent.depth, 1.0f);
}

TEST(MetaSpatialEntityMesh, TheRoomAnchorHoldsItsChildrenAndUuidFiltersFindThem) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Quest q;
  const auto all = q.find(nullptr);
  ASSERT_GE(all.size(), 2u);
  const auto rooms = q.find_component(XR_SPACE_COMPONENT_TYPE_ROOM_LAYOUT_FB);
  ASSERT_EQ(rooms.size(), 1u);
  const auto meshes = q.find_component(XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META);
  ASSERT_EQ(meshes.size(), 1u);
  // The same anchor keeps its space handle across queries.
  EXPECT_EQ(std::count_if(all.begin(), all.end(), [&](const XrSpaceQueryResultFB& r) { return r.space == meshes[0].space; }), 1);

  XrSpaceContainerFB container{XR_TYPE_SPACE_CONTAINER_FB};
  SIM_CHECK(q.container(q.session, rooms[0].space, &container));
  std::vector<XrUuidEXT> children(container.uuidCountOutput);
  container.uuidCapacityInput = container.uuidCountOutput;
  container.uuids = children.data();
  SIM_CHECK(q.container(q.session, rooms[0].space, &container));
  EXPECT_EQ(children.size(), all.size() - 1);  // everything but the room itself
  EXPECT_TRUE(std::any_of(children.begin(), children.end(), [&](const XrUuidEXT& u) { return same_uuid(u, meshes[0].uuid); }));

  XrSpaceUuidFilterInfoFB by_uuid{XR_TYPE_SPACE_UUID_FILTER_INFO_FB};
  by_uuid.uuidCount = 1;
  by_uuid.uuids = children.data();
  const auto one = q.find(reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&by_uuid));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_TRUE(same_uuid(one[0].uuid, children[0]));

  // A storage location of the cloud holds nothing of the room: complete, no results, no results event.
  XrSpaceStorageLocationFilterInfoFB cloud{XR_TYPE_SPACE_STORAGE_LOCATION_FILTER_INFO_FB};
  cloud.location = XR_SPACE_STORAGE_LOCATION_CLOUD_FB;
  q.events();
  const XrAsyncRequestIdFB request = q.start_query(reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&cloud));
  const auto events = q.events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].type, XR_TYPE_EVENT_DATA_SPACE_QUERY_COMPLETE_FB);
  EXPECT_TRUE(q.results(request).empty());
}

TEST(MetaSpatialEntityMesh, AQuestCaptureServesItsLabelledAnchors) {
  ROOMSENSE_REQUIRE_ROOM(path, "quest-iwer/meeting_room.json");
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  Quest q;
  std::map<std::string, int> counts;
  XrSpace floor = XR_NULL_HANDLE, table = XR_NULL_HANDLE;
  for (const XrSpaceQueryResultFB& r : q.find_component(XR_SPACE_COMPONENT_TYPE_SEMANTIC_LABELS_FB)) {
    const std::string label = q.label_of(r.space);
    ++counts[label];
    if (label == "FLOOR") floor = r.space;
    if (label == "TABLE") table = r.space;
  }
  EXPECT_EQ(counts["GLOBAL_MESH"], 1);
  EXPECT_EQ(counts["FLOOR"], 1);
  EXPECT_EQ(counts["CEILING"], 1);
  EXPECT_GE(counts["WALL_FACE"], 4);
  EXPECT_GE(counts["TABLE"], 1);
  ASSERT_NE(floor, XR_NULL_HANDLE);
  ASSERT_NE(table, XR_NULL_HANDLE);

  // Labels an application does not recognise come back as OTHER.
  EXPECT_EQ(q.label_of(table, "FLOOR,CEILING,WALL_FACE"), "OTHER");
  EXPECT_EQ(q.label_of(floor, "FLOOR,CEILING,WALL_FACE"), "FLOOR");

  // The floor: a plane whose +Z points up, with its 2D bounds and boundary.
  const XrPosef pose = q.locate(floor);
  const glm::dquat rot(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
  EXPECT_GT((rot * glm::dvec3(0, 0, 1)).y, 0.99);
  XrRect2Df box{};
  SIM_CHECK(q.box2d(q.session, floor, &box));
  EXPECT_GT(box.extent.width * box.extent.height, 4.0f);
  XrBoundary2DFB boundary{XR_TYPE_BOUNDARY_2D_FB};
  SIM_CHECK(q.boundary(q.session, floor, &boundary));
  EXPECT_EQ(boundary.vertexCountOutput, 4u);

  // The room layout names the floor, the ceiling and every wall.
  const auto rooms = q.find_component(XR_SPACE_COMPONENT_TYPE_ROOM_LAYOUT_FB);
  ASSERT_EQ(rooms.size(), 1u);
  XrRoomLayoutFB layout{XR_TYPE_ROOM_LAYOUT_FB};
  SIM_CHECK(q.layout(q.session, rooms[0].space, &layout));
  EXPECT_EQ(static_cast<int>(layout.wallUuidCountOutput), counts["WALL_FACE"]);
  XrUuidEXT floor_uuid{};
  SIM_CHECK(q.uuid(floor, &floor_uuid));
  EXPECT_TRUE(same_uuid(layout.floorUuid, floor_uuid));
}

TEST(MetaSpatialEntityMesh, ValidationErrors) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Quest q;
  XrAsyncRequestIdFB request = 0;
  EXPECT_EQ(q.query(q.session, nullptr, &request), XR_ERROR_VALIDATION_FAILURE);
  XrSpaceQueryInfoFB info{XR_TYPE_SPACE_QUERY_INFO_FB};
  info.queryAction = XR_SPACE_QUERY_ACTION_LOAD_FB;
  const auto* header = reinterpret_cast<const XrSpaceQueryInfoBaseHeaderFB*>(&info);
  EXPECT_EQ(q.query(q.session, header, nullptr), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(q.query(XR_NULL_HANDLE, header, &request), XR_ERROR_HANDLE_INVALID);
  info.queryAction = static_cast<XrSpaceQueryActionFB>(7);
  EXPECT_EQ(q.query(q.session, header, &request), XR_ERROR_VALIDATION_FAILURE);
  info.queryAction = XR_SPACE_QUERY_ACTION_LOAD_FB;
  XrSpaceUuidFilterInfoFB empty{XR_TYPE_SPACE_UUID_FILTER_INFO_FB};
  info.filter = reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&empty);
  EXPECT_EQ(q.query(q.session, header, &request), XR_ERROR_VALIDATION_FAILURE);
  info.filter = reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&info);  // not a filter
  EXPECT_EQ(q.query(q.session, header, &request), XR_ERROR_VALIDATION_FAILURE);

  XrSpaceQueryResultsFB results{XR_TYPE_SPACE_QUERY_RESULTS_FB};
  EXPECT_EQ(q.retrieve(q.session, 12345, &results), XR_ERROR_VALIDATION_FAILURE);  // unknown request
  const XrAsyncRequestIdFB all = q.start_query(nullptr);
  SIM_CHECK(q.retrieve(q.session, all, &results));
  std::vector<XrSpaceQueryResultFB> some(results.resultCountOutput - 1);
  results.resultCapacityInput = static_cast<uint32_t>(some.size());
  results.results = some.data();
  EXPECT_EQ(q.retrieve(q.session, all, &results), XR_ERROR_SIZE_INSUFFICIENT);
  results.results = nullptr;
  EXPECT_EQ(q.retrieve(q.session, all, &results), XR_ERROR_VALIDATION_FAILURE);
  results.type = XR_TYPE_SPACE_QUERY_INFO_FB;
  EXPECT_EQ(q.retrieve(q.session, all, &results), XR_ERROR_VALIDATION_FAILURE);

  // A reference space is no spatial entity.
  XrUuidEXT uuid{};
  EXPECT_EQ(q.uuid(q.local, &uuid), XR_ERROR_VALIDATION_FAILURE);
  uint32_t count = 7;
  SIM_CHECK(q.components(q.local, 0, &count, nullptr));
  EXPECT_EQ(count, 0u);
  XrSpaceComponentStatusFB status{XR_TYPE_SPACE_COMPONENT_STATUS_FB};
  EXPECT_EQ(q.getStatus(q.local, XR_SPACE_COMPONENT_TYPE_LOCATABLE_FB, &status), XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB);
  EXPECT_EQ(q.uuid(XR_NULL_HANDLE, &uuid), XR_ERROR_HANDLE_INVALID);

  const XrSpace mesh_space = q.find_component(XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META).at(0).space;
  XrRect2Df box{};
  EXPECT_EQ(q.box2d(q.session, mesh_space, &box), XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB);
  XrSpaceComponentStatusSetInfoFB set{XR_TYPE_SPACE_COMPONENT_STATUS_SET_INFO_FB};
  set.componentType = XR_SPACE_COMPONENT_TYPE_LOCATABLE_FB;
  set.enabled = XR_TRUE;
  EXPECT_EQ(q.setStatus(mesh_space, &set, &request), XR_ERROR_SPACE_COMPONENT_STATUS_ALREADY_SET_FB);
  set.componentType = XR_SPACE_COMPONENT_TYPE_ROOM_LAYOUT_FB;
  EXPECT_EQ(q.setStatus(mesh_space, &set, &request), XR_ERROR_SPACE_COMPONENT_NOT_SUPPORTED_FB);
  set.componentType = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
  SIM_CHECK(q.setStatus(mesh_space, &set, &request));

  XrSpaceTriangleMeshGetInfoMETA get{XR_TYPE_SPACE_TRIANGLE_MESH_GET_INFO_META};
  XrSpaceTriangleMeshMETA mesh{XR_TYPE_SPACE_TRIANGLE_MESH_META};
  SIM_CHECK(q.mesh(mesh_space, &get, &mesh));
  std::vector<XrVector3f> vertices(mesh.vertexCountOutput - 1);
  mesh.vertexCapacityInput = static_cast<uint32_t>(vertices.size());
  mesh.vertices = vertices.data();
  EXPECT_EQ(q.mesh(mesh_space, &get, &mesh), XR_ERROR_SIZE_INSUFFICIENT);
  mesh.vertices = nullptr;
  EXPECT_EQ(q.mesh(mesh_space, &get, &mesh), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(q.mesh(mesh_space, nullptr, &mesh), XR_ERROR_VALIDATION_FAILURE);
  XrSemanticLabelsFB labels{XR_TYPE_SEMANTIC_LABELS_FB};
  labels.bufferCapacityInput = 4;  // "GLOBAL_MESH" does not fit
  char small[4];
  labels.buffer = small;
  EXPECT_EQ(q.labels(q.session, mesh_space, &labels), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(labels.bufferCountOutput, 12u);
}

TEST(MetaSpatialEntityMesh, NewAnchorsAreLocatedWhereTheyWereMade) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Quest q;
  q.events();
  XrSpatialAnchorCreateInfoFB info{XR_TYPE_SPATIAL_ANCHOR_CREATE_INFO_FB};
  info.space = q.local;
  info.poseInSpace = {{0, 0.38268343f, 0, 0.92387953f}, {1.0f, 0.5f, -2.0f}};
  info.time = 1;
  XrAsyncRequestIdFB request = 0;
  SIM_CHECK(q.createAnchor(q.session, &info, &request));
  const auto events = q.events();
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].type, XR_TYPE_EVENT_DATA_SPATIAL_ANCHOR_CREATE_COMPLETE_FB);
  const auto& done = reinterpret_cast<const XrEventDataSpatialAnchorCreateCompleteFB&>(events[0]);
  EXPECT_EQ(done.requestId, request);
  EXPECT_EQ(done.result, XR_SUCCESS);
  const XrPosef pose = q.locate(done.space);
  EXPECT_NEAR(pose.position.x, 1.0f, 1e-5);
  EXPECT_NEAR(pose.position.z, -2.0f, 1e-5);
  EXPECT_NEAR(pose.orientation.y, 0.38268343f, 1e-5);
  info.poseInSpace.orientation.w = 0;
  EXPECT_EQ(q.createAnchor(q.session, &info, &request), XR_ERROR_POSE_INVALID);
}

TEST(MetaSpatialEntityMesh, ASessionsAnchorsAndEventsGoWithIt) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Quest q;
  const XrAsyncRequestIdFB request = q.start_query(nullptr);
  const XrSession old = q.session;
  SIM_CHECK(xrDestroySession(q.session));
  for (const XrEventDataBuffer& e : q.events())
    EXPECT_EQ(e.type, XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) << "an event of the destroyed session's query";
  q.start_session();
  XrSpaceQueryResultsFB results{XR_TYPE_SPACE_QUERY_RESULTS_FB};
  EXPECT_NE(q.retrieve(q.session, request, &results), XR_SUCCESS);
  EXPECT_EQ(q.retrieve(old, request, &results), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(q.find_component(XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META).size(), 1u);
}

TEST(MetaSpatialEntityMesh, PlayingAQuestHidesTheOtherSceneExtensions) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(kQuestExtensions));
  uint32_t count = 0;
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr));
  std::vector<XrExtensionProperties> props(count, XrExtensionProperties{XR_TYPE_EXTENSION_PROPERTIES});
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()));
  std::vector<std::string> names;
  for (const auto& p : props) names.emplace_back(p.extensionName);
  auto has = [&](const char* n) { return std::find(names.begin(), names.end(), n) != names.end(); };
  for (const char* quest : {XR_FB_SPATIAL_ENTITY_EXTENSION_NAME, XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME, XR_FB_SCENE_EXTENSION_NAME,
                            XR_FB_SPATIAL_ENTITY_CONTAINER_EXTENSION_NAME, XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME})
    EXPECT_TRUE(has(quest)) << quest;
  EXPECT_FALSE(has(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(simtest::create_instance(&instance, {XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME}),
            XR_ERROR_EXTENSION_NOT_PRESENT);
  // And a Quest app runs as before.
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Quest q;
  EXPECT_EQ(q.find_component(XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META).size(), 1u);
}

}  // namespace
