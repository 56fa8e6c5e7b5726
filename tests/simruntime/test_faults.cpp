// ROOMSENSE_SIM_FAULTS (README.md, "Faults"): each fault does what the grammar says, a bad value fails
// xrCreateInstance, and the next instance without the variable is a well-behaved runtime again.
#include "sim_env.h"
#include "xr_harness.h"

#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_ML_world_mesh_detection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace {

using simtest::App;
using simtest::proc;
using simtest::ScopedEnv;

XrResult create_with(const std::string& faults) {
  ScopedEnv f("ROOMSENSE_SIM_FAULTS", faults);
  XrInstance instance = XR_NULL_HANDLE;
  const XrResult r = simtest::create_instance(&instance, {XR_MND_HEADLESS_EXTENSION_NAME});
  if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
  return r;
}

TEST(SimFaults, TheGrammar) {
  EXPECT_EQ(create_with(""), XR_SUCCESS);
  EXPECT_EQ(create_with("error:xrGetSceneMeshBuffersMSFT=XR_ERROR_RUNTIME_FAILURE, pending, pending:XR_ML_world_mesh_detection,"
                        "mesh=nan,mesh:XR_ANDROID_scene_meshing=huge,lost,lost:xrLocateSpace=3,error:xrPollFutureEXT=XR_TIMEOUT_EXPIRED"),
            XR_SUCCESS);
  for (const char* bad : {"bogus", "error", "error:xrNoSuchFunction=XR_ERROR_RUNTIME_FAILURE", "error:xrGetSceneMeshBuffersMSFT",
                          "error:xrGetSceneMeshBuffersMSFT=XR_SUCCESS", "error:xrGetSceneMeshBuffersMSFT=NOT_A_RESULT",
                          "error:xrCreateInstance=XR_ERROR_RUNTIME_FAILURE", "pending:XR_FB_scene", "pending=1", "mesh",
                          "mesh=wobbly", "mesh:XR_NOPE=nan", "lost:xrPollEvent", "lost=0", "lost=x", "lost:=2", "pending,,mesh=nan",
                          "mesh=nan\x01"})
    EXPECT_EQ(create_with(bad), XR_ERROR_INITIALIZATION_FAILED) << bad;
  EXPECT_EQ(create_with(""), XR_SUCCESS);
}

TEST(SimFaults, AnErrorFromAnyCallAndOnlyThatOne) {
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("error:xrLocateSpace=XR_ERROR_TIME_INVALID,error:xrCreateSceneMSFT=XR_ERROR_OUT_OF_MEMORY"));
  App app;
  XrSpaceLocation where{XR_TYPE_SPACE_LOCATION};
  EXPECT_EQ(xrLocateSpace(app.local, app.local, app.now(), &where), XR_ERROR_TIME_INVALID);
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneObserverCreateInfoMSFT create{XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT};
  ASSERT_EQ(app.msft.createObserver(app.session, &create, &observer), XR_SUCCESS);
  EXPECT_THROW(simtest::compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT}), std::runtime_error);
  XrSceneCreateInfoMSFT scene_info{XR_TYPE_SCENE_CREATE_INFO_MSFT};
  XrSceneMSFT scene = XR_NULL_HANDLE;
  EXPECT_EQ(app.msft.createScene(observer, &scene_info, &scene), XR_ERROR_OUT_OF_MEMORY);
  EXPECT_EQ(app.msft.destroyObserver(observer), XR_SUCCESS);
}

TEST(SimFaults, APendingSceneComputeStaysUpdatingUntilTheObserverGoes) {
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("pending:XR_MSFT_scene_understanding"));
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneObserverCreateInfoMSFT create{XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT};
  ASSERT_EQ(app.msft.createObserver(app.session, &create, &observer), XR_SUCCESS);
  const XrSceneSphereBoundMSFT sphere{{0, 0, 0}, 100.0f};
  const std::vector<XrSceneComputeFeatureMSFT> features = {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT};
  const XrNewSceneComputeInfoMSFT info = simtest::compute_info(app, features, &sphere);
  ASSERT_EQ(app.msft.compute(observer, &info), XR_SUCCESS);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // 20 times the delay ctest sets
  XrSceneComputeStateMSFT state = XR_SCENE_COMPUTE_STATE_NONE_MSFT;
  ASSERT_EQ(app.msft.computeState(observer, &state), XR_SUCCESS);
  EXPECT_EQ(state, XR_SCENE_COMPUTE_STATE_UPDATING_MSFT);
  EXPECT_EQ(app.msft.destroyObserver(observer), XR_SUCCESS);  // returns: the worker is stopped
}

TEST(SimFaults, PendingFuturesStayPendingAndCanBeCancelled) {
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("pending:XR_ML_world_mesh_detection"));
  App app({XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME, XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME});
  const auto poll = proc<PFN_xrPollFutureEXT>(app.instance, "xrPollFutureEXT");
  const auto cancel = proc<PFN_xrCancelFutureEXT>(app.instance, "xrCancelFutureEXT");
  const auto create = proc<PFN_xrCreateWorldMeshDetectorML>(app.instance, "xrCreateWorldMeshDetectorML");
  const auto async = proc<PFN_xrRequestWorldMeshStateAsyncML>(app.instance, "xrRequestWorldMeshStateAsyncML");
  const auto complete = proc<PFN_xrRequestWorldMeshStateCompleteML>(app.instance, "xrRequestWorldMeshStateCompleteML");
  XrWorldMeshDetectorCreateInfoML detector_info{XR_TYPE_WORLD_MESH_DETECTOR_CREATE_INFO_ML};
  XrWorldMeshDetectorML detector = XR_NULL_HANDLE;
  ASSERT_EQ(create(app.session, &detector_info, &detector), XR_SUCCESS);
  XrWorldMeshStateRequestInfoML request{XR_TYPE_WORLD_MESH_STATE_REQUEST_INFO_ML};
  request.baseSpace = app.local;
  request.time = app.now();
  request.boundingBoxCenter.orientation.w = 1;
  request.boundingBoxExtents = {100.0f, 100.0f, 100.0f};
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  ASSERT_EQ(async(detector, &request, &future), XR_SUCCESS);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  XrFuturePollInfoEXT poll_info{XR_TYPE_FUTURE_POLL_INFO_EXT};
  poll_info.future = future;
  XrFuturePollResultEXT polled{XR_TYPE_FUTURE_POLL_RESULT_EXT};
  ASSERT_EQ(poll(app.instance, &poll_info, &polled), XR_SUCCESS);
  EXPECT_EQ(polled.state, XR_FUTURE_STATE_PENDING_EXT);
  XrWorldMeshStateRequestCompletionML completion{XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML};
  EXPECT_EQ(complete(detector, future, &completion), XR_ERROR_FUTURE_PENDING_EXT);
  XrFutureCancelInfoEXT cancel_info{XR_TYPE_FUTURE_CANCEL_INFO_EXT};
  cancel_info.future = future;
  EXPECT_EQ(cancel(app.instance, &cancel_info), XR_SUCCESS);
}

// One visual mesh component's buffers, read with ROOMSENSE_SIM_FAULTS=mesh...: the raw counts and arrays.
struct Served {
  uint32_t vertex_count = 0, index_count = 0;
  std::vector<XrVector3f> vertices;
  std::vector<uint32_t> indices;
};

struct MeshRead {
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneMSFT scene = XR_NULL_HANDLE;
  uint64_t buffer = 0;

  MeshRead() {
    XrSceneObserverCreateInfoMSFT create{XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT};
    SIM_CHECK(app.msft.createObserver(app.session, &create, &observer));
    scene = simtest::compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT});
    XrSceneComponentsGetInfoMSFT get{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT};
    get.componentType = XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT;
    XrSceneComponentsMSFT list{XR_TYPE_SCENE_COMPONENTS_MSFT};
    SIM_CHECK(app.msft.components(scene, &get, &list));
    std::vector<XrSceneComponentMSFT> components(list.componentCountOutput);
    std::vector<XrSceneMeshMSFT> meshes(components.size());
    XrSceneMeshesMSFT mesh_list{XR_TYPE_SCENE_MESHES_MSFT};
    mesh_list.sceneMeshCount = static_cast<uint32_t>(meshes.size());
    mesh_list.sceneMeshes = meshes.data();
    list.next = &mesh_list;
    list.componentCapacityInput = static_cast<uint32_t>(components.size());
    list.components = components.data();
    SIM_CHECK(app.msft.components(scene, &get, &list));
    buffer = meshes.at(0).meshBufferId;
  }
  ~MeshRead() {
    app.msft.destroyScene(scene);
    app.msft.destroyObserver(observer);
  }

  // The vertex count call, then the vertex and index arrays with `capacity` (0: the counts the runtime said).
  XrResult read(Served& out, std::optional<uint32_t> vertex_capacity = std::nullopt) {
    XrSceneMeshBuffersGetInfoMSFT info{XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT};
    info.meshBufferId = buffer;
    XrSceneMeshVertexBufferMSFT v{XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT};
    XrSceneMeshIndicesUint32MSFT i{XR_TYPE_SCENE_MESH_INDICES_UINT32_MSFT};
    v.next = &i;
    XrSceneMeshBuffersMSFT buffers{XR_TYPE_SCENE_MESH_BUFFERS_MSFT, &v};
    SIM_CHECK(app.msft.meshBuffers(scene, &info, &buffers));
    out.vertex_count = v.vertexCountOutput;
    out.index_count = i.indexCountOutput;
    out.vertices.resize(vertex_capacity.value_or(out.vertex_count));
    out.indices.resize(out.index_count);
    v.vertexCapacityInput = static_cast<uint32_t>(out.vertices.size());
    v.vertices = out.vertices.data();
    i.indexCapacityInput = static_cast<uint32_t>(out.indices.size());
    i.indices = out.indices.data();
    return app.msft.meshBuffers(scene, &info, &buffers);
  }
};

TEST(SimFaults, BrokenMeshes) {
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Served clean;
  {
    MeshRead m;
    ASSERT_EQ(m.read(clean), XR_SUCCESS);
    ASSERT_GT(clean.vertex_count, 3u);
    ASSERT_EQ(clean.index_count % 3, 0u);
  }
  {
    ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("mesh:XR_MSFT_scene_understanding=nan"));
    MeshRead m;
    Served s;
    ASSERT_EQ(m.read(s), XR_SUCCESS);
    EXPECT_TRUE(std::isnan(s.vertices[0].x) && std::isnan(s.vertices[0].y) && std::isnan(s.vertices[0].z));
    EXPECT_EQ(s.vertices.size(), clean.vertices.size());
    EXPECT_TRUE(std::isfinite(s.vertices[1].x));
  }
  {
    ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("mesh=empty"));
    MeshRead m;
    Served s;
    ASSERT_EQ(m.read(s), XR_SUCCESS);
    EXPECT_EQ(s.vertex_count, 0u);
    EXPECT_EQ(s.index_count, 0u);
  }
  {
    ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("mesh=ragged"));
    MeshRead m;
    Served s;
    ASSERT_EQ(m.read(s), XR_SUCCESS);
    EXPECT_EQ(s.index_count, clean.index_count + 1);
    EXPECT_EQ(s.index_count % 3, 1u);
  }
  {
    ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("mesh:XR_MSFT_scene_understanding=range"));
    MeshRead m;
    Served s;
    ASSERT_EQ(m.read(s), XR_SUCCESS);
    EXPECT_EQ(s.indices.back(), s.vertex_count);  // one past the last vertex
  }
  {
    ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("mesh=huge"));
    MeshRead m;
    Served s;
    EXPECT_EQ(m.read(s, clean.vertex_count - 1), XR_ERROR_SIZE_INSUFFICIENT);
    EXPECT_EQ(s.vertex_count, 1u << 31);  // the count call
    EXPECT_EQ(m.read(s, clean.vertex_count), XR_SUCCESS);  // a capacity that holds the real ones gets them
    EXPECT_EQ(s.vertices[1].x, clean.vertices[1].x);
  }
  {
    ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("mesh:XR_ML_world_mesh_detection=empty"));  // another extension's
    MeshRead m;
    Served s;
    ASSERT_EQ(m.read(s), XR_SUCCESS);
    EXPECT_EQ(s.vertex_count, clean.vertex_count);
  }
}

TEST(SimFaults, ASessionLostMidQuery) {
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv f("ROOMSENSE_SIM_FAULTS", std::string("lost:xrGetSceneComponentsMSFT=2"));
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneObserverCreateInfoMSFT create{XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT};
  ASSERT_EQ(app.msft.createObserver(app.session, &create, &observer), XR_SUCCESS);
  const XrSceneMSFT scene = simtest::compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT});
  XrSceneComponentsGetInfoMSFT get{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT};
  get.componentType = XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT;
  XrSceneComponentsMSFT list{XR_TYPE_SCENE_COMPONENTS_MSFT};
  EXPECT_EQ(app.msft.components(scene, &get, &list), XR_SUCCESS);        // the count call
  EXPECT_EQ(app.msft.components(scene, &get, &list), XR_ERROR_SESSION_LOST);  // the second: lost here
  bool loss_pending = false;
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
  while (!loss_pending && xrPollEvent(app.instance, &event) == XR_SUCCESS) {
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED)
      loss_pending = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state == XR_SESSION_STATE_LOSS_PENDING;
    event = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  EXPECT_TRUE(loss_pending);
  // Every call on the session or its children is lost; instance calls and destruction work.
  XrSpaceLocation where{XR_TYPE_SPACE_LOCATION};
  EXPECT_EQ(xrLocateSpace(app.local, app.local, app.now(), &where), XR_ERROR_SESSION_LOST);
  XrSceneComputeStateMSFT state{};
  EXPECT_EQ(app.msft.computeState(observer, &state), XR_ERROR_SESSION_LOST);
  XrInstanceProperties properties{XR_TYPE_INSTANCE_PROPERTIES};
  EXPECT_EQ(xrGetInstanceProperties(app.instance, &properties), XR_SUCCESS);
  EXPECT_EQ(app.msft.destroyScene(scene), XR_SUCCESS);
  EXPECT_EQ(app.msft.destroyObserver(observer), XR_SUCCESS);
  EXPECT_EQ(xrDestroySession(app.session), XR_SUCCESS);
  app.session = XR_NULL_HANDLE;
}

}  // namespace
