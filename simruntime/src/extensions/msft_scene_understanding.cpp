// XR_MSFT_scene_understanding: observers compute scenes from the room on a worker thread (UPDATING, then
// COMPLETED after ROOMSENSE_SIM_COMPUTE_DELAY_MS), scenes expose components, locations and mesh buffers.
#include "msft_scene_understanding.h"

#include "../faults.h"
#include "../functions.h"
#include "../log.h"
#include "../runtime.h"
#include "../spaces.h"
#include "../validate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace roomsense::sim {
namespace {

const std::vector<XrSceneComputeFeatureMSFT> kFeatures = {
    XR_SCENE_COMPUTE_FEATURE_PLANE_MSFT, XR_SCENE_COMPUTE_FEATURE_PLANE_MESH_MSFT,
    XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT, XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT};

bool finite(const XrVector3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Validates the bounds and resolves them into world space. Call under the lock.
XrResult resolve_bounds(const XrSceneBoundsMSFT& in, std::uint64_t session, WorldBounds& out) {
  const SpaceState* space = runtime().space(in.space);
  if (space == nullptr) return XR_ERROR_HANDLE_INVALID;
  if (space->session != session) return XR_ERROR_VALIDATION_FAILURE;
  if (in.time <= 0) return XR_ERROR_TIME_INVALID;
  if ((in.sphereCount > 0 && in.spheres == nullptr) || (in.boxCount > 0 && in.boxes == nullptr) ||
      (in.frustumCount > 0 && in.frustums == nullptr))
    return XR_ERROR_VALIDATION_FAILURE;
  Rigid world;
  if (!space_in_world(*space, world)) return XR_ERROR_HANDLE_INVALID;
  for (uint32_t i = 0; i < in.sphereCount; ++i) {
    const auto& s = in.spheres[i];
    if (!finite(s.center) || !std::isfinite(s.radius) || s.radius < 0) return XR_ERROR_VALIDATION_FAILURE;
    out.spheres.push_back({world.apply({s.center.x, s.center.y, s.center.z}), s.radius});
  }
  for (uint32_t i = 0; i < in.boxCount; ++i) {
    const auto& b = in.boxes[i];
    if (!is_valid_pose(b.pose)) return XR_ERROR_POSE_INVALID;
    if (!finite(b.extents) || b.extents.x < 0 || b.extents.y < 0 || b.extents.z < 0) return XR_ERROR_VALIDATION_FAILURE;
    out.boxes.push_back({world * to_rigid(b.pose), glm::dvec3(b.extents.x, b.extents.y, b.extents.z) * 0.5});
  }
  for (uint32_t i = 0; i < in.frustumCount; ++i) {
    const auto& f = in.frustums[i];
    if (!is_valid_pose(f.pose)) return XR_ERROR_POSE_INVALID;
    if (!std::isfinite(f.farDistance) || f.farDistance <= 0) return XR_ERROR_VALIDATION_FAILURE;
    // Approximated by the sphere that holds it: a superset, as the spec allows a runtime to return more.
    out.spheres.push_back({world.apply(to_rigid(f.pose).translation), f.farDistance});
  }
  return XR_SUCCESS;
}

void run_compute(std::shared_ptr<ComputeJob> job, ComputeRequest request, int delay_ms) {
  {
    std::unique_lock lock(job->mutex);
    const auto ending = [&] { return job->ending; };
    if (faults::pending(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME)) job->wake.wait(lock, ending);  // UPDATING until the observer goes
    else job->wake.wait_for(lock, std::chrono::milliseconds(delay_ms), ending);
    if (job->ending) return;
  }
  std::shared_ptr<const SceneData> data;
  if (!request.scanned) {
    log_error("scene compute failed: ROOMSENSE_SIM_SCENE is not set, so there is no room to serve");
  } else {
    try {
      data = build_scene(request);
    } catch (const std::exception& e) {
      log_error(std::string("scene compute failed: ") + e.what());
    }
  }
  std::lock_guard lock(job->mutex);
  job->state = data ? XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT : XR_SCENE_COMPUTE_STATE_COMPLETED_WITH_ERROR_MSFT;
  if (data) job->result = std::move(data);
}

bool uuid_equal(const XrUuidMSFT& a, const XrUuidMSFT& b) { return std::memcmp(a.bytes, b.bytes, sizeof a.bytes) == 0; }

}  // namespace

XrResult XRAPI_CALL xrEnumerateSceneComputeFeaturesMSFT(XrInstance instance, XrSystemId systemId, uint32_t capacity,
                                                        uint32_t* countOutput, XrSceneComputeFeatureMSFT* features) {
  return guarded("xrEnumerateSceneComputeFeaturesMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().instance(instance) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    return two_call(capacity, countOutput, features, kFeatures);
  });
}

XrResult XRAPI_CALL xrCreateSceneObserverMSFT(XrSession session, const XrSceneObserverCreateInfoMSFT* createInfo,
                                              XrSceneObserverMSFT* sceneObserver) {
  return guarded("xrCreateSceneObserverMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SessionState* owner = runtime().session(session);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    if ((createInfo != nullptr && createInfo->type != XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT) || sceneObserver == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    const InstanceState* instance = Runtime::find(runtime().instances, owner->instance);
    if (instance == nullptr || !instance->has(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME)) return XR_ERROR_FUNCTION_UNSUPPORTED;
    auto state = std::make_unique<ObserverState>();
    state->session = id_of(session);
    const std::uint64_t id = runtime().new_id();
    runtime().observers.emplace(id, std::move(state));
    *sceneObserver = handle_of<XrSceneObserverMSFT>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySceneObserverMSFT(XrSceneObserverMSFT sceneObserver) {
  return guarded("xrDestroySceneObserverMSFT", [&]() -> XrResult {
    Runtime::Graveyard graveyard;  // joined after the lock is released
    std::lock_guard lock(runtime().mutex);
    if (runtime().observer(sceneObserver) == nullptr) return XR_ERROR_HANDLE_INVALID;
    runtime().destroy_observer(id_of(sceneObserver), graveyard);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrComputeNewSceneMSFT(XrSceneObserverMSFT sceneObserver, const XrNewSceneComputeInfoMSFT* computeInfo) {
  return guarded("xrComputeNewSceneMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    ObserverState* observer = runtime().observer(sceneObserver);
    if (observer == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(computeInfo, XR_TYPE_NEW_SCENE_COMPUTE_INFO_MSFT)) return XR_ERROR_VALIDATION_FAILURE;
    if (computeInfo->requestedFeatureCount == 0 || computeInfo->requestedFeatures == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const auto consistency = computeInfo->consistency;
    if (consistency != XR_SCENE_COMPUTE_CONSISTENCY_SNAPSHOT_COMPLETE_MSFT &&
        consistency != XR_SCENE_COMPUTE_CONSISTENCY_SNAPSHOT_INCOMPLETE_FAST_MSFT &&
        consistency != XR_SCENE_COMPUTE_CONSISTENCY_OCCLUSION_OPTIMIZED_MSFT)
      return XR_ERROR_VALIDATION_FAILURE;
    if (auto* lod = find_next<const XrVisualMeshComputeLodInfoMSFT>(computeInfo->next, XR_TYPE_VISUAL_MESH_COMPUTE_LOD_INFO_MSFT))
      if (lod->lod < XR_MESH_COMPUTE_LOD_COARSE_MSFT || lod->lod > XR_MESH_COMPUTE_LOD_UNLIMITED_MSFT)
        return XR_ERROR_VALIDATION_FAILURE;  // every level of detail serves the file's full mesh

    ComputeRequest request;
    for (uint32_t i = 0; i < computeInfo->requestedFeatureCount; ++i) {
      switch (computeInfo->requestedFeatures[i]) {
        case XR_SCENE_COMPUTE_FEATURE_PLANE_MSFT: request.planes = true; break;
        case XR_SCENE_COMPUTE_FEATURE_PLANE_MESH_MSFT: request.plane_meshes = true; break;
        case XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT: request.visual_mesh = true; break;
        case XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT: request.collider_mesh = true; break;
        case XR_SCENE_COMPUTE_FEATURE_SERIALIZE_SCENE_MSFT: return XR_ERROR_SCENE_COMPUTE_FEATURE_INCOMPATIBLE_MSFT;
        default: return XR_ERROR_VALIDATION_FAILURE;
      }
    }
    if (XrResult r = resolve_bounds(computeInfo->bounds, observer->session, request.bounds); r != XR_SUCCESS) return r;

    {
      std::lock_guard job_lock(observer->job->mutex);
      if (observer->job->state == XR_SCENE_COMPUTE_STATE_UPDATING_MSFT) return XR_ERROR_COMPUTE_NEW_SCENE_NOT_COMPLETED_MSFT;
      observer->job->state = XR_SCENE_COMPUTE_STATE_UPDATING_MSFT;
    }
    const SessionState* session = Runtime::find(runtime().sessions, observer->session);
    const InstanceState* instance = session ? Runtime::find(runtime().instances, session->instance) : nullptr;
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    request.scanned = instance->room_at(now_time());
    request.serial = id_of(sceneObserver);  // the spec: an observer correlates component ids across its computes
    if (observer->first_compute == 0) observer->first_compute = now_time();
    request.time = observer->first_compute;
    // The previous worker has finished (state was not UPDATING); assigning joins it.
    observer->worker = std::jthread(run_compute, observer->job, std::move(request), instance->config.compute_delay_ms);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetSceneComputeStateMSFT(XrSceneObserverMSFT sceneObserver, XrSceneComputeStateMSFT* state) {
  return guarded("xrGetSceneComputeStateMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    ObserverState* observer = runtime().observer(sceneObserver);
    if (observer == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (state == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    std::lock_guard job_lock(observer->job->mutex);
    *state = observer->job->state;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCreateSceneMSFT(XrSceneObserverMSFT sceneObserver, const XrSceneCreateInfoMSFT* createInfo, XrSceneMSFT* scene) {
  return guarded("xrCreateSceneMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    ObserverState* observer = runtime().observer(sceneObserver);
    if (observer == nullptr) return XR_ERROR_HANDLE_INVALID;
    if ((createInfo != nullptr && createInfo->type != XR_TYPE_SCENE_CREATE_INFO_MSFT) || scene == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    std::shared_ptr<const SceneData> data;
    {
      std::lock_guard job_lock(observer->job->mutex);
      if (observer->job->state != XR_SCENE_COMPUTE_STATE_COMPLETED_MSFT) return XR_ERROR_COMPUTE_NEW_SCENE_NOT_COMPLETED_MSFT;
      data = observer->job->result;
    }
    auto state = std::make_unique<SceneState>();
    state->observer = id_of(sceneObserver);
    state->session = observer->session;
    state->data = std::move(data);
    const std::uint64_t id = runtime().new_id();
    runtime().scenes.emplace(id, std::move(state));
    *scene = handle_of<XrSceneMSFT>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySceneMSFT(XrSceneMSFT scene) {
  return guarded("xrDestroySceneMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    return runtime().scenes.erase(id_of(scene)) == 1 ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
  });
}

XrResult XRAPI_CALL xrGetSceneComponentsMSFT(XrSceneMSFT scene, const XrSceneComponentsGetInfoMSFT* getInfo,
                                             XrSceneComponentsMSFT* components) {
  return guarded("xrGetSceneComponentsMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SceneState* state = runtime().scene(scene);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(getInfo, XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT) || !has_type(components, XR_TYPE_SCENE_COMPONENTS_MSFT))
      return XR_ERROR_VALIDATION_FAILURE;
    const XrSceneComponentTypeMSFT type = getInfo->componentType;
    if (type != XR_SCENE_COMPONENT_TYPE_OBJECT_MSFT && type != XR_SCENE_COMPONENT_TYPE_PLANE_MSFT &&
        type != XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT && type != XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT &&
        type != XR_SCENE_COMPONENT_TYPE_SERIALIZED_SCENE_FRAGMENT_MSFT)
      return XR_ERROR_VALIDATION_FAILURE;

    // Filters on the get info.
    const auto* parent = find_next<const XrSceneComponentParentFilterInfoMSFT>(getInfo->next, XR_TYPE_SCENE_COMPONENT_PARENT_FILTER_INFO_MSFT);
    const auto* kinds = find_next<const XrSceneObjectTypesFilterInfoMSFT>(getInfo->next, XR_TYPE_SCENE_OBJECT_TYPES_FILTER_INFO_MSFT);
    const auto* aligns = find_next<const XrScenePlaneAlignmentFilterInfoMSFT>(getInfo->next, XR_TYPE_SCENE_PLANE_ALIGNMENT_FILTER_INFO_MSFT);
    if ((kinds && kinds->objectTypeCount > 0 && kinds->objectTypes == nullptr) ||
        (aligns && aligns->alignmentCount > 0 && aligns->alignments == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    std::vector<const SceneComponent*> matches;
    for (const SceneComponent& c : state->data->components) {
      if (c.type != type) continue;
      if (parent && !uuid_equal(parent->parentId, c.parent)) continue;
      if (kinds && kinds->objectTypeCount > 0 &&
          (!c.object_type || std::find(kinds->objectTypes, kinds->objectTypes + kinds->objectTypeCount, *c.object_type) ==
                                 kinds->objectTypes + kinds->objectTypeCount))
        continue;
      if (aligns && aligns->alignmentCount > 0 &&
          (c.type != XR_SCENE_COMPONENT_TYPE_PLANE_MSFT ||
           std::find(aligns->alignments, aligns->alignments + aligns->alignmentCount, c.alignment) == aligns->alignments + aligns->alignmentCount))
        continue;
      matches.push_back(&c);
    }

    // Property arrays chained on the output; each must match the component type.
    auto* objects = find_next<XrSceneObjectsMSFT>(components->next, XR_TYPE_SCENE_OBJECTS_MSFT);
    auto* planes = find_next<XrScenePlanesMSFT>(components->next, XR_TYPE_SCENE_PLANES_MSFT);
    auto* meshes = find_next<XrSceneMeshesMSFT>(components->next, XR_TYPE_SCENE_MESHES_MSFT);
    const bool mesh_type = type == XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT || type == XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT;
    if ((objects && type != XR_SCENE_COMPONENT_TYPE_OBJECT_MSFT) || (planes && type != XR_SCENE_COMPONENT_TYPE_PLANE_MSFT) ||
        (meshes && !mesh_type))
      return XR_ERROR_SCENE_COMPONENT_TYPE_MISMATCH_MSFT;

    const uint32_t capacity = components->componentCapacityInput;
    if (capacity > 0 && components->components == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    components->componentCountOutput = static_cast<uint32_t>(matches.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < matches.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    if ((objects && objects->sceneObjectCount > 0 && objects->sceneObjects == nullptr) ||
        (planes && planes->scenePlaneCount > 0 && planes->scenePlanes == nullptr) ||
        (meshes && meshes->sceneMeshCount > 0 && meshes->sceneMeshes == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    if ((objects && objects->sceneObjectCount < capacity) || (planes && planes->scenePlaneCount < capacity) ||
        (meshes && meshes->sceneMeshCount < capacity))
      return XR_ERROR_SIZE_INSUFFICIENT;
    for (std::size_t i = 0; i < matches.size(); ++i) {
      const SceneComponent& c = *matches[i];
      components->components[i] = {c.type, c.id, c.parent, c.update_time};
      if (objects) objects->sceneObjects[i].objectType = c.object_type.value_or(XR_SCENE_OBJECT_TYPE_UNCATEGORIZED_MSFT);
      if (planes) planes->scenePlanes[i] = {c.alignment, c.size, c.mesh_buffer_id, static_cast<XrBool32>(c.uint16_ok)};
      if (meshes) meshes->sceneMeshes[i] = {c.mesh_buffer_id, static_cast<XrBool32>(c.uint16_ok)};
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrLocateSceneComponentsMSFT(XrSceneMSFT scene, const XrSceneComponentsLocateInfoMSFT* locateInfo,
                                                XrSceneComponentLocationsMSFT* locations) {
  return guarded("xrLocateSceneComponentsMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SceneState* state = runtime().scene(scene);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(locateInfo, XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT) || !has_type(locations, XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT))
      return XR_ERROR_VALIDATION_FAILURE;
    const SpaceState* base = runtime().space(locateInfo->baseSpace);
    if (base == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (base->session != state->session) return XR_ERROR_VALIDATION_FAILURE;
    if (locateInfo->time <= 0) return XR_ERROR_TIME_INVALID;
    if (locateInfo->componentIdCount > 0 && locateInfo->componentIds == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (locations->locationCount < locateInfo->componentIdCount) return XR_ERROR_SIZE_INSUFFICIENT;
    if (locations->locationCount > 0 && locations->locations == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    Rigid base_world;
    if (!space_in_world(*base, base_world)) return XR_ERROR_HANDLE_INVALID;
    const Rigid world_to_base = base_world.inverse();
    for (uint32_t i = 0; i < locateInfo->componentIdCount; ++i) {
      const auto& components = state->data->components;
      const auto it = std::find_if(components.begin(), components.end(),
                                   [&](const SceneComponent& c) { return uuid_equal(c.id, locateInfo->componentIds[i]); });
      XrSceneComponentLocationMSFT& out = locations->locations[i];
      if (it == components.end()) {
        out = {0, {{0, 0, 0, 1}, {0, 0, 0}}};  // unknown id: no flags, as the spec asks
        continue;
      }
      out.pose = to_pose(world_to_base * it->pose);
      out.flags = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
                  XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetSceneMeshBuffersMSFT(XrSceneMSFT scene, const XrSceneMeshBuffersGetInfoMSFT* getInfo,
                                              XrSceneMeshBuffersMSFT* buffers) {
  return guarded("xrGetSceneMeshBuffersMSFT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SceneState* state = runtime().scene(scene);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(getInfo, XR_TYPE_SCENE_MESH_BUFFERS_GET_INFO_MSFT) || !has_type(buffers, XR_TYPE_SCENE_MESH_BUFFERS_MSFT))
      return XR_ERROR_VALIDATION_FAILURE;
    const auto found = state->data->meshes.find(getInfo->meshBufferId);
    if (found == state->data->meshes.end()) return XR_ERROR_SCENE_MESH_BUFFER_ID_INVALID_MSFT;
    MeshBuffer scratch;
    const MeshBuffer& mesh = faults::faulty_mesh(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME, *found->second, scratch);

    auto* vertices = find_next<XrSceneMeshVertexBufferMSFT>(buffers->next, XR_TYPE_SCENE_MESH_VERTEX_BUFFER_MSFT);
    auto* indices32 = find_next<XrSceneMeshIndicesUint32MSFT>(buffers->next, XR_TYPE_SCENE_MESH_INDICES_UINT32_MSFT);
    auto* indices16 = find_next<XrSceneMeshIndicesUint16MSFT>(buffers->next, XR_TYPE_SCENE_MESH_INDICES_UINT16_MSFT);
    if (vertices == nullptr && indices32 == nullptr && indices16 == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (indices32 != nullptr && indices16 != nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (indices16 != nullptr && !mesh.fits_uint16()) return XR_ERROR_VALIDATION_FAILURE;  // supportsIndicesUint16 was false

    const uint32_t vertex_count = faults::vertex_count(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME, mesh.vertices.size(),
                                                       vertices ? vertices->vertexCapacityInput : 0);
    const auto index_count = static_cast<uint32_t>(mesh.indices.size());
    uint32_t index_capacity = 0;
    bool index_array_missing = false;
    if (indices32) index_capacity = indices32->indexCapacityInput, index_array_missing = index_capacity > 0 && indices32->indices == nullptr;
    if (indices16) index_capacity = indices16->indexCapacityInput, index_array_missing = index_capacity > 0 && indices16->indices == nullptr;
    if (index_array_missing || (vertices && vertices->vertexCapacityInput > 0 && vertices->vertices == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    // Counts first; nothing is written unless every non-zero capacity is large enough.
    if (vertices) vertices->vertexCountOutput = vertex_count;
    if (indices32) indices32->indexCountOutput = index_count;
    if (indices16) indices16->indexCountOutput = index_count;
    if ((vertices && vertices->vertexCapacityInput > 0 && vertices->vertexCapacityInput < vertex_count) ||
        (index_capacity > 0 && index_capacity < index_count))
      return XR_ERROR_SIZE_INSUFFICIENT;
    if (vertices && vertices->vertexCapacityInput > 0) std::copy(mesh.vertices.begin(), mesh.vertices.end(), vertices->vertices);
    if (indices32 && index_capacity > 0) std::copy(mesh.indices.begin(), mesh.indices.end(), indices32->indices);
    if (indices16 && index_capacity > 0)
      std::transform(mesh.indices.begin(), mesh.indices.end(), indices16->indices, [](uint32_t i) { return static_cast<uint16_t>(i); });
    return XR_SUCCESS;
  });
}

const ServedExtension& msft_scene_understanding_extension() {
#define SIM_MSFT_FUNCTIONS(_)                                                                               \
  _(xrEnumerateSceneComputeFeaturesMSFT) _(xrCreateSceneObserverMSFT) _(xrDestroySceneObserverMSFT)         \
  _(xrCreateSceneMSFT) _(xrDestroySceneMSFT) _(xrComputeNewSceneMSFT) _(xrGetSceneComputeStateMSFT)          \
  _(xrGetSceneComponentsMSFT) _(xrLocateSceneComponentsMSFT) _(xrGetSceneMeshBuffersMSFT)
#define SIM_SERVE(name) ServedFunction{#name, reinterpret_cast<PFN_xrVoidFunction>(&sim::name)},
  static const ServedExtension e{XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME, XR_MSFT_scene_understanding_SPEC_VERSION,
                                 true, {SIM_MSFT_FUNCTIONS(SIM_SERVE)}};
#undef SIM_SERVE
#undef SIM_MSFT_FUNCTIONS
  return e;
}

}  // namespace roomsense::sim
