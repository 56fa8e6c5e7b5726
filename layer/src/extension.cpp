// XR_EXTX_room_understanding's entry points: the spec's validation, then the analyzer (analyzer.h).
// Order of checks, as in OpenXR: handle, then structure types and pointers, then state (call order).
#include "analyzer.h"
#include "functions.h"
#include "guard.h"
#include "log.h"
#include "state.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace roomsense::layer {

std::shared_ptr<Analyzer> find_analyzer(XrRoomAnalyzerEXTX handle) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  const auto it = r.analyzers.find(handle);
  return it == r.analyzers.end() ? nullptr : it->second;
}

namespace {

bool gravity_aligned(XrReferenceSpaceType type) {
  constexpr auto kLocalFloorExt = static_cast<XrReferenceSpaceType>(1000426000);  // XR_EXT_local_floor
  return type == XR_REFERENCE_SPACE_TYPE_LOCAL || type == XR_REFERENCE_SPACE_TYPE_STAGE ||
         type == XR_REFERENCE_SPACE_TYPE_UNBOUNDED_MSFT || type == kLocalFloorExt;
}

constexpr float kMinVoxel = 0.01f, kMaxVoxel = 1.0f;

}  // namespace

XrResult XRAPI_CALL xrCreateRoomAnalyzerEXTX(XrSession session, const XrRoomAnalyzerCreateInfoEXTX* createInfo,
                                             XrRoomAnalyzerEXTX* analyzer) {
  return guarded("xrCreateRoomAnalyzerEXTX", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (!s->instance->extx) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!has_type(createInfo, XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX) || analyzer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (s->lost.load()) return XR_ERROR_SESSION_LOST;  // the runtime said so to one of the layer's calls
    if (createInfo->baseSpace == XR_NULL_HANDLE) return XR_ERROR_HANDLE_INVALID;
    const float voxel = createInfo->voxelSize;
    if (!std::isfinite(voxel) || (voxel != 0.0f && (voxel < kMinVoxel || voxel > kMaxVoxel))) return XR_ERROR_VALIDATION_FAILURE;
    const XrRoomComputeBackendEXTX backend = createInfo->backend;
    if (backend != XR_ROOM_COMPUTE_BACKEND_AUTO_EXTX && backend != XR_ROOM_COMPUTE_BACKEND_CPU_EXTX &&
        backend != XR_ROOM_COMPUTE_BACKEND_VULKAN_EXTX)
      return XR_ERROR_VALIDATION_FAILURE;

    ReferenceSpaceInfo base;
    {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      const auto it = r.spaces.find(createInfo->baseSpace);
      if (it == r.spaces.end()) {
        log_warn("xrCreateRoomAnalyzerEXTX: baseSpace is not a reference space of this session");
        return XR_ERROR_VALIDATION_FAILURE;
      }
      base = it->second;
    }
    if (base.session != session || !gravity_aligned(base.type) || !is_yaw_only(base.pose)) {
      log_warn("xrCreateRoomAnalyzerEXTX: baseSpace must be a gravity-aligned (LOCAL or STAGE) space of this session");
      return XR_ERROR_VALIDATION_FAILURE;
    }

    // The analyzer keeps its own space of the same kind and pose: the application may destroy its space.
    Analyzer::Settings settings;
    auto copy = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    copy.referenceSpaceType = base.type;
    copy.poseInReferenceSpace = base.pose;
    if (const XrResult r = s->instance->next.xrCreateReferenceSpace(session, &copy, &settings.base_space); XR_FAILED(r)) return r;
    settings.base_type = base.type;
    settings.voxel_size = voxel == 0.0f ? kDefaultVoxelSize : voxel;
    settings.backend = backend == XR_ROOM_COMPUTE_BACKEND_CPU_EXTX      ? Backend::Cpu
                       : backend == XR_ROOM_COMPUTE_BACKEND_VULKAN_EXTX ? Backend::Vulkan
                                                                        : s->instance->config.env_backend;
    auto created = std::make_shared<Analyzer>(s, settings);
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (r.sessions.find(session) == r.sessions.end()) {  // the session went away meanwhile
      created->shut_down();
      return XR_ERROR_HANDLE_INVALID;
    }
    const auto handle = reinterpret_cast<XrRoomAnalyzerEXTX>(static_cast<std::uintptr_t>(++r.serial));
    r.analyzers[handle] = std::move(created);
    *analyzer = handle;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroyRoomAnalyzerEXTX(XrRoomAnalyzerEXTX analyzer) {
  return guarded("xrDestroyRoomAnalyzerEXTX", [&]() -> XrResult {
    std::shared_ptr<Analyzer> a;
    {
      Registry& r = registry();
      std::lock_guard lock(r.mutex);
      const auto it = r.analyzers.find(analyzer);
      if (it == r.analyzers.end()) return XR_ERROR_HANDLE_INVALID;
      a = std::move(it->second);
      r.analyzers.erase(it);
    }
    a->shut_down();
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrSubmitRoomMeshEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomMeshEXTX* mesh) {
  return guarded("xrSubmitRoomMeshEXTX", [&]() -> XrResult {
    const std::shared_ptr<Analyzer> a = find_analyzer(analyzer);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(mesh, XR_TYPE_ROOM_MESH_EXTX)) return XR_ERROR_VALIDATION_FAILURE;
    if (mesh->vertexCount == 0 || mesh->vertices == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (mesh->indexCount % 3 != 0 || (mesh->indexCount > 0 && mesh->indices == nullptr)) return XR_ERROR_VALIDATION_FAILURE;
    for (uint32_t i = 0; i < mesh->indexCount; ++i)
      if (mesh->indices[i] >= mesh->vertexCount) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_valid_pose(mesh->pose)) return XR_ERROR_POSE_INVALID;
    MeshPiece piece;
    piece.vertices = transformed(mesh->vertices, mesh->vertexCount, to_rigid(mesh->pose));
    piece.indices.assign(mesh->indices, mesh->indices + mesh->indexCount);
    return a->submit(std::move(piece));
  });
}

XrResult XRAPI_CALL xrComputeRoomEXTX(XrRoomAnalyzerEXTX analyzer, const XrRoomComputeInfoEXTX* computeInfo) {
  return guarded("xrComputeRoomEXTX", [&]() -> XrResult {
    const std::shared_ptr<Analyzer> a = find_analyzer(analyzer);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(computeInfo, XR_TYPE_ROOM_COMPUTE_INFO_EXTX)) return XR_ERROR_VALIDATION_FAILURE;
    if (computeInfo->time <= 0) return XR_ERROR_TIME_INVALID;
    if (a->session()->lost.load()) return XR_ERROR_SESSION_LOST;  // the runtime said so to one of the layer's calls
    return a->compute(*computeInfo);
  });
}

XrResult XRAPI_CALL xrGetRoomComputeStateEXTX(XrRoomAnalyzerEXTX analyzer, XrRoomComputeStateEXTX* state) {
  return guarded("xrGetRoomComputeStateEXTX", [&]() -> XrResult {
    const std::shared_ptr<Analyzer> a = find_analyzer(analyzer);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (state == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *state = a->state();
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetRoomLayoutEXTX(XrRoomAnalyzerEXTX analyzer, XrRoomLayoutEXTX* layout) {
  return guarded("xrGetRoomLayoutEXTX", [&]() -> XrResult {
    const std::shared_ptr<Analyzer> a = find_analyzer(analyzer);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(layout, XR_TYPE_ROOM_LAYOUT_EXTX)) return XR_ERROR_VALIDATION_FAILURE;
    auto* json = find_next<XrRoomAnalysisJsonEXTX>(layout->next, XR_TYPE_ROOM_ANALYSIS_JSON_EXTX);
    if (json != nullptr && json->jsonCapacityInput > 0 && json->json == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    auto* home = find_next<XrRoomHomeLayoutEXTX>(layout->next, XR_TYPE_ROOM_HOME_LAYOUT_EXTX);
    if (home != nullptr && ((home->storeyCapacityInput > 0 && home->storeys == nullptr) ||
                            (home->roomCapacityInput > 0 && home->rooms == nullptr)))
      return XR_ERROR_VALIDATION_FAILURE;
    const std::shared_ptr<const RoomResult> result = a->latest();
    if (!result) return XR_ERROR_CALL_ORDER_INVALID;
    if (home != nullptr) {
      const auto storeys = static_cast<uint32_t>(result->storeys.size());
      const auto rooms = static_cast<uint32_t>(result->rooms.size());
      home->storeyCountOutput = storeys;
      home->roomCountOutput = rooms;
      if ((home->storeyCapacityInput > 0 && home->storeyCapacityInput < storeys) ||
          (home->roomCapacityInput > 0 && home->roomCapacityInput < rooms))
        return XR_ERROR_SIZE_INSUFFICIENT;
      if (home->storeyCapacityInput > 0) std::copy(result->storeys.begin(), result->storeys.end(), home->storeys);
      if (home->roomCapacityInput > 0) std::copy(result->rooms.begin(), result->rooms.end(), home->rooms);
    }
    if (json != nullptr) {
      const auto needed = static_cast<uint32_t>(result->json().size() + 1);
      json->jsonCountOutput = needed;
      if (json->jsonCapacityInput > 0) {
        if (json->jsonCapacityInput < needed) return XR_ERROR_SIZE_INSUFFICIENT;
        std::memcpy(json->json, result->json().c_str(), needed);
      }
    }
    layout->floorHeight = result->floor_y;
    layout->ceilingHeight = result->ceiling_y;
    layout->storeyCount = static_cast<uint32_t>(result->storeys.size());
    layout->boundsMin = result->bounds_min;
    layout->boundsMax = result->bounds_max;
    layout->inputVertexCount = result->input_vertices;
    layout->inputTriangleCount = result->input_triangles;
    layout->computeDuration = result->duration;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetRoomAreasEXTX(XrRoomAnalyzerEXTX analyzer, uint32_t areaCapacityInput, uint32_t* areaCountOutput,
                                       XrRoomAreaEXTX* areas) {
  return guarded("xrGetRoomAreasEXTX", [&]() -> XrResult {
    const std::shared_ptr<Analyzer> a = find_analyzer(analyzer);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (areaCountOutput == nullptr || (areaCapacityInput > 0 && areas == nullptr)) return XR_ERROR_VALIDATION_FAILURE;
    for (uint32_t i = 0; i < areaCapacityInput; ++i)
      if (areas[i].type != XR_TYPE_ROOM_AREA_EXTX) return XR_ERROR_VALIDATION_FAILURE;
    const std::shared_ptr<const RoomResult> result = a->latest();
    if (!result) return XR_ERROR_CALL_ORDER_INVALID;
    const auto count = static_cast<uint32_t>(result->areas.size());
    *areaCountOutput = count;
    if (areaCapacityInput == 0) return XR_SUCCESS;
    if (areaCapacityInput < count) return XR_ERROR_SIZE_INSUFFICIENT;
    for (uint32_t i = 0; i < count; ++i) {
      void* next = areas[i].next;  // the application's chain stays as it was
      areas[i] = result->areas[i];
      areas[i].next = next;
      if (auto* location = find_next<XrRoomAreaLocationEXTX>(next, XR_TYPE_ROOM_AREA_LOCATION_EXTX)) {
        void* after = location->next;
        *location = result->area_locations[i];
        location->next = after;
      }
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetRoomBoundsMeshEXTX(XrRoomAnalyzerEXTX analyzer, XrRoomBoundsMeshEXTX* mesh) {
  return guarded("xrGetRoomBoundsMeshEXTX", [&]() -> XrResult {
    const std::shared_ptr<Analyzer> a = find_analyzer(analyzer);
    if (!a) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(mesh, XR_TYPE_ROOM_BOUNDS_MESH_EXTX)) return XR_ERROR_VALIDATION_FAILURE;
    if ((mesh->vertexCapacityInput > 0 && mesh->vertices == nullptr) || (mesh->indexCapacityInput > 0 && mesh->indices == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    const std::shared_ptr<const RoomResult> result = a->latest();
    if (!result) return XR_ERROR_CALL_ORDER_INVALID;
    const std::vector<XrVector3f>* from_vertices = &result->bounds_vertices;
    const std::vector<uint32_t>* from_indices = &result->bounds_indices;
    if (const auto* room = find_next<const XrRoomBoundsMeshRoomEXTX>(mesh->next, XR_TYPE_ROOM_BOUNDS_MESH_ROOM_EXTX)) {
      if (room->roomIndex >= result->room_bounds.size()) return XR_ERROR_VALIDATION_FAILURE;
      from_vertices = &result->room_bounds[room->roomIndex].vertices;
      from_indices = &result->room_bounds[room->roomIndex].indices;
    }
    const auto vertices = static_cast<uint32_t>(from_vertices->size());
    const auto indices = static_cast<uint32_t>(from_indices->size());
    mesh->vertexCountOutput = vertices;
    mesh->indexCountOutput = indices;
    if ((mesh->vertexCapacityInput > 0 && mesh->vertexCapacityInput < vertices) ||
        (mesh->indexCapacityInput > 0 && mesh->indexCapacityInput < indices))
      return XR_ERROR_SIZE_INSUFFICIENT;
    if (mesh->vertexCapacityInput > 0) std::memcpy(mesh->vertices, from_vertices->data(), vertices * sizeof(XrVector3f));
    if (mesh->indexCapacityInput > 0) std::memcpy(mesh->indices, from_indices->data(), indices * sizeof(uint32_t));
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::layer
