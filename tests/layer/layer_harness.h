// Test helpers for the layer, all through the real Khronos loader: the layer is found as an implicit layer
// (XDG_DATA_HOME=<build>/share, set by ctest) and the simulated runtime through XR_RUNTIME_JSON. Failures
// throw with the call and its XrResult, so tests read as the steps an application takes.
#pragma once
#include <openxr/openxr.h>

#include <openxr/XR_EXTX_room_understanding.h>

#include <gtest/gtest.h>

#include "sim_env.h"
#include "xr_harness.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace layertest {

inline constexpr const char* kLayerName = "XR_APILAYER_ROOMSENSE_room_understanding";

// The simulated runtime's test helpers serve here too: scoped environment variables, checked calls and
// xrGetInstanceProcAddr lookups.
using simtest::check;
using simtest::Msft;
using simtest::proc;
using simtest::ScopedEnv;
#define LT_CHECK(call) ::layertest::check((call), #call)

struct Extx {
  PFN_xrCreateRoomAnalyzerEXTX create = nullptr;
  PFN_xrDestroyRoomAnalyzerEXTX destroy = nullptr;
  PFN_xrSubmitRoomMeshEXTX submit = nullptr;
  PFN_xrComputeRoomEXTX compute = nullptr;
  PFN_xrGetRoomComputeStateEXTX state = nullptr;
  PFN_xrGetRoomLayoutEXTX layout = nullptr;
  PFN_xrGetRoomAreasEXTX areas = nullptr;
  PFN_xrGetRoomBoundsMeshEXTX bounds = nullptr;
  PFN_xrFindRoomPlacementsEXTX place = nullptr;
  PFN_xrRaycastRoomEXTX raycast = nullptr;
  PFN_xrGetRoomRandomPointEXTX random_point = nullptr;
  PFN_xrLocateRoomPointEXTX locate = nullptr;

  void load(XrInstance i) {
    create = proc<PFN_xrCreateRoomAnalyzerEXTX>(i, "xrCreateRoomAnalyzerEXTX");
    destroy = proc<PFN_xrDestroyRoomAnalyzerEXTX>(i, "xrDestroyRoomAnalyzerEXTX");
    submit = proc<PFN_xrSubmitRoomMeshEXTX>(i, "xrSubmitRoomMeshEXTX");
    compute = proc<PFN_xrComputeRoomEXTX>(i, "xrComputeRoomEXTX");
    state = proc<PFN_xrGetRoomComputeStateEXTX>(i, "xrGetRoomComputeStateEXTX");
    layout = proc<PFN_xrGetRoomLayoutEXTX>(i, "xrGetRoomLayoutEXTX");
    areas = proc<PFN_xrGetRoomAreasEXTX>(i, "xrGetRoomAreasEXTX");
    bounds = proc<PFN_xrGetRoomBoundsMeshEXTX>(i, "xrGetRoomBoundsMeshEXTX");
    place = proc<PFN_xrFindRoomPlacementsEXTX>(i, "xrFindRoomPlacementsEXTX");
    raycast = proc<PFN_xrRaycastRoomEXTX>(i, "xrRaycastRoomEXTX");
    random_point = proc<PFN_xrGetRoomRandomPointEXTX>(i, "xrGetRoomRandomPointEXTX");
    locate = proc<PFN_xrLocateRoomPointEXTX>(i, "xrLocateRoomPointEXTX");
  }
};

// The version the loader reports for an instance extension (of one layer, or of all with nullptr); 0 if absent.
inline uint32_t extension_version(const char* layer, const char* name) {
  uint32_t count = 0;
  check(xrEnumerateInstanceExtensionProperties(layer, 0, &count, nullptr), "xrEnumerateInstanceExtensionProperties");
  std::vector<XrExtensionProperties> props(count, {XR_TYPE_EXTENSION_PROPERTIES, nullptr});
  check(xrEnumerateInstanceExtensionProperties(layer, count, &count, props.data()), "xrEnumerateInstanceExtensionProperties");
  for (const auto& p : props)
    if (std::strcmp(p.extensionName, name) == 0) return p.extensionVersion;
  return 0;
}

inline bool has_extension(const char* layer, const char* name) { return extension_version(layer, name) != 0; }

inline int layer_listed(const char* name) {
  uint32_t count = 0;
  check(xrEnumerateApiLayerProperties(0, &count, nullptr), "xrEnumerateApiLayerProperties");
  std::vector<XrApiLayerProperties> layers(count, {XR_TYPE_API_LAYER_PROPERTIES, nullptr});
  check(xrEnumerateApiLayerProperties(count, &count, layers.data()), "xrEnumerateApiLayerProperties");
  int n = 0;
  for (const auto& l : layers) n += std::strcmp(l.layerName, name) == 0;
  return n;
}

// Whether the layer's library is mapped into this process.
inline bool layer_library_loaded() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find("libXrApiLayer_roomsense.so") != std::string::npos) return true;
  return false;
}

inline XrResult create_instance(XrInstance* instance, const std::vector<const char*>& extensions) {
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO, nullptr};
  std::strcpy(info.applicationInfo.applicationName, "roomsense-layer-test");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.enabledExtensionNames = extensions.data();
  return xrCreateInstance(&info, instance);
}

inline XrTime now() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Instance + system + headless session + LOCAL space (+ the extension's functions when enabled).
struct App {
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  XrSpace local = XR_NULL_HANDLE;
  Extx extx;
  Msft msft;

  explicit App(std::vector<const char*> extensions = {XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME}) {
    LT_CHECK(create_instance(&instance, extensions));
    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO, nullptr};
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    LT_CHECK(xrGetSystem(instance, &system_info, &system));
    open_session();
    for (const char* e : extensions) {
      if (std::strcmp(e, XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME) == 0) extx.load(instance);
      if (std::strcmp(e, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME) == 0) msft.load(instance);
    }
  }
  ~App() {
    if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);  // takes the session and spaces with it
  }
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  void open_session() {
    XrSessionCreateInfo session_info{XR_TYPE_SESSION_CREATE_INFO, nullptr};
    session_info.systemId = system;
    LT_CHECK(xrCreateSession(instance, &session_info, &session));
    local = reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  }
  void close_session() {
    LT_CHECK(xrDestroySession(session));
    session = XR_NULL_HANDLE;
    local = XR_NULL_HANDLE;
  }

  XrSpace reference_space(XrReferenceSpaceType type, XrPosef pose = {{0, 0, 0, 1}, {0, 0, 0}}) const {
    XrReferenceSpaceCreateInfo info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO, nullptr};
    info.referenceSpaceType = type;
    info.poseInReferenceSpace = pose;
    XrSpace space = XR_NULL_HANDLE;
    LT_CHECK(xrCreateReferenceSpace(session, &info, &space));
    return space;
  }

  XrRoomAnalyzerEXTX analyzer(XrSpace base = XR_NULL_HANDLE, float voxel = 0.0f,
                              XrRoomComputeBackendEXTX backend = XR_ROOM_COMPUTE_BACKEND_CPU_EXTX) const {
    XrRoomAnalyzerCreateInfoEXTX info{XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX, nullptr};
    info.baseSpace = base != XR_NULL_HANDLE ? base : local;
    info.voxelSize = voxel;
    info.backend = backend;
    XrRoomAnalyzerEXTX a = XR_NULL_HANDLE;
    LT_CHECK(extx.create(session, &info, &a));
    return a;
  }

  void submit(XrRoomAnalyzerEXTX a, const std::vector<XrVector3f>& vertices, const std::vector<uint32_t>& indices,
              XrPosef pose = {{0, 0, 0, 1}, {0, 0, 0}}) const {
    XrRoomMeshEXTX mesh{XR_TYPE_ROOM_MESH_EXTX, nullptr};
    mesh.pose = pose;
    mesh.vertexCount = static_cast<uint32_t>(vertices.size());
    mesh.vertices = vertices.data();
    mesh.indexCount = static_cast<uint32_t>(indices.size());
    mesh.indices = indices.data();
    LT_CHECK(extx.submit(a, &mesh));
  }

  void start(XrRoomAnalyzerEXTX a, bool include_runtime) const {
    XrRoomComputeInfoEXTX info{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
    info.time = now();
    info.includeRuntimeMeshes = include_runtime ? XR_TRUE : XR_FALSE;
    LT_CHECK(extx.compute(a, &info));
  }

  XrRoomComputeStateEXTX wait(XrRoomAnalyzerEXTX a, std::chrono::seconds timeout = std::chrono::seconds(120)) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    XrRoomComputeStateEXTX state = XR_ROOM_COMPUTE_STATE_RUNNING_EXTX;
    while (state == XR_ROOM_COMPUTE_STATE_RUNNING_EXTX && std::chrono::steady_clock::now() < deadline) {
      LT_CHECK(extx.state(a, &state));
      if (state == XR_ROOM_COMPUTE_STATE_RUNNING_EXTX) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return state;
  }

  XrRoomComputeStateEXTX compute(XrRoomAnalyzerEXTX a, bool include_runtime) const {
    start(a, include_runtime);
    return wait(a);
  }
};

// Everything the getters return, read with the two-call idiom.
struct Result {
  XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
  std::vector<XrRoomAreaEXTX> areas;
  std::vector<XrRoomAreaLocationEXTX> area_locations;  // chained to each area (spec version 3)
  std::vector<XrRoomStoreyEXTX> storeys;                // XrRoomHomeLayoutEXTX
  std::vector<XrRoomInfoEXTX> rooms;
  std::vector<XrVector3f> vertices;
  std::vector<uint32_t> indices;
  std::string json;
};

// The bounds mesh with the two-call idiom; `next` chains to its XrRoomBoundsMeshEXTX (one room's bounds).
inline void read_bounds(const Extx& extx, XrRoomAnalyzerEXTX a, void* next, std::vector<XrVector3f>& vertices,
                        std::vector<uint32_t>& indices) {
  XrRoomBoundsMeshEXTX bounds{XR_TYPE_ROOM_BOUNDS_MESH_EXTX, next};
  LT_CHECK(extx.bounds(a, &bounds));
  vertices.resize(bounds.vertexCountOutput);
  indices.resize(bounds.indexCountOutput);
  bounds.vertexCapacityInput = bounds.vertexCountOutput;
  bounds.vertices = vertices.data();
  bounds.indexCapacityInput = bounds.indexCountOutput;
  bounds.indices = indices.data();
  LT_CHECK(extx.bounds(a, &bounds));
}

inline Result read_result(const Extx& extx, XrRoomAnalyzerEXTX a) {
  Result r;
  XrRoomHomeLayoutEXTX home{XR_TYPE_ROOM_HOME_LAYOUT_EXTX, nullptr};
  XrRoomAnalysisJsonEXTX json{XR_TYPE_ROOM_ANALYSIS_JSON_EXTX, &home};
  r.layout.next = &json;
  LT_CHECK(extx.layout(a, &r.layout));
  std::vector<char> text(json.jsonCountOutput);
  json.jsonCapacityInput = json.jsonCountOutput;
  json.json = text.data();
  r.storeys.resize(home.storeyCountOutput);
  r.rooms.resize(home.roomCountOutput);
  home.storeyCapacityInput = home.storeyCountOutput;
  home.storeys = r.storeys.data();
  home.roomCapacityInput = home.roomCountOutput;
  home.rooms = r.rooms.data();
  LT_CHECK(extx.layout(a, &r.layout));
  r.layout.next = nullptr;
  r.json.assign(text.data(), text.empty() ? 0 : text.size() - 1);
  uint32_t count = 0;
  LT_CHECK(extx.areas(a, 0, &count, nullptr));
  r.area_locations.assign(count, {XR_TYPE_ROOM_AREA_LOCATION_EXTX, nullptr});
  r.areas.assign(count, {XR_TYPE_ROOM_AREA_EXTX, nullptr});
  for (uint32_t i = 0; i < count; ++i) r.areas[i].next = &r.area_locations[i];
  LT_CHECK(extx.areas(a, count, &count, r.areas.data()));
  for (XrRoomAreaEXTX& area : r.areas) area.next = nullptr;
  read_bounds(extx, a, nullptr, r.vertices, r.indices);
  return r;
}

// Computes a scene of visual meshes and reads every mesh, as a scene-aware application would; returns the
// number of meshes read. Destroys the scene (and observer) unless `keep_scene`.
inline std::size_t read_scene_meshes(App& app, float radius = 1000.0f) {
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneObserverCreateInfoMSFT observer_info{XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT, nullptr};
  LT_CHECK(app.msft.createObserver(app.session, &observer_info, &observer));
  const XrSceneComputeFeatureMSFT feature = XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT;
  const XrSceneSphereBoundMSFT sphere{{0, 0, 0}, radius};
  XrNewSceneComputeInfoMSFT info{XR_TYPE_NEW_SCENE_COMPUTE_INFO_MSFT, nullptr};
  info.requestedFeatureCount = 1;
  info.requestedFeatures = &feature;
  info.consistency = XR_SCENE_COMPUTE_CONSISTENCY_SNAPSHOT_COMPLETE_MSFT;
  info.bounds.space = app.local;
  info.bounds.time = now();
  info.bounds.sphereCount = 1;
  info.bounds.spheres = &sphere;
  LT_CHECK(app.msft.compute(observer, &info));
  XrSceneComputeStateMSFT state = XR_SCENE_COMPUTE_STATE_UPDATING_MSFT;
  while (state == XR_SCENE_COMPUTE_STATE_UPDATING_MSFT) {
    LT_CHECK(app.msft.computeState(observer, &state));
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (state != XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT) throw std::runtime_error("scene compute failed");
  XrSceneCreateInfoMSFT create{XR_TYPE_SCENE_CREATE_INFO_MSFT, nullptr};
  XrSceneMSFT scene = XR_NULL_HANDLE;
  LT_CHECK(app.msft.createScene(observer, &create, &scene));

  XrSceneComponentsGetInfoMSFT get{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT, nullptr};
  get.componentType = XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT;
  XrSceneComponentsMSFT list{XR_TYPE_SCENE_COMPONENTS_MSFT, nullptr};
  LT_CHECK(app.msft.components(scene, &get, &list));
  std::vector<XrSceneComponentMSFT> components(list.componentCountOutput);
  std::vector<XrSceneMeshMSFT> meshes(components.size());
  XrSceneMeshesMSFT mesh_info{XR_TYPE_SCENE_MESHES_MSFT, nullptr};
  mesh_info.sceneMeshCount = static_cast<uint32_t>(meshes.size());
  mesh_info.sceneMeshes = meshes.data();
  list.next = &mesh_info;
  list.componentCapacityInput = static_cast<uint32_t>(components.size());
  list.components = components.data();
  LT_CHECK(app.msft.components(scene, &get, &list));
  for (const XrSceneMeshMSFT& m : meshes) {
    XrSceneMeshBuffersGetInfoMSFT buffer_info{XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT, nullptr};
    buffer_info.meshBufferId = m.meshBufferId;
    // One chain holding both, with uint16 indices where the runtime allows them (the other path of the layer's
    // capture; its own query uses separate uint32 calls).
    XrSceneMeshVertexBufferMSFT vertices{XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT, nullptr};
    XrSceneMeshIndicesUint16MSFT i16{XR_TYPE_SCENE_MESH_INDICES_UINT16_MSFT, nullptr};
    XrSceneMeshIndicesUint32MSFT i32{XR_TYPE_SCENE_MESH_INDICES_UINT32_MSFT, nullptr};
    const bool small = m.supportsIndicesUint16 != XR_FALSE;
    if (small) vertices.next = &i16;
    else vertices.next = &i32;
    XrSceneMeshBuffersMSFT buffers{XR_TYPE_SCENE_MESH_BUFFERS_MSFT, &vertices};
    LT_CHECK(app.msft.meshBuffers(scene, &buffer_info, &buffers));
    std::vector<XrVector3f> v(vertices.vertexCountOutput);
    std::vector<uint16_t> s(small ? i16.indexCountOutput : 0);
    std::vector<uint32_t> l(small ? 0 : i32.indexCountOutput);
    vertices.vertexCapacityInput = static_cast<uint32_t>(v.size());
    vertices.vertices = v.data();
    i16.indexCapacityInput = static_cast<uint32_t>(s.size());
    i16.indices = s.data();
    i32.indexCapacityInput = static_cast<uint32_t>(l.size());
    i32.indices = l.data();
    LT_CHECK(app.msft.meshBuffers(scene, &buffer_info, &buffers));
  }
  LT_CHECK(app.msft.destroyScene(scene));
  LT_CHECK(app.msft.destroyObserver(observer));
  return meshes.size();
}

}  // namespace layertest
