#include "capture.h"

#include "analyzer.h"
#include "guard.h"
#include "log.h"
#include "results.h"

#include <algorithm>
#include <chrono>
#include <cstring>

namespace roomsense::layer {
namespace {

bool same_uuid(const XrUuidMSFT& a, const XrUuidMSFT& b) { return std::memcmp(a.bytes, b.bytes, sizeof a.bytes) == 0; }

bool is_mesh_component(XrSceneComponentTypeMSFT type) {
  return type == XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT || type == XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT;
}

std::shared_ptr<SceneRecord> scene_record(XrSceneMSFT scene) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  const auto it = r.scenes.find(scene);
  return it == r.scenes.end() ? nullptr : it->second;
}

// The session's capture space, created on first use. Call with session.mutex held.
XrSpace capture_space_locked(SessionState& session) {
  if (session.capture_space == XR_NULL_HANDLE && !session.capture_space_failed) {
    auto info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    info.poseInReferenceSpace.orientation.w = 1.0f;
    const XrResult r = session.instance->next.xrCreateReferenceSpace(session.handle, &info, &session.capture_space);
    if (XR_FAILED(r)) {
      session.capture_space = XR_NULL_HANDLE;
      session.capture_space_failed = true;
      log_warn("cannot create a LOCAL space for capturing scene meshes (XrResult " + std::to_string(r) + ")");
    }
  }
  return session.capture_space;
}

// A mesh buffer the application has read in full: locate its component and keep it.
void keep_capture(XrSceneMSFT scene, SceneRecord& record, const SceneRecord::Component& component,
                  const SceneRecord::Partial& buffers) {
  SessionState& session = *record.session;
  const InstanceState& instance = *session.instance;
  XrSpace space;
  {
    std::lock_guard lock(session.mutex);
    space = capture_space_locked(session);
  }
  if (space == XR_NULL_HANDLE || component.update_time <= 0) return;
  XrSceneComponentLocationMSFT location{};
  auto locate = xr_struct<XrSceneComponentsLocateInfoMSFT>(XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT);
  locate.baseSpace = space;
  locate.time = component.update_time;
  locate.componentIdCount = 1;
  locate.componentIds = &component.id;
  auto located = xr_struct<XrSceneComponentLocationsMSFT>(XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT);
  located.locationCount = 1;
  located.locations = &location;
  constexpr XrSpaceLocationFlags kValid = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
  if (XR_FAILED(instance.next.xrLocateSceneComponentsMSFT(scene, &locate, &located)) || (location.flags & kValid) != kValid) {
    log_debug([] { return std::string("a scene mesh the application read cannot be located; not captured"); });
    return;
  }
  auto mesh = std::make_shared<CapturedMesh>();
  mesh->component = component.id;
  mesh->observer = record.observer;
  mesh->scene = record.serial;
  mesh->hash = content_hash(buffers.vertices.data(), buffers.vertices.size(), buffers.indices.data(), buffers.indices.size());
  mesh->mesh.vertices = transformed(buffers.vertices.data(), buffers.vertices.size(), to_rigid(location.pose));
  mesh->mesh.indices = buffers.indices;
  mesh->mesh.indices.resize(mesh->mesh.indices.size() / 3 * 3);
  for (std::uint32_t i : mesh->mesh.indices)
    if (i >= mesh->mesh.vertices.size()) return;  // the runtime's business; nothing we can analyse

  std::lock_guard lock(session.mutex);
  auto& kept = session.captured;
  // A newer scene of the same observer replaces the older one's meshes; an older scene read late adds nothing.
  for (const auto& m : kept)
    if (m->observer == mesh->observer && m->scene > mesh->scene) return;
  std::erase_if(kept, [&](const std::shared_ptr<const CapturedMesh>& m) {
    return (m->observer == mesh->observer && m->scene < mesh->scene) || same_uuid(m->component, mesh->component) ||
           m->hash == mesh->hash;
  });
  kept.push_back(std::move(mesh));
  ++session.capture_generation;
  log_debug([&] { return "captured a scene mesh the application read (" + std::to_string(kept.size()) + " kept)"; });
}

}  // namespace

// ---- hooks of XR_MSFT_scene_understanding (only when the layer captures and the application enabled it)

XrResult XRAPI_CALL xrCreateSceneObserverMSFT(XrSession session, const XrSceneObserverCreateInfoMSFT* createInfo,
                                              XrSceneObserverMSFT* sceneObserver) {
  return guarded("xrCreateSceneObserverMSFT", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = s->instance->next.xrCreateSceneObserverMSFT(session, createInfo, sceneObserver);
    if (XR_SUCCEEDED(result)) {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      r.observers[*sceneObserver] = {s, ++r.serial};
    }
    return result;
  });
}

XrResult XRAPI_CALL xrDestroySceneObserverMSFT(XrSceneObserverMSFT sceneObserver) {
  return guarded("xrDestroySceneObserverMSFT", [&]() -> XrResult {
    std::shared_ptr<SessionState> s;
    {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      const auto it = r.observers.find(sceneObserver);
      if (it == r.observers.end()) return XR_ERROR_HANDLE_INVALID;
      s = it->second.session;
    }
    const XrResult result = s->instance->next.xrDestroySceneObserverMSFT(sceneObserver);
    if (XR_SUCCEEDED(result)) {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      r.observers.erase(sceneObserver);
    }
    return result;
  });
}

XrResult XRAPI_CALL xrCreateSceneMSFT(XrSceneObserverMSFT sceneObserver, const XrSceneCreateInfoMSFT* createInfo, XrSceneMSFT* scene) {
  return guarded("xrCreateSceneMSFT", [&]() -> XrResult {
    ObserverRecord observer;
    {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      const auto it = r.observers.find(sceneObserver);
      if (it == r.observers.end()) return XR_ERROR_HANDLE_INVALID;
      observer = it->second;
    }
    const XrResult result = observer.session->instance->next.xrCreateSceneMSFT(sceneObserver, createInfo, scene);
    if (XR_SUCCEEDED(result)) {
      auto record = std::make_shared<SceneRecord>();
      record->session = observer.session;
      record->observer = observer.serial;
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      record->serial = ++r.serial;
      r.scenes[*scene] = std::move(record);
    }
    return result;
  });
}

XrResult XRAPI_CALL xrDestroySceneMSFT(XrSceneMSFT scene) {
  return guarded("xrDestroySceneMSFT", [&]() -> XrResult {
    const std::shared_ptr<SceneRecord> record = scene_record(scene);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = record->session->instance->next.xrDestroySceneMSFT(scene);
    if (XR_SUCCEEDED(result)) {
      {
        Registry& r = registry();
        std::lock_guard lock(r.mutex);
        r.scenes.erase(scene);
      }
      // The application is done with this scene: without the extension, that is when the layer analyses.
      SessionState& session = *record->session;
      if (!session.instance->extx && !session.instance->config.export_dir.empty()) {
        bool changed;
        {
          std::lock_guard lock(session.mutex);
          changed = session.capture_generation != session.exported_generation;
        }
        if (changed) request_export(record->session);
      }
    }
    return result;
  });
}

XrResult XRAPI_CALL xrGetSceneComponentsMSFT(XrSceneMSFT scene, const XrSceneComponentsGetInfoMSFT* getInfo,
                                             XrSceneComponentsMSFT* components) {
  return guarded("xrGetSceneComponentsMSFT", [&]() -> XrResult {
    const std::shared_ptr<SceneRecord> record = scene_record(scene);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = record->session->instance->next.xrGetSceneComponentsMSFT(scene, getInfo, components);
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

XrResult XRAPI_CALL xrGetSceneMeshBuffersMSFT(XrSceneMSFT scene, const XrSceneMeshBuffersGetInfoMSFT* getInfo,
                                              XrSceneMeshBuffersMSFT* buffers) {
  return guarded("xrGetSceneMeshBuffersMSFT", [&]() -> XrResult {
    const std::shared_ptr<SceneRecord> record = scene_record(scene);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = record->session->instance->next.xrGetSceneMeshBuffersMSFT(scene, getInfo, buffers);
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
    keep_capture(scene, *record, component, complete);
    return result;
  });
}

// ---- export-only analyses

void export_captured(SessionState& session) {
  std::vector<std::shared_ptr<const CapturedMesh>> captured;
  std::uint64_t generation;
  {
    std::lock_guard lock(session.mutex);
    if (session.capture_generation == session.exported_generation) return;
    captured = session.captured;
    generation = session.capture_generation;
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    std::vector<const MeshPiece*> pieces;
    for (const auto& c : captured) pieces.push_back(&c->mesh);
    const AnalysisResult analysis = analyze_pieces(pieces, kDefaultVoxelSize, session.instance->config.env_backend);
    if (!analysis.ok()) {
      log_warn("export: the scene meshes the application read hold no room yet: " + analysis.status_message);
    } else {
      MeshSources sources;
      sources.base_space = "LOCAL";
      sources.app_read_meshes = pieces.size();
      const auto elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start);
      const RoomResult result = make_room_result(analysis, sources, elapsed.count());
      export_files(session.instance->config.export_dir, result, analysis.bounds);
    }
  } catch (const std::exception& e) {
    log_warn(std::string("export: analysis of the captured scene meshes failed: ") + e.what());
  }
  std::lock_guard lock(session.mutex);
  session.exported_generation = generation;
}

void request_export(const std::shared_ptr<SessionState>& session) {
  std::lock_guard lock(session->mutex);
  session->export_pending = true;
  if (!session->export_worker.joinable()) {
    SessionState* s = session.get();  // the session outlives the worker: shut_down_session joins it
    session->export_worker = std::jthread([s](std::stop_token stop) {
      for (;;) {
        {
          std::unique_lock lock(s->mutex);
          if (!s->export_wake.wait(lock, stop, [s] { return s->export_pending; })) return;
          s->export_pending = false;
        }
        export_captured(*s);
      }
    });
  }
  session->export_wake.notify_all();
}

}  // namespace roomsense::layer
