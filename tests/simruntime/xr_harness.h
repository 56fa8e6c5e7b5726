// A small OpenXR application for the tests: an instance, a headless session and scene reading, going
// through the real Khronos loader (XR_RUNTIME_JSON points at our runtime). Failures throw, with the call
// and its XrResult, so the tests and the smoke app read as the steps an app takes.
#pragma once
#include <openxr/openxr.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace simtest {

inline void check(XrResult result, const char* what) {
  if (result != XR_SUCCESS) throw std::runtime_error(std::string(what) + " returned " + std::to_string(result));
}
#define SIM_CHECK(call) ::simtest::check((call), #call)

template <typename PFN>
PFN proc(XrInstance instance, const char* name) {
  PFN_xrVoidFunction fn = nullptr;
  check(xrGetInstanceProcAddr(instance, name, &fn), name);
  return reinterpret_cast<PFN>(fn);
}

struct Msft {
  PFN_xrEnumerateSceneComputeFeaturesMSFT enumerateFeatures = nullptr;
  PFN_xrCreateSceneObserverMSFT createObserver = nullptr;
  PFN_xrDestroySceneObserverMSFT destroyObserver = nullptr;
  PFN_xrCreateSceneMSFT createScene = nullptr;
  PFN_xrDestroySceneMSFT destroyScene = nullptr;
  PFN_xrComputeNewSceneMSFT compute = nullptr;
  PFN_xrGetSceneComputeStateMSFT computeState = nullptr;
  PFN_xrGetSceneComponentsMSFT components = nullptr;
  PFN_xrLocateSceneComponentsMSFT locate = nullptr;
  PFN_xrGetSceneMeshBuffersMSFT meshBuffers = nullptr;

  void load(XrInstance i) {
    enumerateFeatures = proc<PFN_xrEnumerateSceneComputeFeaturesMSFT>(i, "xrEnumerateSceneComputeFeaturesMSFT");
    createObserver = proc<PFN_xrCreateSceneObserverMSFT>(i, "xrCreateSceneObserverMSFT");
    destroyObserver = proc<PFN_xrDestroySceneObserverMSFT>(i, "xrDestroySceneObserverMSFT");
    createScene = proc<PFN_xrCreateSceneMSFT>(i, "xrCreateSceneMSFT");
    destroyScene = proc<PFN_xrDestroySceneMSFT>(i, "xrDestroySceneMSFT");
    compute = proc<PFN_xrComputeNewSceneMSFT>(i, "xrComputeNewSceneMSFT");
    computeState = proc<PFN_xrGetSceneComputeStateMSFT>(i, "xrGetSceneComputeStateMSFT");
    components = proc<PFN_xrGetSceneComponentsMSFT>(i, "xrGetSceneComponentsMSFT");
    locate = proc<PFN_xrLocateSceneComponentsMSFT>(i, "xrLocateSceneComponentsMSFT");
    meshBuffers = proc<PFN_xrGetSceneMeshBuffersMSFT>(i, "xrGetSceneMeshBuffersMSFT");
  }
};

inline XrResult create_instance(XrInstance* instance, std::vector<const char*> extensions) {
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "roomsense-simruntime-test");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.enabledExtensionNames = extensions.data();
  return xrCreateInstance(&info, instance);
}

// Instance + system + headless session + LOCAL space; destroys everything on destruction.
struct App {
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  XrSpace local = XR_NULL_HANDLE;
  Msft msft;

  // A headset with these extensions enabled (the scene extension tests build on it with their own functions).
  explicit App(const std::vector<const char*>& extensions = {XR_MND_HEADLESS_EXTENSION_NAME,
                                                             XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME}) {
    SIM_CHECK(create_instance(&instance, extensions));
    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO};
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    SIM_CHECK(xrGetSystem(instance, &system_info, &system));
    start_session();
    for (const char* e : extensions)
      if (std::strcmp(e, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME) == 0) msft.load(instance);
  }
  ~App() {
    if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);  // takes the session and spaces with it
  }
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  // A new session and LOCAL space (the constructor's, or after a test destroyed the session).
  void start_session() {
    XrSessionCreateInfo session_info{XR_TYPE_SESSION_CREATE_INFO};
    session_info.systemId = system;
    SIM_CHECK(xrCreateSession(instance, &session_info, &session));
    XrReferenceSpaceCreateInfo space_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    space_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    space_info.poseInReferenceSpace.orientation.w = 1;
    SIM_CHECK(xrCreateReferenceSpace(session, &space_info, &local));
  }

  XrTime now() const {
    // Any positive time will do for a runtime where nothing moves; use the clock like an app would.
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }
};

struct ComponentMesh {
  XrSceneComponentTypeMSFT type{};
  XrSceneComponentMSFT component{};
  XrPosef pose{};  // in LOCAL
  XrBool32 supports_uint16 = XR_FALSE;
  std::vector<XrVector3f> vertices;  // component space
  std::vector<uint32_t> indices;
};

// Waits for a compute to leave UPDATING, as an app polling each frame would.
inline XrSceneComputeStateMSFT wait_for_compute(App& app, XrSceneObserverMSFT observer) {
  XrSceneComputeStateMSFT state = XR_SCENE_COMPUTE_STATE_UPDATING_MSFT;
  for (int i = 0; i < 2000 && state == XR_SCENE_COMPUTE_STATE_UPDATING_MSFT; ++i) {
    SIM_CHECK(app.msft.computeState(observer, &state));
    if (state == XR_SCENE_COMPUTE_STATE_UPDATING_MSFT) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return state;
}

inline XrNewSceneComputeInfoMSFT compute_info(const App& app, const std::vector<XrSceneComputeFeatureMSFT>& features,
                                              const XrSceneSphereBoundMSFT* sphere) {
  XrNewSceneComputeInfoMSFT info{XR_TYPE_NEW_SCENE_COMPUTE_INFO_MSFT};
  info.requestedFeatureCount = static_cast<uint32_t>(features.size());
  info.requestedFeatures = features.data();
  info.consistency = XR_SCENE_COMPUTE_CONSISTENCY_SNAPSHOT_COMPLETE_MSFT;
  info.bounds.space = app.local;
  info.bounds.time = app.now();
  info.bounds.sphereCount = sphere ? 1 : 0;
  info.bounds.spheres = sphere;
  return info;
}

// Computes a scene with the given features and returns a scene handle (caller destroys it).
inline XrSceneMSFT compute_scene(App& app, XrSceneObserverMSFT observer, const std::vector<XrSceneComputeFeatureMSFT>& features,
                                 float radius = 1000.0f) {
  const XrSceneSphereBoundMSFT sphere{{0, 0, 0}, radius};
  const XrNewSceneComputeInfoMSFT info = compute_info(app, features, &sphere);
  SIM_CHECK(app.msft.compute(observer, &info));
  if (wait_for_compute(app, observer) != XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT) throw std::runtime_error("compute did not complete");
  XrSceneCreateInfoMSFT create{XR_TYPE_SCENE_CREATE_INFO_MSFT};
  XrSceneMSFT scene = XR_NULL_HANDLE;
  SIM_CHECK(app.msft.createScene(observer, &create, &scene));
  return scene;
}

// Every component of `type` with its located pose and, for meshes, its buffers (two-call idiom throughout).
// read_buffers=false stops after components and locations (see sim_smoke.cpp for why).
inline std::vector<ComponentMesh> read_meshes(App& app, XrSceneMSFT scene, XrSceneComponentTypeMSFT type, bool prefer_uint16,
                                              bool read_buffers = true) {
  XrSceneComponentsGetInfoMSFT get{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT};
  get.componentType = type;
  XrSceneComponentsMSFT list{XR_TYPE_SCENE_COMPONENTS_MSFT};
  SIM_CHECK(app.msft.components(scene, &get, &list));
  std::vector<XrSceneComponentMSFT> components(list.componentCountOutput);
  std::vector<XrSceneMeshMSFT> meshes(components.size());
  XrSceneMeshesMSFT mesh_info{XR_TYPE_SCENE_MESHES_MSFT};
  mesh_info.sceneMeshCount = static_cast<uint32_t>(meshes.size());
  mesh_info.sceneMeshes = meshes.data();
  list.next = &mesh_info;
  list.componentCapacityInput = static_cast<uint32_t>(components.size());
  list.components = components.data();
  SIM_CHECK(app.msft.components(scene, &get, &list));

  std::vector<XrUuidMSFT> ids;
  for (const auto& c : components) ids.push_back(c.id);
  std::vector<XrSceneComponentLocationMSFT> locations(ids.size());
  XrSceneComponentsLocateInfoMSFT locate{XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT};
  locate.baseSpace = app.local;
  locate.time = app.now();
  locate.componentIdCount = static_cast<uint32_t>(ids.size());
  locate.componentIds = ids.data();
  XrSceneComponentLocationsMSFT located{XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT};
  located.locationCount = static_cast<uint32_t>(locations.size());
  located.locations = locations.data();
  SIM_CHECK(app.msft.locate(scene, &locate, &located));

  std::vector<ComponentMesh> out;
  for (std::size_t i = 0; i < components.size(); ++i) {
    ComponentMesh m;
    m.type = type;
    m.component = components[i];
    m.pose = locations[i].pose;
    m.supports_uint16 = meshes[i].supportsIndicesUint16;
    if (!(locations[i].flags & XR_SPACE_LOCATION_POSITION_VALID_BIT)) throw std::runtime_error("component not located");
    if (!read_buffers) {
      out.push_back(std::move(m));
      continue;
    }
    XrSceneMeshBuffersGetInfoMSFT buffer_info{XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT};
    buffer_info.meshBufferId = meshes[i].meshBufferId;
    XrSceneMeshBuffersMSFT buffers{XR_TYPE_SCENE_MESH_BUFFERS_MSFT};
    XrSceneMeshVertexBufferMSFT vertices{XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT};
    XrSceneMeshIndicesUint32MSFT indices32{XR_TYPE_SCENE_MESH_INDICES_UINT32_MSFT};
    XrSceneMeshIndicesUint16MSFT indices16{XR_TYPE_SCENE_MESH_INDICES_UINT16_MSFT};
    const bool use16 = prefer_uint16 && m.supports_uint16;
    // Vertices and indices in separate calls, as the spec allows (one chain holding both works too).
    buffers.next = &vertices;
    SIM_CHECK(app.msft.meshBuffers(scene, &buffer_info, &buffers));
    m.vertices.resize(vertices.vertexCountOutput);
    vertices.vertexCapacityInput = vertices.vertexCountOutput;
    vertices.vertices = m.vertices.data();
    SIM_CHECK(app.msft.meshBuffers(scene, &buffer_info, &buffers));
    buffers.next = use16 ? static_cast<void*>(&indices16) : static_cast<void*>(&indices32);
    SIM_CHECK(app.msft.meshBuffers(scene, &buffer_info, &buffers));
    std::vector<uint16_t> small;
    if (use16) {
      small.resize(indices16.indexCountOutput);
      indices16.indexCapacityInput = indices16.indexCountOutput;
      indices16.indices = small.data();
    } else {
      m.indices.resize(indices32.indexCountOutput);
      indices32.indexCapacityInput = indices32.indexCountOutput;
      indices32.indices = m.indices.data();
    }
    SIM_CHECK(app.msft.meshBuffers(scene, &buffer_info, &buffers));
    if (use16) m.indices.assign(small.begin(), small.end());
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace simtest
