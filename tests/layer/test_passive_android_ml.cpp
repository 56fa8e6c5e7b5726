// Passive capture through XR_ANDROID_scene_meshing and XR_ML_world_mesh_detection: an application that enables
// only the headset's scene extension (not XR_EXTX_room_understanding) reads the whole room itself; with
// ROOMSENSE_EXPORT_DIR the layer analyses what it read and exports the CLI's room, and the application receives
// exactly what the runtime sends without the layer.
#include "compare.h"
#include "passive_capture.h"

#include "roomsense/xr/ext/XR_ANDROID_scene_meshing.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_ML_world_mesh_detection.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace layertest;

// ---- an Android XR application: a tracker with labels, one snapshot, every submesh read in full

Received read_android(App& app, XrSpace base) {
  const auto createTracker = proc<PFN_xrCreateSceneMeshingTrackerANDROID>(app.instance, "xrCreateSceneMeshingTrackerANDROID");
  const auto destroyTracker = proc<PFN_xrDestroySceneMeshingTrackerANDROID>(app.instance, "xrDestroySceneMeshingTrackerANDROID");
  const auto createSnapshot = proc<PFN_xrCreateSceneMeshSnapshotANDROID>(app.instance, "xrCreateSceneMeshSnapshotANDROID");
  const auto destroySnapshot = proc<PFN_xrDestroySceneMeshSnapshotANDROID>(app.instance, "xrDestroySceneMeshSnapshotANDROID");
  const auto states = proc<PFN_xrGetAllSubmeshStatesANDROID>(app.instance, "xrGetAllSubmeshStatesANDROID");
  const auto data = proc<PFN_xrGetSubmeshDataANDROID>(app.instance, "xrGetSubmeshDataANDROID");

  XrSceneMeshingTrackerCreateInfoANDROID tracker_info{XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID};
  tracker_info.semanticLabelSet = XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID;
  XrSceneMeshingTrackerANDROID tracker = XR_NULL_HANDLE;
  LT_CHECK(createTracker(app.session, &tracker_info, &tracker));
  XrSceneMeshSnapshotCreateInfoANDROID info{XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID};
  info.baseSpace = base;
  info.time = now();
  info.boundingBox.center.orientation.w = 1;
  info.boundingBox.extents = {1000.0f, 1000.0f, 1000.0f};
  XrSceneMeshSnapshotCreationResultANDROID created{XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID};
  LT_CHECK(createSnapshot(tracker, &info, &created));
  const XrSceneMeshSnapshotANDROID snapshot = created.snapshot;

  uint32_t count = 0;
  LT_CHECK(states(snapshot, 0, &count, nullptr));
  std::vector<XrSceneSubmeshStateANDROID> all(count, XrSceneSubmeshStateANDROID{XR_TYPE_SCENE_SUBMESH_STATE_ANDROID});
  if (count > 0) LT_CHECK(states(snapshot, count, &count, all.data()));
  Received r;
  for (const XrSceneSubmeshStateANDROID& state : all) {
    XrSceneSubmeshDataANDROID d{XR_TYPE_SCENE_SUBMESH_DATA_ANDROID};
    d.submeshId = state.submeshId;
    LT_CHECK(data(snapshot, 1, &d));  // counts
    std::vector<XrVector3f> vertices(d.vertexCountOutput);
    std::vector<uint8_t> labels(d.vertexCountOutput);
    std::vector<uint32_t> indices(d.indexCountOutput);
    d.vertexCapacityInput = d.vertexCountOutput;
    d.vertexPositions = vertices.data();
    d.vertexSemantics = labels.data();
    d.indexCapacityInput = d.indexCountOutput;
    d.indices = indices.data();
    LT_CHECK(data(snapshot, 1, &d));
    ++r.meshes;
    r.vertices += vertices.size();
    r.indices += indices.size();
    r.labels += labels.size();
    r.add(&state.submeshId, sizeof state.submeshId);
    r.add(&state.submeshPoseInBaseSpace, sizeof state.submeshPoseInBaseSpace);
    r.add(vertices);
    r.add(labels);
    r.add(indices);
  }
  LT_CHECK(destroySnapshot(snapshot));  // done reading: the layer analyses what was read
  LT_CHECK(destroyTracker(tracker));
  return r;
}

// ---- a Magic Leap application: a detector, the block states through a future, every block's mesh through another

void wait(App& app, PFN_xrPollFutureEXT poll, XrFutureEXT future) {
  for (int i = 0; i < 5000; ++i) {
    XrFuturePollInfoEXT info{XR_TYPE_FUTURE_POLL_INFO_EXT};
    info.future = future;
    XrFuturePollResultEXT result{XR_TYPE_FUTURE_POLL_RESULT_EXT};
    LT_CHECK(poll(app.instance, &info, &result));
    if (result.state == XR_FUTURE_STATE_READY_EXT) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  throw std::runtime_error("future never ready");
}

Received read_ml(App& app, XrSpace base) {
  const auto poll = proc<PFN_xrPollFutureEXT>(app.instance, "xrPollFutureEXT");
  const auto createDetector = proc<PFN_xrCreateWorldMeshDetectorML>(app.instance, "xrCreateWorldMeshDetectorML");
  const auto destroyDetector = proc<PFN_xrDestroyWorldMeshDetectorML>(app.instance, "xrDestroyWorldMeshDetectorML");
  const auto stateAsync = proc<PFN_xrRequestWorldMeshStateAsyncML>(app.instance, "xrRequestWorldMeshStateAsyncML");
  const auto stateComplete = proc<PFN_xrRequestWorldMeshStateCompleteML>(app.instance, "xrRequestWorldMeshStateCompleteML");
  const auto recommendSize = proc<PFN_xrGetWorldMeshBufferRecommendSizeML>(app.instance, "xrGetWorldMeshBufferRecommendSizeML");
  const auto allocate = proc<PFN_xrAllocateWorldMeshBufferML>(app.instance, "xrAllocateWorldMeshBufferML");
  const auto free = proc<PFN_xrFreeWorldMeshBufferML>(app.instance, "xrFreeWorldMeshBufferML");
  const auto meshAsync = proc<PFN_xrRequestWorldMeshAsyncML>(app.instance, "xrRequestWorldMeshAsyncML");
  const auto meshComplete = proc<PFN_xrRequestWorldMeshCompleteML>(app.instance, "xrRequestWorldMeshCompleteML");

  XrWorldMeshDetectorCreateInfoML create{XR_TYPE_WORLD_MESH_DETECTOR_CREATE_INFO_ML};
  XrWorldMeshDetectorML detector = XR_NULL_HANDLE;
  LT_CHECK(createDetector(app.session, &create, &detector));

  XrWorldMeshStateRequestInfoML request{XR_TYPE_WORLD_MESH_STATE_REQUEST_INFO_ML};
  request.baseSpace = base;
  request.time = now();
  request.boundingBoxCenter.orientation.w = 1;
  request.boundingBoxExtents = {1000.0f, 1000.0f, 1000.0f};
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  LT_CHECK(stateAsync(detector, &request, &future));
  wait(app, poll, future);
  XrWorldMeshStateRequestCompletionML completion{XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML};
  LT_CHECK(stateComplete(detector, future, &completion));  // counts
  LT_CHECK(completion.futureResult);
  XrWorldMeshBlockStateML proto{};
  proto.type = XR_TYPE_WORLD_MESH_BLOCK_STATE_ML;
  std::vector<XrWorldMeshBlockStateML> states(completion.meshBlockStateCountOutput, proto);
  completion.meshBlockStateCapacityInput = static_cast<uint32_t>(states.size());
  completion.meshBlockStates = states.data();
  LT_CHECK(stateComplete(detector, future, &completion));

  XrWorldMeshBufferRecommendedSizeInfoML size_info{XR_TYPE_WORLD_MESH_BUFFER_RECOMMENDED_SIZE_INFO_ML};
  size_info.maxBlockCount = static_cast<uint32_t>(states.size());
  XrWorldMeshBufferSizeML size{XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML};
  LT_CHECK(recommendSize(detector, &size_info, &size));
  XrWorldMeshBufferML buffer{XR_TYPE_WORLD_MESH_BUFFER_ML};
  LT_CHECK(allocate(detector, &size, &buffer));
  std::vector<XrWorldMeshBlockRequestML> requests;
  for (const auto& state : states) {
    XrWorldMeshBlockRequestML b{XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML};
    b.uuid = state.uuid;
    b.lod = XR_WORLD_MESH_DETECTOR_LOD_MAXIMUM_ML;
    requests.push_back(b);
  }
  XrWorldMeshGetInfoML get{XR_TYPE_WORLD_MESH_GET_INFO_ML};
  get.blockCount = static_cast<uint32_t>(requests.size());
  get.blocks = requests.data();
  LT_CHECK(meshAsync(detector, &get, &buffer, &future));
  wait(app, poll, future);
  XrWorldMeshRequestCompletionInfoML info{XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_INFO_ML};
  info.meshSpace = base;
  info.meshSpaceLocateTime = request.time;
  XrWorldMeshBlockML block_proto{};
  block_proto.type = XR_TYPE_WORLD_MESH_BLOCK_ML;
  std::vector<XrWorldMeshBlockML> blocks(requests.size(), block_proto);
  XrWorldMeshRequestCompletionML done{XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_ML};
  done.blockCount = static_cast<uint32_t>(blocks.size());
  done.blocks = blocks.data();
  LT_CHECK(meshComplete(detector, &info, future, &done));  // the layer analyses what was read
  LT_CHECK(done.futureResult);
  Received r;
  for (std::size_t i = 0; i < std::min<std::size_t>(done.blockCount, blocks.size()); ++i) {
    const XrWorldMeshBlockML& b = blocks[i];
    EXPECT_EQ(b.blockResult, XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML);
    ++r.meshes;
    r.vertices += b.vertexCount;
    r.indices += b.indexCount;
    r.add(&b.uuid, sizeof b.uuid);
    r.add(&states[i].meshBoundingBoxCenter, sizeof(XrPosef));
    r.add(b.vertexBuffer, b.vertexCount * sizeof(XrVector3f));
    r.add(b.indexBuffer, b.indexCount * sizeof(uint16_t));
  }
  LT_CHECK(free(detector, &buffer));
  LT_CHECK(destroyDetector(detector));
  return r;
}

struct PassiveHeadset {
  const char* extension;
  std::vector<const char*> app_extensions;
  Received (*read)(App&, XrSpace);
  bool labels = false;  // the runtime labels its meshes: the layer's areas differ from the CLI's (compare.h)
};

const PassiveHeadset kAndroid{XR_ANDROID_SCENE_MESHING_EXTENSION_NAME,
                              {XR_MND_HEADLESS_EXTENSION_NAME, XR_ANDROID_SCENE_MESHING_EXTENSION_NAME},
                              &read_android, true};
const PassiveHeadset kMagicLeap{XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME,
                                {XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME, XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME},
                                &read_ml};

// The application's base space: LOCAL, or a LOCAL space moved by `pose` (the layer then places what it read
// through the base space's location in its own capture space).
XrSpace base_space(const App& app, const XrPosef* pose) {
  return pose == nullptr ? app.local : app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL, *pose);
}

// The application without the layer, as the runtime serves it.
Received read_without_layer(const PassiveHeadset& headset, const XrPosef* pose) {
  ScopedEnv disable("DISABLE_XR_APILAYER_ROOMSENSE", std::string("1"));
  App app(headset.app_extensions);
  return headset.read(app, base_space(app, pose));
}

void expect_export_of_what_the_app_read(const PassiveHeadset& headset, const std::string& name, const XrPosef* pose = nullptr) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(headset.extension));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  const Received want = read_without_layer(headset, pose);
  ASSERT_GT(want.meshes, 0u);

  const auto dir = temp_dir(name);
  ScopedEnv export_dir("ROOMSENSE_EXPORT_DIR", dir.string());
  Received got;
  {
    App app(headset.app_extensions);
    ASSERT_TRUE(layer_library_loaded());
    got = headset.read(app, base_space(app, pose));
    app.close_session();  // waits for the export-only analysis
  }
  EXPECT_EQ(got, want) << "the application must receive what the runtime sends";
  std::ifstream in(dir / "analysis.json");
  ASSERT_TRUE(in.good()) << "no analysis.json in " << dir;
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_TRUE(std::filesystem::exists(dir / "bounds.obj"));
  const std::size_t captured = doc.at("openxr").at("app_read_meshes").get<std::size_t>();
  EXPECT_GT(captured, 0u);
  EXPECT_LE(captured, got.meshes);
  std::printf("[ figures  ] %s: the application read %zu meshes (%zu vertices, %zu indices); the layer analysed %zu\n",
              headset.extension, got.meshes, got.vertices, got.indices, captured);
  EXPECT_EQ(doc.at("openxr").at("runtime_meshes").get<int>(), 0);
  const nlohmann::json cli = run_cli("synthetic:default");
  if (!headset.labels) {
    EXPECT_EQ(doc.at("areas").size(), cli.at("areas").size());
  }
  EXPECT_NEAR(doc.at("floor_y").get<double>(), cli.at("floor_y").get<double>(), 1e-4);
  EXPECT_NEAR(doc.at("ceiling_y").get<double>(), cli.at("ceiling_y").get<double>(), 1e-4);
  // The whole room, within the submeshes' (blocks') rounding.
  JsonDiff d;
  for (const char* member : kRoomMembers) {
    if (headset.labels && changed_by_labels(member)) continue;
    nlohmann::json g = room_member(doc, member), w = room_member(cli, member);
    diff_json(g, w, member, d);
  }
  for (const std::string& m : d.mismatches) ADD_FAILURE() << headset.extension << ": " << m;
  EXPECT_LE(d.max_number_difference, 1e-4) << headset.extension;
  std::filesystem::remove_all(dir);
}

TEST(LayerPassiveAndroidMl, ExportDirAnalysesWhatAnAndroidApplicationRead) {
  expect_export_of_what_the_app_read(kAndroid, "layer_passive_android");
}

TEST(LayerPassiveAndroidMl, ExportDirAnalysesWhatAMagicLeapApplicationRead) {
  expect_export_of_what_the_app_read(kMagicLeap, "layer_passive_ml");
}

// Submesh and block poses in a base space other than the layer's capture space (turned 90 degrees about +Y and
// raised 1 m): the room comes out the same.
const XrPosef kMovedBase{{0.0f, 0.70710678f, 0.0f, 0.70710678f}, {0.5f, 1.0f, -0.25f}};

TEST(LayerPassiveAndroidMl, AnAndroidApplicationsOwnBaseSpaceIsLocated) {
  expect_export_of_what_the_app_read(kAndroid, "layer_passive_android_moved", &kMovedBase);
}

TEST(LayerPassiveAndroidMl, AMagicLeapApplicationsOwnBaseSpaceIsLocated) {
  expect_export_of_what_the_app_read(kMagicLeap, "layer_passive_ml_moved", &kMovedBase);
}

// A Magic Leap application that also enables XR_EXT_spatial_entity, which this runtime lacks (the layer serves it):
// the layer answers xrPollFutureEXT for its own futures and passes the runtime's on, so the application still
// receives exactly what the runtime sends.
TEST(LayerPassiveAndroidMl, AMagicLeapApplicationsFuturesPassTheLayersSpatialEntities) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  const Received want = read_without_layer(kMagicLeap, nullptr);
  std::vector<const char*> extensions = kMagicLeap.app_extensions;
  extensions.push_back(XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME);
  App app(extensions);
  ASSERT_TRUE(layer_library_loaded());
  EXPECT_EQ(read_ml(app, app.local), want);
}

}  // namespace
