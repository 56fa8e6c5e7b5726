#include "msft_scene_understanding.h"

#include "source_support.h"

#include "../capture.h"
#include "../guard.h"
#include "../log.h"
#include "../state.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>
#include <unordered_map>

namespace roomsense::layer {
namespace {

using xr::check;

#define MSFT_FUNCTIONS(_)                                                                                   \
  _(xrEnumerateSceneComputeFeaturesMSFT) _(xrCreateSceneObserverMSFT) _(xrDestroySceneObserverMSFT)         \
  _(xrCreateSceneMSFT) _(xrDestroySceneMSFT) _(xrComputeNewSceneMSFT) _(xrGetSceneComputeStateMSFT)         \
  _(xrGetSceneComponentsMSFT) _(xrLocateSceneComponentsMSFT) _(xrGetSceneMeshBuffersMSFT)

constexpr float kQueryRadius = 100.0f;  // metres around the base space's origin: any room
constexpr std::size_t kMaxComponents = 1u << 20;

std::string chunk_id(const XrUuidMSFT& id) { return uuid_chunk_id("msft", id.bytes); }

bool is_mesh_component(XrSceneComponentTypeMSFT type) {
  return type == XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT || type == XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT;
}

class MsftSource final : public MeshSource {
 public:
#define MSFT_MEMBER(name) PFN_##name name = nullptr;
  MSFT_FUNCTIONS(MSFT_MEMBER)
#undef MSFT_MEMBER

  std::vector<SourceChunk> run_query(const QueryContext& context, std::stop_token stop) override;
  void forget_session(XrSession session) override;

  // The observer of a session's queries, kept from one to the next: the runtime correlates component ids across an
  // observer's computes (the spec), so a mesh it did not change keeps its id and update time, and is neither read
  // again (served_before) nor analysed again (the analyzer's ChunkFeed). One query at a time computes on it.
  struct KeptObserver {
    std::mutex busy;
    XrSceneObserverMSFT handle = XR_NULL_HANDLE;
  };
  std::shared_ptr<KeptObserver> kept_observer(XrSession session);

 private:
  std::mutex observers_mutex_;
  std::unordered_map<XrSession, std::shared_ptr<KeptObserver>> observers_;
};

// ---- active query: the session's observer, a new scene of visual meshes around the base space's origin, every
// mesh read and located in the base space

// Destroys the query's scene, whatever happens, and the kept observer unless its compute ended (a failed, stopped
// or never-ending compute leaves it unusable: the next query makes a new one).
struct QueryHandles {
  const MsftSource& next;
  XrSceneObserverMSFT& observer;
  XrSceneMSFT scene = XR_NULL_HANDLE;
  bool observer_reusable = false;
  ~QueryHandles() {
    if (scene != XR_NULL_HANDLE) next.xrDestroySceneMSFT(scene);
    if (!observer_reusable && observer != XR_NULL_HANDLE) {
      next.xrDestroySceneObserverMSFT(observer);
      observer = XR_NULL_HANDLE;
    }
  }
};

std::shared_ptr<MsftSource::KeptObserver> MsftSource::kept_observer(XrSession session) {
  std::lock_guard lock(observers_mutex_);
  std::shared_ptr<KeptObserver>& kept = observers_[session];
  if (!kept) kept = std::make_shared<KeptObserver>();
  return kept;
}

// Vertices and indices of one mesh buffer, each with the two-call idiom.
MeshPiece read_mesh_buffer(const MsftSource& next, XrSceneMSFT scene, std::uint64_t buffer_id) {
  auto buffer_info = xr_struct<XrSceneMeshBuffersGetInfoMSFT>(XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT);
  buffer_info.meshBufferId = buffer_id;
  auto buffers = xr_struct<XrSceneMeshBuffersMSFT>(XR_TYPE_SCENE_MESH_BUFFERS_MSFT);
  auto vertex_buffer = xr_struct<XrSceneMeshVertexBufferMSFT>(XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT);
  buffers.next = &vertex_buffer;
  const auto vertices = xr::read_two_call<XrVector3f>(
      "xrGetSceneMeshBuffersMSFT",
      [&](std::uint32_t capacity, std::uint32_t* count, XrVector3f* out) {
        vertex_buffer.vertexCapacityInput = capacity;
        vertex_buffer.vertices = out;
        const XrResult r = next.xrGetSceneMeshBuffersMSFT(scene, &buffer_info, &buffers);
        *count = vertex_buffer.vertexCountOutput;
        return r;
      },
      kMaxRuntimeBufferElements);
  auto index_buffer = xr_struct<XrSceneMeshIndicesUint32MSFT>(XR_TYPE_SCENE_MESH_INDICES_UINT32_MSFT);
  buffers.next = &index_buffer;
  std::vector<std::uint32_t> indices = xr::read_two_call<std::uint32_t>(
      "xrGetSceneMeshBuffersMSFT",
      [&](std::uint32_t capacity, std::uint32_t* count, std::uint32_t* out) {
        index_buffer.indexCapacityInput = capacity;
        index_buffer.indices = out;
        const XrResult r = next.xrGetSceneMeshBuffersMSFT(scene, &buffer_info, &buffers);
        *count = index_buffer.indexCountOutput;
        return r;
      },
      kMaxRuntimeBufferElements);
  MeshPiece piece;  // broken triangles are dropped by checked_chunks
  piece.vertices.reserve(vertices.size());
  for (const XrVector3f& v : vertices) piece.vertices.emplace_back(v.x, v.y, v.z);
  piece.indices = std::move(indices);
  return piece;
}

std::vector<SourceChunk> MsftSource::run_query(const QueryContext& context, std::stop_token stop) {
  // Which meshes the runtime can compute.
  const auto features = xr::read_two_call<XrSceneComputeFeatureMSFT>(
      "xrEnumerateSceneComputeFeaturesMSFT",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSceneComputeFeatureMSFT* out) {
        return xrEnumerateSceneComputeFeaturesMSFT(context.instance, context.system, capacity, count, out);
      },
      64);
  auto offers = [&](XrSceneComputeFeatureMSFT f) { return std::find(features.begin(), features.end(), f) != features.end(); };
  XrSceneComputeFeatureMSFT feature = XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT;
  XrSceneComponentTypeMSFT component_type = XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT;
  if (!offers(feature)) {
    if (!offers(XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT)) throw std::runtime_error("the runtime computes no scene meshes");
    feature = XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT;
    component_type = XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT;
  }

  const std::shared_ptr<KeptObserver> kept = kept_observer(context.session);
  std::lock_guard busy(kept->busy);
  QueryHandles handles{*this, kept->handle};
  if (handles.observer == XR_NULL_HANDLE) {
    auto observer_info = xr_struct<XrSceneObserverCreateInfoMSFT>(XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT);
    check(xrCreateSceneObserverMSFT(context.session, &observer_info, &handles.observer), "xrCreateSceneObserverMSFT");
  }

  const XrSceneSphereBoundMSFT sphere{{0.0f, 0.0f, 0.0f}, kQueryRadius};
  auto compute = xr_struct<XrNewSceneComputeInfoMSFT>(XR_TYPE_NEW_SCENE_COMPUTE_INFO_MSFT);
  compute.requestedFeatureCount = 1;
  compute.requestedFeatures = &feature;
  compute.consistency = XR_SCENE_COMPUTE_CONSISTENCY_SNAPSHOT_COMPLETE_MSFT;
  compute.bounds.space = context.base;
  compute.bounds.time = context.time;
  compute.bounds.sphereCount = 1;
  compute.bounds.spheres = &sphere;
  check(xrComputeNewSceneMSFT(handles.observer, &compute), "xrComputeNewSceneMSFT");

  const auto deadline = std::chrono::steady_clock::now() + runtime_timeout();
  PollPause pause;
  XrSceneComputeStateMSFT state = XR_SCENE_COMPUTE_STATE_UPDATING_MSFT;
  for (;;) {
    check(xrGetSceneComputeStateMSFT(handles.observer, &state), "xrGetSceneComputeStateMSFT");
    if (state != XR_SCENE_COMPUTE_STATE_UPDATING_MSFT) break;
    if (stop.stop_requested()) return {};
    if (std::chrono::steady_clock::now() > deadline) throw std::runtime_error("the runtime's scene compute did not complete within " + std::to_string(runtime_timeout().count()) + " ms");
    pause.wait();
  }
  if (state != XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT)
    throw std::runtime_error("the runtime's scene compute ended in state " + std::to_string(state) + " (failed)");
  handles.observer_reusable = true;
  if (stop.stop_requested()) return {};

  auto scene_info = xr_struct<XrSceneCreateInfoMSFT>(XR_TYPE_SCENE_CREATE_INFO_MSFT);
  check(xrCreateSceneMSFT(handles.observer, &scene_info, &handles.scene), "xrCreateSceneMSFT");

  // The mesh components and their buffer ids (two-call idiom).
  auto get = xr_struct<XrSceneComponentsGetInfoMSFT>(XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT);
  get.componentType = component_type;
  auto list = xr_struct<XrSceneComponentsMSFT>(XR_TYPE_SCENE_COMPONENTS_MSFT);
  check(xrGetSceneComponentsMSFT(handles.scene, &get, &list), "xrGetSceneComponentsMSFT");
  if (list.componentCountOutput > kMaxComponents) throw std::runtime_error("the runtime reported an absurd component count");
  std::vector<XrSceneComponentMSFT> components(list.componentCountOutput);
  std::vector<XrSceneMeshMSFT> meshes(components.size());
  auto mesh_list = xr_struct<XrSceneMeshesMSFT>(XR_TYPE_SCENE_MESHES_MSFT);
  mesh_list.sceneMeshCount = static_cast<uint32_t>(meshes.size());
  mesh_list.sceneMeshes = meshes.data();
  list.next = &mesh_list;
  list.componentCapacityInput = static_cast<uint32_t>(components.size());
  list.components = components.data();
  if (!components.empty()) check(xrGetSceneComponentsMSFT(handles.scene, &get, &list), "xrGetSceneComponentsMSFT");
  components.resize(std::min<std::size_t>(components.size(), list.componentCountOutput));
  if (components.empty()) return {};

  // Where each component is in the base space.
  std::vector<XrUuidMSFT> ids;
  ids.reserve(components.size());
  for (const auto& c : components) ids.push_back(c.id);
  std::vector<XrSceneComponentLocationMSFT> locations(ids.size());
  auto locate = xr_struct<XrSceneComponentsLocateInfoMSFT>(XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT);
  locate.baseSpace = context.base;
  locate.time = context.time;
  locate.componentIdCount = static_cast<uint32_t>(ids.size());
  locate.componentIds = ids.data();
  auto where = xr_struct<XrSceneComponentLocationsMSFT>(XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT);
  where.locationCount = static_cast<uint32_t>(locations.size());
  where.locations = locations.data();
  check(xrLocateSceneComponentsMSFT(handles.scene, &locate, &where), "xrLocateSceneComponentsMSFT");

  std::vector<SourceChunk> out;
  out.reserve(components.size());
  std::size_t unlocated = 0;
  for (std::size_t i = 0; i < components.size(); ++i) {
    if (stop.stop_requested()) return {};
    if (!located(locations[i].flags)) {
      ++unlocated;
      continue;
    }
    const std::string id = chunk_id(components[i].id);
    const auto change = static_cast<std::uint64_t>(components[i].updateTime);
    if (std::optional<SourceChunk> kept = served_before(context, id, change, locations[i].pose)) {
      out.push_back(std::move(*kept));
      continue;
    }
    SourceChunk chunk;
    chunk.id = id;
    chunk.change = change;
    chunk.placed = locations[i].pose;
    chunk.mesh = read_mesh_buffer(*this, handles.scene, meshes[i].meshBufferId);
    transform_in_place(chunk.mesh.vertices, to_rigid(chunk.placed));
    out.push_back(std::move(chunk));
  }
  if (unlocated > 0) log_warn(std::to_string(unlocated) + " runtime mesh(es) could not be located and were left out");
  return out;
}

// ---- passive capture: the application's observers and scenes, and the mesh buffers it reads of them

struct SceneRecord {
  std::shared_ptr<SessionState> session;
  std::uint64_t observer = 0, serial = 0;
  struct Component {
    XrUuidMSFT id{};
    XrTime update_time = 0;
  };
  std::mutex mutex;  // the application may read buffers from several threads
  std::unordered_map<std::uint64_t, Component> mesh_components;  // mesh buffer id -> component
  struct Partial {
    std::vector<XrVector3f> vertices;
    std::vector<std::uint32_t> indices;
    bool have_vertices = false, have_indices = false, done = false;
  };
  std::unordered_map<std::uint64_t, Partial> buffers;  // mesh buffer id -> what was read so far
};

struct ObserverRecord {
  std::shared_ptr<SessionState> session;
  std::uint64_t serial = 0;
};

// The application's handles. Lock `mutex` only to look up or change them, never while calling down the chain.
struct Records {
  std::mutex mutex;
  std::unordered_map<XrSceneObserverMSFT, ObserverRecord> observers;
  std::unordered_map<XrSceneMSFT, std::shared_ptr<SceneRecord>> scenes;
  std::uint64_t serial = 0;
};

Records& records() {
  static Records r;
  return r;
}

void MsftSource::forget_session(XrSession session) {
  std::shared_ptr<KeptObserver> kept;
  {
    std::lock_guard lock(observers_mutex_);
    if (const auto it = observers_.find(session); it != observers_.end()) kept = std::move(it->second), observers_.erase(it);
  }
  if (kept) {
    std::lock_guard busy(kept->busy);  // the session's analyses have stopped: no query holds it
    if (kept->handle != XR_NULL_HANDLE) xrDestroySceneObserverMSFT(kept->handle);
  }
  Records& r = records();
  std::lock_guard lock(r.mutex);
  std::erase_if(r.observers, [&](const auto& entry) { return entry.second.session->handle == session; });
  std::erase_if(r.scenes, [&](const auto& entry) { return entry.second->session->handle == session; });
}

const SourceInfo& info();

MsftSource& source_of(const SessionState& session) {
  MsftSource* s = session.instance->source<MsftSource>(info());
  if (s == nullptr) throw std::logic_error("XR_MSFT_scene_understanding hook without its source");
  return *s;
}

std::shared_ptr<SceneRecord> scene_record(XrSceneMSFT scene) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  const auto it = r.scenes.find(scene);
  return it == r.scenes.end() ? nullptr : it->second;
}

// A mesh buffer the application has read in full: locate its component in the capture space and keep it.
void keep_buffer(XrSceneMSFT scene, SceneRecord& record, const SceneRecord::Component& component,
                 const SceneRecord::Partial& buffers) {
  SessionState& session = *record.session;
  const XrSpace space = capture_space(session);
  if (space == XR_NULL_HANDLE || component.update_time <= 0) return;
  XrSceneComponentLocationMSFT location{};
  auto locate = xr_struct<XrSceneComponentsLocateInfoMSFT>(XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT);
  locate.baseSpace = space;
  locate.time = component.update_time;
  locate.componentIdCount = 1;
  locate.componentIds = &component.id;
  auto where = xr_struct<XrSceneComponentLocationsMSFT>(XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT);
  where.locationCount = 1;
  where.locations = &location;
  if (XR_FAILED(source_of(session).xrLocateSceneComponentsMSFT(scene, &locate, &where)) || !located(location.flags)) {
    log_debug([] { return std::string("a scene mesh the application read cannot be located; not captured"); });
    return;
  }
  SourceChunk chunk;
  chunk.id = chunk_id(component.id);
  chunk.change = static_cast<std::uint64_t>(component.update_time);
  chunk.mesh.vertices = transformed(buffers.vertices.data(), buffers.vertices.size(), to_rigid(location.pose));
  chunk.mesh.indices = buffers.indices;
  keep_capture(session, info(), std::move(chunk), record.observer, record.serial);
}

XrResult XRAPI_CALL hook_xrCreateSceneObserverMSFT(XrSession session, const XrSceneObserverCreateInfoMSFT* createInfo,
                                                   XrSceneObserverMSFT* sceneObserver) {
  return guarded("xrCreateSceneObserverMSFT", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*s).xrCreateSceneObserverMSFT(session, createInfo, sceneObserver);
    if (XR_SUCCEEDED(result)) {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      r.observers[*sceneObserver] = {s, ++r.serial};
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrDestroySceneObserverMSFT(XrSceneObserverMSFT sceneObserver) {
  return guarded("xrDestroySceneObserverMSFT", [&]() -> XrResult {
    std::shared_ptr<SessionState> s;
    {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      const auto it = r.observers.find(sceneObserver);
      if (it == r.observers.end()) return XR_ERROR_HANDLE_INVALID;
      s = it->second.session;
    }
    const XrResult result = source_of(*s).xrDestroySceneObserverMSFT(sceneObserver);
    if (XR_SUCCEEDED(result)) {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      r.observers.erase(sceneObserver);
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrCreateSceneMSFT(XrSceneObserverMSFT sceneObserver, const XrSceneCreateInfoMSFT* createInfo,
                                           XrSceneMSFT* scene) {
  return guarded("xrCreateSceneMSFT", [&]() -> XrResult {
    ObserverRecord observer;
    {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      const auto it = r.observers.find(sceneObserver);
      if (it == r.observers.end()) return XR_ERROR_HANDLE_INVALID;
      observer = it->second;
    }
    const XrResult result = source_of(*observer.session).xrCreateSceneMSFT(sceneObserver, createInfo, scene);
    if (XR_SUCCEEDED(result)) {
      auto record = std::make_shared<SceneRecord>();
      record->session = observer.session;
      record->observer = observer.serial;
      Records& r = records();
      std::lock_guard lock(r.mutex);
      record->serial = ++r.serial;
      r.scenes[*scene] = std::move(record);
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrDestroySceneMSFT(XrSceneMSFT scene) {
  return guarded("xrDestroySceneMSFT", [&]() -> XrResult {
    const std::shared_ptr<SceneRecord> record = scene_record(scene);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrDestroySceneMSFT(scene);
    if (XR_SUCCEEDED(result)) {
      {
        Records& r = records();
        std::lock_guard lock(r.mutex);
        r.scenes.erase(scene);
      }
      capture_read_done(record->session);  // the application is done with this scene
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrGetSceneComponentsMSFT(XrSceneMSFT scene, const XrSceneComponentsGetInfoMSFT* getInfo,
                                                  XrSceneComponentsMSFT* components) {
  return guarded("xrGetSceneComponentsMSFT", [&]() -> XrResult {
    const std::shared_ptr<SceneRecord> record = scene_record(scene);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrGetSceneComponentsMSFT(scene, getInfo, components);
    if (result != XR_SUCCESS || getInfo == nullptr || components == nullptr || !is_mesh_component(getInfo->componentType) ||
        components->componentCapacityInput == 0 || components->components == nullptr)
      return result;
    const auto* meshes = find_next<const XrSceneMeshesMSFT>(components->next, XR_TYPE_SCENE_MESHES_MSFT);
    if (meshes == nullptr || meshes->sceneMeshes == nullptr) return result;
    const std::uint32_t n = std::min({components->componentCountOutput, components->componentCapacityInput, meshes->sceneMeshCount});
    std::lock_guard lock(record->mutex);
    for (std::uint32_t i = 0; i < n; ++i)
      record->mesh_components[meshes->sceneMeshes[i].meshBufferId] = {components->components[i].id,
                                                                       components->components[i].updateTime};
    return result;
  });
}

XrResult XRAPI_CALL hook_xrGetSceneMeshBuffersMSFT(XrSceneMSFT scene, const XrSceneMeshBuffersGetInfoMSFT* getInfo,
                                                   XrSceneMeshBuffersMSFT* buffers) {
  return guarded("xrGetSceneMeshBuffersMSFT", [&]() -> XrResult {
    const std::shared_ptr<SceneRecord> record = scene_record(scene);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrGetSceneMeshBuffersMSFT(scene, getInfo, buffers);
    if (result != XR_SUCCESS || getInfo == nullptr || buffers == nullptr) return result;
    const auto* vertices = find_next<const XrSceneMeshVertexBufferMSFT>(buffers->next, XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT);
    const auto* indices32 = find_next<const XrSceneMeshIndicesUint32MSFT>(buffers->next, XR_TYPE_SCENE_MESH_INDICES_UINT32_MSFT);
    const auto* indices16 = find_next<const XrSceneMeshIndicesUint16MSFT>(buffers->next, XR_TYPE_SCENE_MESH_INDICES_UINT16_MSFT);
    SceneRecord::Component component;
    SceneRecord::Partial complete;
    {
      std::lock_guard lock(record->mutex);
      const auto known = record->mesh_components.find(getInfo->meshBufferId);
      if (known == record->mesh_components.end()) return result;  // not a mesh component's buffer (a plane's)
      SceneRecord::Partial& p = record->buffers[getInfo->meshBufferId];
      if (p.done) return result;
      if (vertices != nullptr && vertices->vertexCapacityInput > 0 && vertices->vertices != nullptr) {
        p.vertices.assign(vertices->vertices, vertices->vertices + std::min(vertices->vertexCountOutput, vertices->vertexCapacityInput));
        p.have_vertices = true;
      }
      if (indices32 != nullptr && indices32->indexCapacityInput > 0 && indices32->indices != nullptr) {
        p.indices.assign(indices32->indices, indices32->indices + std::min(indices32->indexCountOutput, indices32->indexCapacityInput));
        p.have_indices = true;
      } else if (indices16 != nullptr && indices16->indexCapacityInput > 0 && indices16->indices != nullptr) {
        p.indices.assign(indices16->indices, indices16->indices + std::min(indices16->indexCountOutput, indices16->indexCapacityInput));
        p.have_indices = true;
      }
      if (!p.have_vertices || !p.have_indices) return result;
      p.done = true;
      component = known->second;
      complete = std::move(p);
      p.vertices.clear();
      p.indices.clear();
    }
    keep_buffer(scene, *record, component, complete);
    return result;
  });
}

std::unique_ptr<MeshSource> create(PFN_xrGetInstanceProcAddr next, XrInstance instance) {
  auto source = std::make_unique<MsftSource>();
#define MSFT_LOAD(name) load_next(next, instance, #name, source->name);
  MSFT_FUNCTIONS(MSFT_LOAD)
#undef MSFT_LOAD
  return source;
}

const SourceInfo& info() {
#define MSFT_NAME(name) #name,
#define MSFT_HOOK(name) HookEntry{#name, reinterpret_cast<PFN_xrVoidFunction>(&hook_##name)},
  static const SourceInfo source{
      XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME,
      "scene meshes of a new scene around the base space",
      {{XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME, {MSFT_FUNCTIONS(MSFT_NAME)}}},
      {MSFT_HOOK(xrCreateSceneObserverMSFT) MSFT_HOOK(xrDestroySceneObserverMSFT) MSFT_HOOK(xrCreateSceneMSFT)
           MSFT_HOOK(xrDestroySceneMSFT) MSFT_HOOK(xrGetSceneComponentsMSFT) MSFT_HOOK(xrGetSceneMeshBuffersMSFT)},
      &create,
  };
#undef MSFT_NAME
#undef MSFT_HOOK
  return source;
}

}  // namespace

const SourceInfo& msft_scene_understanding_source() { return info(); }

}  // namespace roomsense::layer
