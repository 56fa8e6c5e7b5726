#include "scene_query.h"

#include "guard.h"
#include "log.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace roomsense::layer {
namespace {

void check(XrResult result, const char* what) {
  if (XR_FAILED(result)) throw std::runtime_error(std::string(what) + " failed (XrResult " + std::to_string(result) + ")");
}

// Destroys what the query created, whatever happens.
struct QueryHandles {
  const NextDispatch& next;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneMSFT scene = XR_NULL_HANDLE;
  ~QueryHandles() {
    if (scene != XR_NULL_HANDLE) next.xrDestroySceneMSFT(scene);
    if (observer != XR_NULL_HANDLE) next.xrDestroySceneObserverMSFT(observer);
  }
};

constexpr auto kPollInterval = std::chrono::milliseconds(5);
constexpr auto kComputeTimeout = std::chrono::seconds(60);

}  // namespace

std::vector<RuntimeMesh> query_runtime_meshes(const NextDispatch& next, XrInstance instance, XrSystemId system,
                                              XrSession session, XrSpace base, XrTime time, std::stop_token stop) {
  // Which meshes the runtime can compute.
  uint32_t count = 0;
  check(next.xrEnumerateSceneComputeFeaturesMSFT(instance, system, 0, &count, nullptr), "xrEnumerateSceneComputeFeaturesMSFT");
  std::vector<XrSceneComputeFeatureMSFT> features(count);
  check(next.xrEnumerateSceneComputeFeaturesMSFT(instance, system, count, &count, features.data()),
        "xrEnumerateSceneComputeFeaturesMSFT");
  features.resize(count);
  auto offers = [&](XrSceneComputeFeatureMSFT f) { return std::find(features.begin(), features.end(), f) != features.end(); };
  XrSceneComputeFeatureMSFT feature = XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT;
  XrSceneComponentTypeMSFT component_type = XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT;
  if (!offers(feature)) {
    if (!offers(XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT)) throw std::runtime_error("the runtime computes no scene meshes");
    feature = XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT;
    component_type = XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT;
  }

  QueryHandles handles{next};
  auto observer_info = xr_struct<XrSceneObserverCreateInfoMSFT>(XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT);
  check(next.xrCreateSceneObserverMSFT(session, &observer_info, &handles.observer), "xrCreateSceneObserverMSFT");

  const XrSceneSphereBoundMSFT sphere{{0.0f, 0.0f, 0.0f}, kQueryRadius};
  auto compute = xr_struct<XrNewSceneComputeInfoMSFT>(XR_TYPE_NEW_SCENE_COMPUTE_INFO_MSFT);
  compute.requestedFeatureCount = 1;
  compute.requestedFeatures = &feature;
  compute.consistency = XR_SCENE_COMPUTE_CONSISTENCY_SNAPSHOT_COMPLETE_MSFT;
  compute.bounds.space = base;
  compute.bounds.time = time;
  compute.bounds.sphereCount = 1;
  compute.bounds.spheres = &sphere;
  check(next.xrComputeNewSceneMSFT(handles.observer, &compute), "xrComputeNewSceneMSFT");

  const auto deadline = std::chrono::steady_clock::now() + kComputeTimeout;
  XrSceneComputeStateMSFT state = XR_SCENE_COMPUTE_STATE_UPDATING_MSFT;
  for (;;) {
    check(next.xrGetSceneComputeStateMSFT(handles.observer, &state), "xrGetSceneComputeStateMSFT");
    if (state != XR_SCENE_COMPUTE_STATE_UPDATING_MSFT) break;
    if (stop.stop_requested()) return {};
    if (std::chrono::steady_clock::now() > deadline) throw std::runtime_error("the runtime's scene compute timed out");
    std::this_thread::sleep_for(kPollInterval);
  }
  if (state != XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT)
    throw std::runtime_error("the runtime's scene compute ended in state " + std::to_string(state));
  if (stop.stop_requested()) return {};

  auto scene_info = xr_struct<XrSceneCreateInfoMSFT>(XR_TYPE_SCENE_CREATE_INFO_MSFT);
  check(next.xrCreateSceneMSFT(handles.observer, &scene_info, &handles.scene), "xrCreateSceneMSFT");

  // The mesh components and their buffer ids (two-call idiom).
  auto get = xr_struct<XrSceneComponentsGetInfoMSFT>(XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT);
  get.componentType = component_type;
  auto list = xr_struct<XrSceneComponentsMSFT>(XR_TYPE_SCENE_COMPONENTS_MSFT);
  check(next.xrGetSceneComponentsMSFT(handles.scene, &get, &list), "xrGetSceneComponentsMSFT");
  std::vector<XrSceneComponentMSFT> components(list.componentCountOutput);
  std::vector<XrSceneMeshMSFT> meshes(components.size());
  auto mesh_list = xr_struct<XrSceneMeshesMSFT>(XR_TYPE_SCENE_MESHES_MSFT);
  mesh_list.sceneMeshCount = static_cast<uint32_t>(meshes.size());
  mesh_list.sceneMeshes = meshes.data();
  list.next = &mesh_list;
  list.componentCapacityInput = static_cast<uint32_t>(components.size());
  list.components = components.data();
  if (!components.empty()) check(next.xrGetSceneComponentsMSFT(handles.scene, &get, &list), "xrGetSceneComponentsMSFT");
  components.resize(std::min<std::size_t>(components.size(), list.componentCountOutput));
  if (components.empty()) return {};

  // Where each component is in the base space.
  std::vector<XrUuidMSFT> ids;
  ids.reserve(components.size());
  for (const auto& c : components) ids.push_back(c.id);
  std::vector<XrSceneComponentLocationMSFT> locations(ids.size());
  auto locate = xr_struct<XrSceneComponentsLocateInfoMSFT>(XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT);
  locate.baseSpace = base;
  locate.time = time;
  locate.componentIdCount = static_cast<uint32_t>(ids.size());
  locate.componentIds = ids.data();
  auto located = xr_struct<XrSceneComponentLocationsMSFT>(XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT);
  located.locationCount = static_cast<uint32_t>(locations.size());
  located.locations = locations.data();
  check(next.xrLocateSceneComponentsMSFT(handles.scene, &locate, &located), "xrLocateSceneComponentsMSFT");

  constexpr XrSpaceLocationFlags kValid = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
  std::vector<RuntimeMesh> out;
  out.reserve(components.size());
  std::size_t unlocated = 0;
  for (std::size_t i = 0; i < components.size(); ++i) {
    if (stop.stop_requested()) return {};
    if ((locations[i].flags & kValid) != kValid) {
      ++unlocated;
      continue;
    }
    auto buffer_info = xr_struct<XrSceneMeshBuffersGetInfoMSFT>(XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT);
    buffer_info.meshBufferId = meshes[i].meshBufferId;
    // Vertices and indices in separate calls, each with the two-call idiom.
    auto vertex_buffer = xr_struct<XrSceneMeshVertexBufferMSFT>(XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT);
    auto buffers = xr_struct<XrSceneMeshBuffersMSFT>(XR_TYPE_SCENE_MESH_BUFFERS_MSFT);
    buffers.next = &vertex_buffer;
    check(next.xrGetSceneMeshBuffersMSFT(handles.scene, &buffer_info, &buffers), "xrGetSceneMeshBuffersMSFT");
    std::vector<XrVector3f> vertices(vertex_buffer.vertexCountOutput);
    vertex_buffer.vertexCapacityInput = static_cast<uint32_t>(vertices.size());
    vertex_buffer.vertices = vertices.data();
    if (!vertices.empty()) check(next.xrGetSceneMeshBuffersMSFT(handles.scene, &buffer_info, &buffers), "xrGetSceneMeshBuffersMSFT");
    vertices.resize(std::min<std::size_t>(vertices.size(), vertex_buffer.vertexCountOutput));

    auto index_buffer = xr_struct<XrSceneMeshIndicesUint32MSFT>(XR_TYPE_SCENE_MESH_INDICES_UINT32_MSFT);
    buffers.next = &index_buffer;
    check(next.xrGetSceneMeshBuffersMSFT(handles.scene, &buffer_info, &buffers), "xrGetSceneMeshBuffersMSFT");
    std::vector<uint32_t> indices(index_buffer.indexCountOutput);
    index_buffer.indexCapacityInput = static_cast<uint32_t>(indices.size());
    index_buffer.indices = indices.data();
    if (!indices.empty()) check(next.xrGetSceneMeshBuffersMSFT(handles.scene, &buffer_info, &buffers), "xrGetSceneMeshBuffersMSFT");
    indices.resize(std::min<std::size_t>(indices.size(), index_buffer.indexCountOutput));
    indices.resize(indices.size() / 3 * 3);
    if (std::any_of(indices.begin(), indices.end(), [&](uint32_t v) { return v >= vertices.size(); }))
      throw std::runtime_error("the runtime served a mesh with an index out of range");

    RuntimeMesh m;
    m.component = components[i].id;
    m.hash = content_hash(vertices.data(), vertices.size(), indices.data(), indices.size());
    m.mesh.vertices = transformed(vertices.data(), vertices.size(), to_rigid(locations[i].pose));
    m.mesh.indices = std::move(indices);
    out.push_back(std::move(m));
  }
  if (unlocated > 0) log_warn(std::to_string(unlocated) + " runtime mesh(es) could not be located and were left out");
  return out;
}

}  // namespace roomsense::layer
