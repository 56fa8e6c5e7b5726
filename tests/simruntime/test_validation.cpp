// Negative tests: the runtime's answers to invalid input, as the spec's return codes (through the loader).
#include "sim_env.h"
#include "test_process.h"
#include "xr_harness.h"

#include <gtest/gtest.h>

#include <thread>

namespace {

using namespace simtest;

std::filesystem::path box_room() {
  static const auto path = write_box_room("validation_box.obj", 4);
  return path;
}

TEST(SimValidation, CreateInstance) {
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(create_instance(&instance, {"XR_NOT_an_extension"}), XR_ERROR_EXTENSION_NOT_PRESENT);
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_NAME_INVALID);  // empty application name
  std::strcpy(info.applicationInfo.applicationName, "x");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(2, 0, 0);
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_API_VERSION_UNSUPPORTED);
  info.type = XR_TYPE_SESSION_CREATE_INFO;
  EXPECT_NE(xrCreateInstance(&info, &instance), XR_SUCCESS);
}

TEST(SimValidation, BadSceneFileOrOptionsFailInstanceCreation) {
  XrInstance instance = XR_NULL_HANDLE;
  {
    ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("/nonexistent/room.obj"));
    EXPECT_EQ(create_instance(&instance, {}), XR_ERROR_INITIALIZATION_FAILED);
  }
  {
    const auto bad = roomsense::test::scratch_dir() / "bad_capture.json";
    std::ofstream(bad) << "{\"spatialEntities\": [ {\"locatable_META\": 3} ]}";
    ScopedEnv scene("ROOMSENSE_SIM_SCENE", bad.string());
    EXPECT_EQ(create_instance(&instance, {}), XR_ERROR_INITIALIZATION_FAILED);
  }
  {
    ScopedEnv chunk("ROOMSENSE_SIM_CHUNK_SIZE", std::string("big"));
    EXPECT_EQ(create_instance(&instance, {}), XR_ERROR_INITIALIZATION_FAILED);
  }
  {
    ScopedEnv head("ROOMSENSE_SIM_HEAD_POSE", std::string("1,2"));
    EXPECT_EQ(create_instance(&instance, {}), XR_ERROR_INITIALIZATION_FAILED);
  }
  for (const char* scan : {"-1", "soon", "4000", "1,2"}) {
    ScopedEnv seconds("ROOMSENSE_SIM_SCAN_SECONDS", std::string(scan));
    EXPECT_EQ(create_instance(&instance, {}), XR_ERROR_INITIALIZATION_FAILED) << scan;
  }
}

TEST(SimValidation, SystemAndEnumerations) {
  App app;
  XrSystemGetInfo info{XR_TYPE_SYSTEM_GET_INFO};
  info.formFactor = XR_FORM_FACTOR_HANDHELD_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  EXPECT_EQ(xrGetSystem(app.instance, &info, &system), XR_ERROR_FORM_FACTOR_UNSUPPORTED);
  XrSystemProperties properties{XR_TYPE_SYSTEM_PROPERTIES};
  EXPECT_EQ(xrGetSystemProperties(app.instance, 42, &properties), XR_ERROR_SYSTEM_INVALID);
  properties.type = XR_TYPE_INSTANCE_PROPERTIES;
  EXPECT_EQ(xrGetSystemProperties(app.instance, app.system, &properties), XR_ERROR_VALIDATION_FAILURE);

  uint32_t count = 0;
  EXPECT_EQ(xrEnumerateReferenceSpaces(app.session, 0, &count, nullptr), XR_SUCCESS);
  EXPECT_EQ(count, 3u);
  std::vector<XrReferenceSpaceType> spaces(1);
  EXPECT_EQ(xrEnumerateReferenceSpaces(app.session, 1, &count, spaces.data()), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(count, 3u);
  EXPECT_EQ(xrEnumerateReferenceSpaces(app.session, 1, nullptr, spaces.data()), XR_ERROR_VALIDATION_FAILURE);

  std::vector<XrViewConfigurationView> views(2, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
  views[1].type = XR_TYPE_VIEW;
  EXPECT_EQ(xrEnumerateViewConfigurationViews(app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 2, &count, views.data()),
            XR_ERROR_VALIDATION_FAILURE);
  views[1].type = XR_TYPE_VIEW_CONFIGURATION_VIEW;
  EXPECT_EQ(xrEnumerateViewConfigurationViews(app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 2, &count, views.data()),
            XR_SUCCESS);
  EXPECT_EQ(xrEnumerateViewConfigurationViews(app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO, 0, &count, nullptr),
            XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);

  std::vector<XrExtensionProperties> extensions(1, {XR_TYPE_EXTENSION_PROPERTIES});
  EXPECT_EQ(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr), XR_SUCCESS);
  EXPECT_GE(count, 3u);
  EXPECT_EQ(xrEnumerateInstanceExtensionProperties(nullptr, 1, &count, extensions.data()), XR_ERROR_SIZE_INSUFFICIENT);
}

TEST(SimValidation, PathsAndStrings) {
  App app;
  XrPath path = XR_NULL_PATH, again = XR_NULL_PATH;
  for (const char* bad : {"", "user/hand", "/user/", "/user//hand", "/User", "/user/./hand", "/user/../x", "/a b"})
    EXPECT_EQ(xrStringToPath(app.instance, bad, &path), XR_ERROR_PATH_FORMAT_INVALID) << bad;
  ASSERT_EQ(xrStringToPath(app.instance, "/user/hand/left", &path), XR_SUCCESS);
  ASSERT_EQ(xrStringToPath(app.instance, "/user/hand/left", &again), XR_SUCCESS);
  EXPECT_EQ(path, again);
  uint32_t count = 0;
  EXPECT_EQ(xrPathToString(app.instance, path, 0, &count, nullptr), XR_SUCCESS);
  EXPECT_EQ(count, 16u);  // with the terminator
  char small[4];
  EXPECT_EQ(xrPathToString(app.instance, path, sizeof small, &count, small), XR_ERROR_SIZE_INSUFFICIENT);
  std::vector<char> text(count);
  EXPECT_EQ(xrPathToString(app.instance, path, count, &count, text.data()), XR_SUCCESS);
  EXPECT_STREQ(text.data(), "/user/hand/left");
  EXPECT_EQ(xrPathToString(app.instance, path + 1000, 0, &count, nullptr), XR_ERROR_PATH_INVALID);

  char buffer[XR_MAX_RESULT_STRING_SIZE];
  EXPECT_EQ(xrResultToString(app.instance, XR_ERROR_SIZE_INSUFFICIENT, buffer), XR_SUCCESS);
  EXPECT_STREQ(buffer, "XR_ERROR_SIZE_INSUFFICIENT");
  EXPECT_EQ(xrResultToString(app.instance, static_cast<XrResult>(-999999), buffer), XR_SUCCESS);
  EXPECT_STREQ(buffer, "XR_UNKNOWN_FAILURE_-999999");
  char name[XR_MAX_STRUCTURE_NAME_SIZE];
  EXPECT_EQ(xrStructureTypeToString(app.instance, XR_TYPE_SCENE_MESHES_MSFT, name), XR_SUCCESS);
  EXPECT_STREQ(name, "XR_TYPE_SCENE_MESHES_MSFT");
}

TEST(SimValidation, ProcAddrAndUnsupported) {
  XrInstance instance = XR_NULL_HANDLE;
  ASSERT_EQ(create_instance(&instance, {XR_MND_HEADLESS_EXTENSION_NAME}), XR_SUCCESS);
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(instance, "xrCreateSceneObserverMSFT", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);  // not enabled
  EXPECT_EQ(fn, nullptr);
  EXPECT_EQ(xrGetInstanceProcAddr(instance, "xrNoSuchFunction", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);
  // Every core function is served (actions and swapchains included: test_actions.cpp, test_swapchain_headless.cpp).
  EXPECT_EQ(xrGetInstanceProcAddr(instance, "xrCreateActionSet", &fn), XR_SUCCESS);
  EXPECT_NE(fn, nullptr);
  EXPECT_EQ(xrGetInstanceProcAddr(instance, "xrEnumerateSwapchainFormats", &fn), XR_SUCCESS);
  EXPECT_EQ(xrDestroyInstance(instance), XR_SUCCESS);  // the 1.0.20 loader allows one instance at a time

  // A session needs XR_MND_headless: without it there is no graphics binding to be had.
  XrInstance plain = XR_NULL_HANDLE;
  ASSERT_EQ(create_instance(&plain, {}), XR_SUCCESS);
  XrSessionCreateInfo session_info{XR_TYPE_SESSION_CREATE_INFO};
  session_info.systemId = 1;
  XrSession session = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateSession(plain, &session_info, &session), XR_ERROR_GRAPHICS_DEVICE_INVALID);
  EXPECT_EQ(xrDestroyInstance(plain), XR_SUCCESS);
}

TEST(SimValidation, Spaces) {
  ScopedEnv head("ROOMSENSE_SIM_HEAD_POSE", std::string("1,1.5,2"));
  App app;
  XrReferenceSpaceCreateInfo info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  info.poseInReferenceSpace.orientation = {0, 0, 0, 2};
  XrSpace view = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateReferenceSpace(app.session, &info, &view), XR_ERROR_POSE_INVALID);
  info.poseInReferenceSpace.orientation = {0, 0, 0, 1};
  info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_UNBOUNDED_MSFT;
  EXPECT_EQ(xrCreateReferenceSpace(app.session, &info, &view), XR_ERROR_REFERENCE_SPACE_UNSUPPORTED);
  info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  ASSERT_EQ(xrCreateReferenceSpace(app.session, &info, &view), XR_SUCCESS);

  XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
  EXPECT_EQ(xrLocateSpace(view, app.local, 0, &location), XR_ERROR_TIME_INVALID);
  location.type = XR_TYPE_SPACE_VELOCITY;
  EXPECT_EQ(xrLocateSpace(view, app.local, app.now(), &location), XR_ERROR_VALIDATION_FAILURE);
  location.type = XR_TYPE_SPACE_LOCATION;
  ASSERT_EQ(xrLocateSpace(view, app.local, app.now(), &location), XR_SUCCESS);
  EXPECT_FLOAT_EQ(location.pose.position.x, 1.0f);
  EXPECT_FLOAT_EQ(location.pose.position.y, 1.5f);
  EXPECT_FLOAT_EQ(location.pose.position.z, 2.0f);
  ASSERT_EQ(xrLocateSpace(app.local, view, app.now(), &location), XR_SUCCESS);
  EXPECT_FLOAT_EQ(location.pose.position.y, -1.5f);
  EXPECT_EQ(xrDestroySpace(view), XR_SUCCESS);
}

TEST(SimValidation, SceneCompute) {
  ScopedEnv scene_env("ROOMSENSE_SIM_SCENE", box_room().string());
  ScopedEnv delay("ROOMSENSE_SIM_COMPUTE_DELAY_MS", std::string("150"));
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  ASSERT_EQ(app.msft.createObserver(app.session, nullptr, &observer), XR_SUCCESS);
  XrSceneComputeStateMSFT state{};
  ASSERT_EQ(app.msft.computeState(observer, &state), XR_SUCCESS);
  EXPECT_EQ(state, XR_SCENE_COMPUTE_STATE_NONE_MSFT);

  const XrSceneSphereBoundMSFT sphere{{0, 0, 0}, 100};
  XrNewSceneComputeInfoMSFT info = compute_info(app, {}, &sphere);
  EXPECT_EQ(app.msft.compute(observer, &info), XR_ERROR_VALIDATION_FAILURE);  // no features
  const std::vector<XrSceneComputeFeatureMSFT> serialize{XR_SCENE_COMPUTE_FEATURE_SERIALIZE_SCENE_MSFT};
  info = compute_info(app, serialize, &sphere);
  EXPECT_EQ(app.msft.compute(observer, &info), XR_ERROR_SCENE_COMPUTE_FEATURE_INCOMPATIBLE_MSFT);
  const std::vector<XrSceneComputeFeatureMSFT> mesh{XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT};
  info = compute_info(app, mesh, &sphere);
  info.bounds.time = 0;
  EXPECT_EQ(app.msft.compute(observer, &info), XR_ERROR_TIME_INVALID);
  info = compute_info(app, mesh, &sphere);
  const XrSceneSphereBoundMSFT negative{{0, 0, 0}, -1};
  info.bounds.spheres = &negative;
  EXPECT_EQ(app.msft.compute(observer, &info), XR_ERROR_VALIDATION_FAILURE);

  info = compute_info(app, mesh, &sphere);
  ASSERT_EQ(app.msft.compute(observer, &info), XR_SUCCESS);
  ASSERT_EQ(app.msft.computeState(observer, &state), XR_SUCCESS);
  EXPECT_EQ(state, XR_SCENE_COMPUTE_STATE_UPDATING_MSFT);  // asynchronous
  EXPECT_EQ(app.msft.compute(observer, &info), XR_ERROR_COMPUTE_NEW_SCENE_NOT_COMPLETED_MSFT);
  XrSceneMSFT scene = XR_NULL_HANDLE;
  EXPECT_EQ(app.msft.createScene(observer, nullptr, &scene), XR_ERROR_COMPUTE_NEW_SCENE_NOT_COMPLETED_MSFT);
  EXPECT_EQ(wait_for_compute(app, observer), XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT);
  ASSERT_EQ(app.msft.createScene(observer, nullptr, &scene), XR_SUCCESS);

  // Components: capacity, mismatched property structs.
  XrSceneComponentsGetInfoMSFT get{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT, nullptr, XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT};
  XrSceneComponentsMSFT list{XR_TYPE_SCENE_COMPONENTS_MSFT};
  ASSERT_EQ(app.msft.components(scene, &get, &list), XR_SUCCESS);
  ASSERT_GT(list.componentCountOutput, 1u);
  std::vector<XrSceneComponentMSFT> components(list.componentCountOutput);
  list.componentCapacityInput = list.componentCountOutput - 1;
  list.components = components.data();
  EXPECT_EQ(app.msft.components(scene, &get, &list), XR_ERROR_SIZE_INSUFFICIENT);
  list.componentCapacityInput = static_cast<uint32_t>(components.size());
  std::vector<XrSceneMeshMSFT> meshes(components.size() - 1);
  XrSceneMeshesMSFT mesh_props{XR_TYPE_SCENE_MESHES_MSFT, nullptr, uint32_t(meshes.size()), meshes.data()};
  list.next = &mesh_props;
  EXPECT_EQ(app.msft.components(scene, &get, &list), XR_ERROR_SIZE_INSUFFICIENT);  // property array too short
  XrScenePlanesMSFT plane_props{XR_TYPE_SCENE_PLANES_MSFT};
  list.next = &plane_props;
  EXPECT_EQ(app.msft.components(scene, &get, &list), XR_ERROR_SCENE_COMPONENT_TYPE_MISMATCH_MSFT);
  list.next = nullptr;
  ASSERT_EQ(app.msft.components(scene, &get, &list), XR_SUCCESS);
  get.componentType = XR_SCENE_COMPONENT_TYPE_PLANE_MSFT;  // not requested: none
  ASSERT_EQ(app.msft.components(scene, &get, &list), XR_SUCCESS);
  EXPECT_EQ(list.componentCountOutput, 0u);

  // Locate: too few locations, bad time; unknown ids get no flags.
  XrUuidMSFT ids[2] = {components[0].id, {}};
  XrSceneComponentLocationMSFT where[2]{};
  XrSceneComponentsLocateInfoMSFT locate{XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT, nullptr, app.local, app.now(), 2, ids};
  XrSceneComponentLocationsMSFT located{XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT, nullptr, 1, where};
  EXPECT_EQ(app.msft.locate(scene, &locate, &located), XR_ERROR_SIZE_INSUFFICIENT);
  located.locationCount = 2;
  locate.time = -5;
  EXPECT_EQ(app.msft.locate(scene, &locate, &located), XR_ERROR_TIME_INVALID);
  locate.time = app.now();
  ASSERT_EQ(app.msft.locate(scene, &locate, &located), XR_SUCCESS);
  EXPECT_NE(where[0].flags, 0u);
  EXPECT_EQ(where[1].flags, 0u);

  // Mesh buffers: unknown id, no buffer struct, capacity too small.
  XrSceneMeshBuffersGetInfoMSFT buffer_info{XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT, nullptr, 987654321};
  XrSceneMeshVertexBufferMSFT vertices{XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT};
  XrSceneMeshBuffersMSFT buffers{XR_TYPE_SCENE_MESH_BUFFERS_MSFT, &vertices};
  EXPECT_EQ(app.msft.meshBuffers(scene, &buffer_info, &buffers), XR_ERROR_SCENE_MESH_BUFFER_ID_INVALID_MSFT);
  std::vector<XrSceneMeshMSFT> all(components.size());
  mesh_props = {XR_TYPE_SCENE_MESHES_MSFT, nullptr, uint32_t(all.size()), all.data()};
  list.next = &mesh_props;
  get.componentType = XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT;
  ASSERT_EQ(app.msft.components(scene, &get, &list), XR_SUCCESS);
  buffer_info.meshBufferId = all[0].meshBufferId;
  buffers.next = nullptr;
  EXPECT_EQ(app.msft.meshBuffers(scene, &buffer_info, &buffers), XR_ERROR_VALIDATION_FAILURE);
  buffers.next = &vertices;
  ASSERT_EQ(app.msft.meshBuffers(scene, &buffer_info, &buffers), XR_SUCCESS);
  ASSERT_GT(vertices.vertexCountOutput, 1u);
  std::vector<XrVector3f> data(vertices.vertexCountOutput - 1);
  vertices.vertexCapacityInput = uint32_t(data.size());
  vertices.vertices = data.data();
  EXPECT_EQ(app.msft.meshBuffers(scene, &buffer_info, &buffers), XR_ERROR_SIZE_INSUFFICIENT);

  // A bound that misses the room gives an empty scene.
  const XrSceneSphereBoundMSFT far{{100, 0, 0}, 1};
  info = compute_info(app, mesh, &far);
  ASSERT_EQ(app.msft.compute(observer, &info), XR_SUCCESS);
  EXPECT_EQ(wait_for_compute(app, observer), XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT);
  XrSceneMSFT empty = XR_NULL_HANDLE;
  ASSERT_EQ(app.msft.createScene(observer, nullptr, &empty), XR_SUCCESS);
  list = {XR_TYPE_SCENE_COMPONENTS_MSFT};
  ASSERT_EQ(app.msft.components(empty, &get, &list), XR_SUCCESS);
  EXPECT_EQ(list.componentCountOutput, 0u);

  // Destroying the observer while a compute runs cancels it, and takes its scenes along.
  ASSERT_EQ(app.msft.compute(observer, &info), XR_SUCCESS);
  EXPECT_EQ(app.msft.destroyObserver(observer), XR_SUCCESS);
  EXPECT_EQ(app.msft.destroyScene(scene), XR_ERROR_HANDLE_INVALID);
}

TEST(SimValidation, Uint16OnlyWhenTheMeshFits) {
  // One chunk of more than 65536 vertices: a 300 x 300 grid.
  const auto path = roomsense::test::scratch_dir() / "big_grid.obj";
  {
    std::ofstream out(path);
    const int n = 300;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) out << "v " << i * 0.01 << " 0 " << k * 0.01 << '\n';
    for (int i = 0; i + 1 < n; ++i)
      for (int k = 0; k + 1 < n; ++k) {
        const int a = 1 + i * n + k;
        out << "f " << a << ' ' << a + 1 << ' ' << a + n << '\n';
      }
  }
  ScopedEnv scene_env("ROOMSENSE_SIM_SCENE", path.string());
  ScopedEnv chunk("ROOMSENSE_SIM_CHUNK_SIZE", std::string("10"));
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  ASSERT_EQ(app.msft.createObserver(app.session, nullptr, &observer), XR_SUCCESS);
  XrSceneMSFT scene = compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT});
  XrSceneComponentsGetInfoMSFT get{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT, nullptr, XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT};
  XrSceneMeshMSFT mesh{};
  XrSceneMeshesMSFT props{XR_TYPE_SCENE_MESHES_MSFT, nullptr, 1, &mesh};
  XrSceneComponentMSFT component{};
  XrSceneComponentsMSFT list{XR_TYPE_SCENE_COMPONENTS_MSFT, &props, 1, 0, &component};
  ASSERT_EQ(app.msft.components(scene, &get, &list), XR_SUCCESS);
  ASSERT_EQ(list.componentCountOutput, 1u);
  EXPECT_EQ(mesh.supportsIndicesUint16, XR_FALSE);
  XrSceneMeshBuffersGetInfoMSFT buffer_info{XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT, nullptr, mesh.meshBufferId};
  XrSceneMeshIndicesUint16MSFT indices{XR_TYPE_SCENE_MESH_INDICES_UINT16_MSFT};
  XrSceneMeshBuffersMSFT buffers{XR_TYPE_SCENE_MESH_BUFFERS_MSFT, &indices};
  EXPECT_EQ(app.msft.meshBuffers(scene, &buffer_info, &buffers), XR_ERROR_VALIDATION_FAILURE);
}

TEST(SimValidation, NoSceneConfiguredCompletesWithError) {
  ScopedEnv scene_env("ROOMSENSE_SIM_SCENE", std::nullopt);
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  ASSERT_EQ(app.msft.createObserver(app.session, nullptr, &observer), XR_SUCCESS);
  const std::vector<XrSceneComputeFeatureMSFT> mesh{XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT};
  const XrNewSceneComputeInfoMSFT info = compute_info(app, mesh, nullptr);
  ASSERT_EQ(app.msft.compute(observer, &info), XR_SUCCESS);
  EXPECT_EQ(wait_for_compute(app, observer), XR_SCENE_COMPUTE_STATE_COMPLETED_WITH_ERROR_MSFT);
  XrSceneMSFT scene = XR_NULL_HANDLE;
  EXPECT_EQ(app.msft.createScene(observer, nullptr, &scene), XR_ERROR_COMPUTE_NEW_SCENE_NOT_COMPLETED_MSFT);
}

TEST(SimValidation, ConcurrentCallsAreSafe) {
  ScopedEnv scene_env("ROOMSENSE_SIM_SCENE", box_room().string());
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  ASSERT_EQ(app.msft.createObserver(app.session, nullptr, &observer), XR_SUCCESS);
  XrSceneMSFT scene = compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT});
  std::vector<std::thread> threads;
  std::atomic<int> failures{0};
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < 50; ++i) {
        XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
        if (xrLocateSpace(app.local, app.local, app.now(), &location) != XR_SUCCESS) ++failures;
        XrPath path = XR_NULL_PATH;
        if (xrStringToPath(app.instance, "/user/head", &path) != XR_SUCCESS) ++failures;
        try {
          if (read_meshes(app, scene, XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT, false).empty()) ++failures;
        } catch (const std::exception&) {
          ++failures;
        }
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
}

}  // namespace
