// Passive capture through XR_META_spatial_entity_mesh (Quest) and XR_EXT_spatial_plane_tracking (OpenXR 1.1
// planes): an application that enables only the headset's scene extensions (not XR_EXTX_room_understanding)
// reads the room itself; with ROOMSENSE_EXPORT_DIR the layer analyses what it read and exports the result, and
// the application receives exactly what the runtime sends without the layer.
#include "compare.h"
#include "passive_capture.h"

#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"
#include "roomsense/xr/ext/XR_FB_scene.h"
#include "roomsense/xr/ext/XR_FB_spatial_entity.h"
#include "roomsense/xr/ext/XR_META_spatial_entity_mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace layertest;

const std::string kQuest = "XR_FB_spatial_entity,XR_FB_spatial_entity_query,XR_FB_scene,XR_FB_spatial_entity_container,"
                           "XR_META_spatial_entity_mesh";
const std::string kPlanesOnly = "XR_EXT_spatial_entity,XR_EXT_spatial_plane_tracking";

// ---- a Quest application: the global mesh's space through a space query, its mesh component enabled, the
// mesh read with the two-call idiom

Received read_quest(App& app) {
  const auto query = proc<PFN_xrQuerySpacesFB>(app.instance, "xrQuerySpacesFB");
  const auto retrieve = proc<PFN_xrRetrieveSpaceQueryResultsFB>(app.instance, "xrRetrieveSpaceQueryResultsFB");
  const auto set_status = proc<PFN_xrSetSpaceComponentStatusFB>(app.instance, "xrSetSpaceComponentStatusFB");
  const auto get_status = proc<PFN_xrGetSpaceComponentStatusFB>(app.instance, "xrGetSpaceComponentStatusFB");
  const auto get_mesh = proc<PFN_xrGetSpaceTriangleMeshMETA>(app.instance, "xrGetSpaceTriangleMeshMETA");

  XrSpaceComponentFilterInfoFB filter{XR_TYPE_SPACE_COMPONENT_FILTER_INFO_FB, nullptr};
  filter.componentType = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
  XrSpaceQueryInfoFB info{XR_TYPE_SPACE_QUERY_INFO_FB, nullptr};
  info.queryAction = XR_SPACE_QUERY_ACTION_LOAD_FB;
  info.maxResultCount = 16;
  info.filter = reinterpret_cast<const XrSpaceFilterInfoBaseHeaderFB*>(&filter);
  XrAsyncRequestIdFB request = 0;
  LT_CHECK(query(app.session, reinterpret_cast<const XrSpaceQueryInfoBaseHeaderFB*>(&info), &request));
  XrSpaceQueryResultsFB results{XR_TYPE_SPACE_QUERY_RESULTS_FB, nullptr};
  for (int i = 0;; ++i) {  // validation failure until the request is complete
    const XrResult r = retrieve(app.session, request, &results);
    if (r != XR_ERROR_VALIDATION_FAILURE || i > 5000) {
      LT_CHECK(r);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::vector<XrSpaceQueryResultFB> found(results.resultCountOutput);
  results.resultCapacityInput = static_cast<uint32_t>(found.size());
  results.results = found.data();
  if (!found.empty()) LT_CHECK(retrieve(app.session, request, &results));

  Received r;
  for (const XrSpaceQueryResultFB& f : found) {
    XrSpaceComponentStatusSetInfoFB set{XR_TYPE_SPACE_COMPONENT_STATUS_SET_INFO_FB, nullptr};
    set.componentType = XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META;
    set.enabled = XR_TRUE;
    XrAsyncRequestIdFB set_request = 0;
    const XrResult s = set_status(f.space, &set, &set_request);
    if (s != XR_ERROR_SPACE_COMPONENT_STATUS_ALREADY_SET_FB) LT_CHECK(s);
    XrSpaceComponentStatusFB status{XR_TYPE_SPACE_COMPONENT_STATUS_FB, nullptr};
    for (int i = 0; i < 5000; ++i) {
      LT_CHECK(get_status(f.space, XR_SPACE_COMPONENT_TYPE_TRIANGLE_MESH_META, &status));
      if (!status.changePending) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_TRUE(status.enabled);

    const XrSpaceTriangleMeshGetInfoMETA get{XR_TYPE_SPACE_TRIANGLE_MESH_GET_INFO_META, nullptr};
    XrSpaceTriangleMeshMETA mesh{XR_TYPE_SPACE_TRIANGLE_MESH_META, nullptr};
    LT_CHECK(get_mesh(f.space, &get, &mesh));
    std::vector<XrVector3f> vertices(mesh.vertexCountOutput);
    std::vector<uint32_t> indices(mesh.indexCountOutput);
    mesh.vertexCapacityInput = static_cast<uint32_t>(vertices.size());
    mesh.vertices = vertices.data();
    mesh.indexCapacityInput = static_cast<uint32_t>(indices.size());
    mesh.indices = indices.data();
    LT_CHECK(get_mesh(f.space, &get, &mesh));
    ++r.meshes;
    r.vertices += mesh.vertexCountOutput;
    r.indices += mesh.indexCountOutput;
    r.add(vertices);
    r.add(indices);
  }
  return r;
}

// ---- an OpenXR 1.1 application: a plane tracking context, a discovery snapshot in its LOCAL space, every
// plane's 2D mesh (and polygon) read, the snapshot destroyed

void wait_future(App& app, XrFutureEXT future) {
  const auto poll = proc<PFN_xrPollFutureEXT>(app.instance, "xrPollFutureEXT");
  XrFuturePollInfoEXT info{XR_TYPE_FUTURE_POLL_INFO_EXT, nullptr, future};
  XrFuturePollResultEXT state{XR_TYPE_FUTURE_POLL_RESULT_EXT, nullptr, XR_FUTURE_STATE_PENDING_EXT};
  for (int i = 0; i < 10000 && state.state != XR_FUTURE_STATE_READY_EXT; ++i) {
    LT_CHECK(poll(app.instance, &info, &state));
    if (state.state != XR_FUTURE_STATE_READY_EXT) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(state.state, XR_FUTURE_STATE_READY_EXT);
}

template <typename T, typename Get>
std::vector<T> read_buffer(Get get, XrSpatialSnapshotEXT snapshot, XrSpatialBufferIdEXT id) {
  const XrSpatialBufferGetInfoEXT info{XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT, nullptr, id};
  uint32_t count = 0;
  LT_CHECK(get(snapshot, &info, 0, &count, nullptr));
  std::vector<T> out(count);
  if (count > 0) LT_CHECK(get(snapshot, &info, count, &count, out.data()));
  return out;
}

Received read_planes(App& app) {
  const auto create = proc<PFN_xrCreateSpatialContextAsyncEXT>(app.instance, "xrCreateSpatialContextAsyncEXT");
  const auto complete = proc<PFN_xrCreateSpatialContextCompleteEXT>(app.instance, "xrCreateSpatialContextCompleteEXT");
  const auto destroy_context = proc<PFN_xrDestroySpatialContextEXT>(app.instance, "xrDestroySpatialContextEXT");
  const auto discover = proc<PFN_xrCreateSpatialDiscoverySnapshotAsyncEXT>(app.instance, "xrCreateSpatialDiscoverySnapshotAsyncEXT");
  const auto discovered =
      proc<PFN_xrCreateSpatialDiscoverySnapshotCompleteEXT>(app.instance, "xrCreateSpatialDiscoverySnapshotCompleteEXT");
  const auto query = proc<PFN_xrQuerySpatialComponentDataEXT>(app.instance, "xrQuerySpatialComponentDataEXT");
  const auto destroy_snapshot = proc<PFN_xrDestroySpatialSnapshotEXT>(app.instance, "xrDestroySpatialSnapshotEXT");
  const auto vector2f = proc<PFN_xrGetSpatialBufferVector2fEXT>(app.instance, "xrGetSpatialBufferVector2fEXT");
  const auto uint16 = proc<PFN_xrGetSpatialBufferUint16EXT>(app.instance, "xrGetSpatialBufferUint16EXT");
  const auto uint32 = proc<PFN_xrGetSpatialBufferUint32EXT>(app.instance, "xrGetSpatialBufferUint32EXT");

  std::vector<XrSpatialComponentTypeEXT> components = {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT,
                                                       XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT,
                                                       XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT};
  XrSpatialCapabilityConfigurationPlaneTrackingEXT config{XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT, nullptr,
                                                          XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT,
                                                          static_cast<uint32_t>(components.size()), components.data()};
  const auto* header = reinterpret_cast<const XrSpatialCapabilityConfigurationBaseHeaderEXT*>(&config);
  XrSpatialContextCreateInfoEXT info{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT, nullptr, 1, &header};
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  LT_CHECK(create(app.session, &info, &future));
  wait_future(app, future);
  XrCreateSpatialContextCompletionEXT context{XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT, nullptr};
  LT_CHECK(complete(app.session, future, &context));
  LT_CHECK(context.futureResult);

  XrSpatialDiscoverySnapshotCreateInfoEXT discover_info{XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT, nullptr};
  discover_info.componentTypeCount = static_cast<uint32_t>(components.size());
  discover_info.componentTypes = components.data();
  LT_CHECK(discover(context.spatialContext, &discover_info, &future));
  wait_future(app, future);
  XrCreateSpatialDiscoverySnapshotCompletionInfoEXT completion_info{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT,
                                                                    nullptr};
  completion_info.baseSpace = app.local;
  completion_info.time = now();
  completion_info.future = future;
  XrCreateSpatialDiscoverySnapshotCompletionEXT snapshot{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT, nullptr};
  LT_CHECK(discovered(context.spatialContext, &completion_info, &snapshot));
  LT_CHECK(snapshot.futureResult);

  XrSpatialComponentDataQueryConditionEXT condition{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT, nullptr};
  condition.componentTypeCount = static_cast<uint32_t>(components.size());
  condition.componentTypes = components.data();
  XrSpatialComponentDataQueryResultEXT result{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT, nullptr};
  LT_CHECK(query(snapshot.snapshot, &condition, &result));
  const uint32_t n = result.entityIdCountOutput;
  std::vector<XrSpatialEntityIdEXT> ids(n);
  std::vector<XrSpatialEntityTrackingStateEXT> states(n);
  std::vector<XrSpatialBounded2DDataEXT> bounds(n);
  std::vector<XrSpatialPolygon2DDataEXT> polygons(n);
  std::vector<XrSpatialMeshDataEXT> meshes(n);
  std::vector<XrSpatialPlaneSemanticLabelEXT> labels(n);
  XrSpatialComponentPlaneSemanticLabelListEXT label_list{XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT, nullptr, n, labels.data()};
  XrSpatialComponentMesh2DListEXT mesh_list{XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT, &label_list, n, meshes.data()};
  XrSpatialComponentPolygon2DListEXT polygon_list{XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT, &mesh_list, n, polygons.data()};
  XrSpatialComponentBounded2DListEXT bound_list{XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT, &polygon_list, n, bounds.data()};
  result.next = &bound_list;
  result.entityIdCapacityInput = n;
  result.entityIds = ids.data();
  result.entityStateCapacityInput = n;
  result.entityStates = states.data();
  if (n > 0) LT_CHECK(query(snapshot.snapshot, &condition, &result));

  Received r;
  r.add(ids);
  r.add(labels);
  for (uint32_t i = 0; i < n; ++i) {
    // The polygon first, then the mesh (which the layer prefers): both paths of the capture.
    const auto outline = read_buffer<XrVector2f>(vector2f, snapshot.snapshot, polygons[i].vertexBuffer.bufferId);
    const auto points = read_buffer<XrVector2f>(vector2f, snapshot.snapshot, meshes[i].vertexBuffer.bufferId);
    std::vector<uint32_t> indices;
    if (meshes[i].indexBuffer.bufferType == XR_SPATIAL_BUFFER_TYPE_UINT16_EXT) {
      const auto small = read_buffer<uint16_t>(uint16, snapshot.snapshot, meshes[i].indexBuffer.bufferId);
      indices.assign(small.begin(), small.end());
    } else {
      indices = read_buffer<uint32_t>(uint32, snapshot.snapshot, meshes[i].indexBuffer.bufferId);
    }
    ++r.meshes;
    r.vertices += points.size();
    r.indices += indices.size();
    r.add(&meshes[i].origin, sizeof(XrPosef));
    r.add(outline);
    r.add(points);
    r.add(indices);
  }
  LT_CHECK(destroy_snapshot(snapshot.snapshot));  // the layer analyses what was read
  LT_CHECK(destroy_context(context.spatialContext));
  return r;
}

struct QuestPassiveHeadset {
  std::string sim_extensions;
  std::vector<const char*> app_extensions;
  Received (*read)(App&);
};

const QuestPassiveHeadset kQuestHeadset{kQuest,
                                        {XR_MND_HEADLESS_EXTENSION_NAME, XR_FB_SPATIAL_ENTITY_EXTENSION_NAME, XR_FB_SPATIAL_ENTITY_QUERY_EXTENSION_NAME,
                                         XR_FB_SCENE_EXTENSION_NAME, XR_META_SPATIAL_ENTITY_MESH_EXTENSION_NAME},
                                        &read_quest};
const QuestPassiveHeadset kPlanesHeadset{kPlanesOnly,
                                         {XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME, XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME,
                                          XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME},
                                         &read_planes};

// The application without the layer, as the runtime serves it.
Received read_without_layer(const QuestPassiveHeadset& headset) {
  ScopedEnv disable("DISABLE_XR_APILAYER_ROOMSENSE", std::string("1"));
  App app(headset.app_extensions);
  return headset.read(app);
}

// Reads with the layer in export-only mode; returns the exported analysis.
nlohmann::json export_of_what_the_app_read(const QuestPassiveHeadset& headset, const std::string& name) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", headset.sim_extensions);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  const Received want = read_without_layer(headset);
  EXPECT_GT(want.meshes, 0u);

  const auto dir = temp_dir(name);
  ScopedEnv export_dir("ROOMSENSE_EXPORT_DIR", dir.string());
  Received got;
  {
    App app(headset.app_extensions);
    EXPECT_TRUE(layer_library_loaded());
    got = headset.read(app);
    app.close_session();  // waits for the export-only analysis
  }
  EXPECT_EQ(got, want) << "the application must receive what the runtime sends";
  std::printf("[ figures  ] %s: the application read %zu meshes (%zu vertices, %zu indices)\n", name.c_str(), got.meshes,
              got.vertices, got.indices);
  std::ifstream in(dir / "analysis.json");
  EXPECT_TRUE(in.good()) << "no analysis.json in " << dir;
  if (!in.good()) return {};
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_TRUE(std::filesystem::exists(dir / "bounds.obj"));
  EXPECT_GT(doc.at("openxr").at("app_read_meshes").get<std::size_t>(), 0u);
  EXPECT_EQ(doc.at("openxr").at("runtime_meshes").get<int>(), 0);
  std::filesystem::remove_all(dir);
  return doc;
}

TEST(LayerPassiveMetaExt, QuestApplicationReadingTheGlobalMeshIsExported) {
  const nlohmann::json doc = export_of_what_the_app_read(kQuestHeadset, "layer_passive_meta");
  ASSERT_FALSE(doc.is_null());
  const nlohmann::json cli = run_cli("synthetic:default");
  ASSERT_TRUE(doc.at("floor_y").is_number()) << doc.dump();
  EXPECT_NEAR(doc.at("floor_y").get<double>(), cli.at("floor_y").get<double>(), 1e-4);
  EXPECT_NEAR(doc.at("ceiling_y").get<double>(), cli.at("ceiling_y").get<double>(), 1e-4);
  EXPECT_EQ(doc.at("areas").size(), cli.at("areas").size());
  // The whole room: the global mesh is the scene itself.
  JsonDiff d;
  for (const char* member : kRoomMembers) {
    nlohmann::json g = room_member(doc, member), w = room_member(cli, member);
    diff_json(g, w, member, d);
  }
  for (const std::string& m : d.mismatches) ADD_FAILURE() << m;
  EXPECT_LE(d.max_number_difference, 1e-4);
}

TEST(LayerPassiveMetaExt, PlanesApplicationReadingItsSnapshotIsExported) {
  const nlohmann::json doc = export_of_what_the_app_read(kPlanesHeadset, "layer_passive_ext");
  ASSERT_FALSE(doc.is_null());
  const nlohmann::json cli = run_cli("synthetic:default");
  ASSERT_TRUE(doc.at("floor_y").is_number()) << doc.dump();
  ASSERT_TRUE(doc.at("ceiling_y").is_number()) << doc.dump();
  std::printf("[ figures  ] planes read by the application: floor_y %.6f ceiling_y %.6f (CLI %.6f %.6f)\n",
              doc.at("floor_y").get<double>(), doc.at("ceiling_y").get<double>(), cli.at("floor_y").get<double>(),
              cli.at("ceiling_y").get<double>());
  EXPECT_NEAR(doc.at("floor_y").get<double>(), cli.at("floor_y").get<double>(), 1e-4);
  EXPECT_NEAR(doc.at("ceiling_y").get<double>(), cli.at("ceiling_y").get<double>(), 1e-4);
}

}  // namespace
