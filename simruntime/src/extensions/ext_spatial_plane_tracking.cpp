// XR_EXT_spatial_entity + XR_EXT_spatial_plane_tracking. A context is created through a future and queues one
// XrEventDataSpatialDiscoveryRecommendedEXT; a discovery snapshot (another future) holds every plane of the room
// (plane_extraction.h), located in the base space its completion names; update snapshots hold the entities
// an application made from ids. Buffer ids encode the plane and the buffer (polygon, mesh vertices, mesh
// indices) and are valid in the snapshots that hold that plane and component. Everything here is guarded by
// runtime().mutex.
#include "ext_spatial_plane_tracking.h"
#include "../process_state.h"

#include "../faults.h"
#include "../functions.h"
#include "../log.h"
#include "../runtime.h"
#include "../spaces.h"
#include "../validate.h"
#include "ext_future.h"
#include "plane_extraction.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"
#include "roomsense/xr/spatial_query.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <optional>
#include <type_traits>
#include <unordered_map>

namespace roomsense::sim {
namespace {

using Component = XrSpatialComponentTypeEXT;

const std::vector<Component> kPlaneComponents = {
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT,
    XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT,
    XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT};

constexpr const char* kContextFuture = "xrCreateSpatialContextAsyncEXT";
constexpr const char* kSnapshotFuture = "xrCreateSpatialDiscoverySnapshotAsyncEXT";

enum BufferKind : std::uint64_t { kPolygon = 1, kMeshVertices = 2, kMeshIndices = 3 };

struct PlaneSet {
  std::shared_ptr<const Room> room;  // keeps the key alive
  std::vector<ServedPlane> planes;
};

struct Context {
  std::uint64_t session = 0, instance = 0;
  std::vector<Component> components;  // enabled
};

struct Snapshot {
  std::uint64_t context = 0, session = 0;
  std::shared_ptr<const PlaneSet> planes;
  std::vector<std::size_t> entities;  // plane indices
  std::vector<Component> components;
  Rigid world_to_base;
};

struct Entity {
  std::uint64_t context = 0, session = 0;
  std::size_t plane = 0;
};

struct ContextRequest {
  std::vector<Component> components;
};

struct DiscoveryRequest {
  std::uint64_t context = 0;
  std::vector<Component> components;
  std::optional<XrSpatialEntityTrackingStateEXT> filter;
};

struct State {
  std::unordered_map<std::uint64_t, Context> contexts;
  std::unordered_map<std::uint64_t, Snapshot> snapshots;
  std::unordered_map<std::uint64_t, Entity> entities;
  std::map<const Room*, std::shared_ptr<const PlaneSet>> planes;
};

State& state() {
  return process_wide<State>();
}

bool contains(const std::vector<Component>& list, Component c) { return std::find(list.begin(), list.end(), c) != list.end(); }

InstanceState* instance_of_session(std::uint64_t session) {
  const SessionState* s = Runtime::find(runtime().sessions, session);
  return s == nullptr ? nullptr : Runtime::find(runtime().instances, s->instance);
}

bool offers_planes(const InstanceState& instance) { return instance.has(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME); }

std::shared_ptr<const PlaneSet> planes_of(const InstanceState& instance) {
  if (!instance.room) return std::make_shared<PlaneSet>();
  auto& cached = state().planes[instance.room.get()];
  if (!cached) {
    auto set = std::make_shared<PlaneSet>();
    set->room = instance.room;
    set->planes = extract_planes(*instance.room);
    cached = std::move(set);
  }
  return cached;
}

// The base space of a snapshot: validated, and the transform from world into it.
XrResult resolve_base(XrSpace space, XrTime time, std::uint64_t session, Rigid& world_to_base) {
  const SpaceState* s = runtime().space(space);
  if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
  if (s->session != session) return XR_ERROR_VALIDATION_FAILURE;
  if (time <= 0) return XR_ERROR_TIME_INVALID;
  Rigid world;
  if (!space_in_world(*s, world)) return XR_ERROR_HANDLE_INVALID;
  world_to_base = world.inverse();
  return XR_SUCCESS;
}

void drop_context_events(InstanceState* instance, const std::vector<std::uint64_t>& contexts) {
  if (instance == nullptr) return;
  std::erase_if(instance->extension_events, [&](const XrEventDataBuffer& e) {
    if (e.type != XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT) return false;
    XrEventDataSpatialDiscoveryRecommendedEXT event;
    std::memcpy(&event, &e, sizeof event);
    return std::find(contexts.begin(), contexts.end(), id_of(event.spatialContext)) != contexts.end();
  });
}

void destroy_context(std::uint64_t id) {
  State& s = state();
  const auto it = s.contexts.find(id);
  if (it == s.contexts.end()) return;
  drop_context_events(Runtime::find(runtime().instances, it->second.instance), {id});
  std::erase_if(s.snapshots, [&](const auto& e) { return e.second.context == id; });
  std::erase_if(s.entities, [&](const auto& e) { return e.second.context == id; });
  s.contexts.erase(it);
}

XrPosef base_pose(const Snapshot& snapshot, const ServedPlane& plane) { return to_pose(snapshot.world_to_base * plane.pose); }

std::uint64_t buffer_id(std::size_t plane, BufferKind kind) { return (static_cast<std::uint64_t>(plane) + 1) * 4 + kind; }

bool small_indices(const ServedPlane& p) { return p.vertices.size() <= 0x10000; }

// The buffer behind an id in this snapshot, or false.
bool find_buffer(const Snapshot& s, std::uint64_t id, const ServedPlane*& plane, BufferKind& kind) {
  if (id < 4) return false;
  const std::size_t index = static_cast<std::size_t>(id / 4 - 1);
  kind = static_cast<BufferKind>(id % 4);
  if (kind == 0 || std::find(s.entities.begin(), s.entities.end(), index) == s.entities.end()) return false;
  if (!contains(s.components, kind == kPolygon ? XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT : XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT))
    return false;
  plane = &s.planes->planes[index];
  return true;
}

XrSpatialBufferTypeEXT buffer_type(const ServedPlane& plane, BufferKind kind) {
  if (kind != kMeshIndices) return XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT;
  return small_indices(plane) ? XR_SPATIAL_BUFFER_TYPE_UINT16_EXT : XR_SPATIAL_BUFFER_TYPE_UINT32_EXT;
}

template <typename T>
XrResult get_buffer(const char* function, XrSpatialSnapshotEXT snapshot, const XrSpatialBufferGetInfoEXT* info,
                    uint32_t capacity, uint32_t* count, T* out) {
  return guarded(function, [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().snapshots.find(id_of(snapshot));
    if (it == state().snapshots.end()) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    const ServedPlane* plane = nullptr;
    BufferKind kind{};
    if (!find_buffer(it->second, info->bufferId, plane, kind)) return XR_ERROR_SPATIAL_BUFFER_ID_INVALID_EXT;
    const XrSpatialBufferTypeEXT type = buffer_type(*plane, kind);
    ServedPlane scratch;
    plane = &faults::faulty_mesh(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME, *plane, scratch);
    if (kind == kMeshVertices && count != nullptr &&
        faults::vertex_count(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME, plane->vertices.size(), capacity) == faults::kHugeCount) {
      *count = faults::kHugeCount;  // 2^31 vertices, and never a capacity that holds them
      return capacity == 0 ? XR_SUCCESS : XR_ERROR_SIZE_INSUFFICIENT;
    }
    if constexpr (std::is_same_v<T, XrVector2f>) {
      if (type != XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT) return XR_ERROR_VALIDATION_FAILURE;
      return two_call(capacity, count, out, kind == kPolygon ? plane->polygon : plane->vertices);
    } else if constexpr (std::is_same_v<T, std::uint32_t>) {
      if (type != XR_SPATIAL_BUFFER_TYPE_UINT32_EXT) return XR_ERROR_VALIDATION_FAILURE;
      return two_call(capacity, count, out, plane->indices);
    } else if constexpr (std::is_same_v<T, std::uint16_t>) {
      if (type != XR_SPATIAL_BUFFER_TYPE_UINT16_EXT) return XR_ERROR_VALIDATION_FAILURE;
      const std::vector<std::uint16_t> small(plane->indices.begin(), plane->indices.end());
      return two_call(capacity, count, out, small);
    } else {
      return XR_ERROR_VALIDATION_FAILURE;  // no buffer of this type is ever served
    }
  });
}

// ---- capabilities

XrResult XRAPI_CALL xrEnumerateSpatialCapabilitiesEXT(XrInstance instance, XrSystemId systemId, uint32_t capacity,
                                                      uint32_t* countOutput, XrSpatialCapabilityEXT* capabilities) {
  return guarded("xrEnumerateSpatialCapabilitiesEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    std::vector<XrSpatialCapabilityEXT> list;
    if (offers_planes(*state)) list.push_back(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT);
    return two_call(capacity, countOutput, capabilities, list);
  });
}

XrResult XRAPI_CALL xrEnumerateSpatialCapabilityComponentTypesEXT(XrInstance instance, XrSystemId systemId,
                                                                  XrSpatialCapabilityEXT capability,
                                                                  XrSpatialCapabilityComponentTypesEXT* components) {
  return guarded("xrEnumerateSpatialCapabilityComponentTypesEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (!has_type(components, XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    if (capability != XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT || !offers_planes(*state))
      return XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT;
    return two_call(components->componentTypeCapacityInput, &components->componentTypeCountOutput,
                    components->componentTypes, kPlaneComponents);
  });
}

XrResult XRAPI_CALL xrEnumerateSpatialCapabilityFeaturesEXT(XrInstance instance, XrSystemId systemId,
                                                            XrSpatialCapabilityEXT capability, uint32_t capacity,
                                                            uint32_t* countOutput, XrSpatialCapabilityFeatureEXT* features) {
  return guarded("xrEnumerateSpatialCapabilityFeaturesEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (capability != XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT || !offers_planes(*state))
      return XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT;
    return two_call(capacity, countOutput, features, std::vector<XrSpatialCapabilityFeatureEXT>{});
  });
}

// ---- contexts

XrResult XRAPI_CALL xrCreateSpatialContextAsyncEXT(XrSession session, const XrSpatialContextCreateInfoEXT* createInfo,
                                                   XrFutureEXT* future) {
  return guarded("xrCreateSpatialContextAsyncEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    const InstanceState* instance = instance_of_session(id_of(session));
    if (instance == nullptr || !instance->has(XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME)) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!has_type(createInfo, XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT) || future == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->capabilityConfigCount == 0 || createInfo->capabilityConfigs == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    auto request = std::make_shared<ContextRequest>();
    std::vector<XrSpatialCapabilityEXT> seen;
    for (uint32_t i = 0; i < createInfo->capabilityConfigCount; ++i) {
      const XrSpatialCapabilityConfigurationBaseHeaderEXT* config = createInfo->capabilityConfigs[i];
      if (config == nullptr) return XR_ERROR_VALIDATION_FAILURE;
      if (config->capability != XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT || !offers_planes(*instance))
        return XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT;
      if (config->type != XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT) return XR_ERROR_VALIDATION_FAILURE;
      if (std::find(seen.begin(), seen.end(), config->capability) != seen.end())
        return XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT;  // one configuration per capability
      seen.push_back(config->capability);
      if (config->enabledComponentCount == 0 || config->enabledComponents == nullptr)
        return XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT;
      for (uint32_t c = 0; c < config->enabledComponentCount; ++c) {
        const Component component = config->enabledComponents[c];
        if (!contains(kPlaneComponents, component)) return XR_ERROR_SPATIAL_COMPONENT_UNSUPPORTED_FOR_CAPABILITY_EXT;
        if (!contains(request->components, component)) request->components.push_back(component);
      }
    }
    *future = make_future(runtime().session(session)->instance, id_of(session), kContextFuture,
                          faults::future_delay(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME,
                                               std::chrono::milliseconds(instance->config.compute_delay_ms)),
                          request);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCreateSpatialContextCompleteEXT(XrSession session, XrFutureEXT future,
                                                      XrCreateSpatialContextCompletionEXT* completion) {
  return guarded("xrCreateSpatialContextCompleteEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SessionState* owner = runtime().session(session);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(completion, XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    std::shared_ptr<const void> result;
    if (XrResult r = take_future(future, id_of(session), kContextFuture, result); r != XR_SUCCESS) return r;
    const auto& request = *static_cast<const ContextRequest*>(result.get());
    const std::uint64_t id = runtime().new_id();
    state().contexts[id] = Context{id_of(session), owner->instance, request.components};
    completion->futureResult = XR_SUCCESS;
    completion->spatialContext = handle_of<XrSpatialContextEXT>(id);
    // The room is there to discover: say so once, as a device does when its first scan is ready.
    if (InstanceState* instance = Runtime::find(runtime().instances, owner->instance)) {
      XrEventDataSpatialDiscoveryRecommendedEXT event{};
      event.type = XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT;
      event.spatialContext = completion->spatialContext;
      XrEventDataBuffer buffer{};
      static_assert(sizeof event <= sizeof buffer);
      std::memcpy(static_cast<void*>(&buffer), &event, sizeof event);
      instance->extension_events.push_back(buffer);
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySpatialContextEXT(XrSpatialContextEXT spatialContext) {
  return guarded("xrDestroySpatialContextEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (state().contexts.count(id_of(spatialContext)) == 0) return XR_ERROR_HANDLE_INVALID;
    destroy_context(id_of(spatialContext));
    return XR_SUCCESS;
  });
}

// ---- snapshots

XrResult XRAPI_CALL xrCreateSpatialDiscoverySnapshotAsyncEXT(XrSpatialContextEXT spatialContext,
                                                             const XrSpatialDiscoverySnapshotCreateInfoEXT* createInfo,
                                                             XrFutureEXT* future) {
  return guarded("xrCreateSpatialDiscoverySnapshotAsyncEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().contexts.find(id_of(spatialContext));
    if (it == state().contexts.end()) return XR_ERROR_HANDLE_INVALID;
    const Context& context = it->second;
    if (!has_type(createInfo, XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT) || future == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->componentTypeCount > 0 && createInfo->componentTypes == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    auto request = std::make_shared<DiscoveryRequest>();
    request->context = id_of(spatialContext);
    for (uint32_t i = 0; i < createInfo->componentTypeCount; ++i) {
      if (!contains(context.components, createInfo->componentTypes[i])) return XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT;
      if (!contains(request->components, createInfo->componentTypes[i])) request->components.push_back(createInfo->componentTypes[i]);
    }
    if (request->components.empty()) request->components = context.components;  // none named: every enabled one
    if (const auto* filter = find_next<const XrSpatialFilterTrackingStateEXT>(createInfo->next, XR_TYPE_SPATIAL_FILTER_TRACKING_STATE_EXT))
      request->filter = filter->trackingState;
    const InstanceState* instance = Runtime::find(runtime().instances, context.instance);
    const int delay = instance ? instance->config.compute_delay_ms : 0;
    *future = make_future(context.instance, context.session, kSnapshotFuture,
                          faults::future_delay(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME, std::chrono::milliseconds(delay)), request);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCreateSpatialDiscoverySnapshotCompleteEXT(XrSpatialContextEXT spatialContext,
                                                                const XrCreateSpatialDiscoverySnapshotCompletionInfoEXT* info,
                                                                XrCreateSpatialDiscoverySnapshotCompletionEXT* completion) {
  return guarded("xrCreateSpatialDiscoverySnapshotCompleteEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().contexts.find(id_of(spatialContext));
    if (it == state().contexts.end()) return XR_ERROR_HANDLE_INVALID;
    const Context context = it->second;
    if (!has_type(info, XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT) ||
        !has_type(completion, XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT))
      return XR_ERROR_VALIDATION_FAILURE;
    Snapshot snapshot;
    if (XrResult r = resolve_base(info->baseSpace, info->time, context.session, snapshot.world_to_base); r != XR_SUCCESS) return r;
    std::shared_ptr<const void> result;
    if (XrResult r = take_future(info->future, context.session, kSnapshotFuture, result); r != XR_SUCCESS) return r;
    const auto& request = *static_cast<const DiscoveryRequest*>(result.get());
    if (request.context != id_of(spatialContext)) return XR_ERROR_FUTURE_INVALID_EXT;  // another context's future
    const InstanceState* instance = Runtime::find(runtime().instances, context.instance);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    snapshot.context = id_of(spatialContext);
    snapshot.session = context.session;
    snapshot.planes = planes_of(*instance);
    snapshot.components = request.components;
    // Every plane is tracked; a filter for another state finds nothing.
    if (!request.filter || *request.filter == XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT)
      for (std::size_t i = 0; i < snapshot.planes->planes.size(); ++i) snapshot.entities.push_back(i);
    const std::uint64_t id = runtime().new_id();
    state().snapshots.emplace(id, std::move(snapshot));
    completion->futureResult = XR_SUCCESS;
    completion->snapshot = handle_of<XrSpatialSnapshotEXT>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrQuerySpatialComponentDataEXT(XrSpatialSnapshotEXT snapshot, const XrSpatialComponentDataQueryConditionEXT* condition,
                                                   XrSpatialComponentDataQueryResultEXT* result) {
  return guarded("xrQuerySpatialComponentDataEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().snapshots.find(id_of(snapshot));
    if (it == state().snapshots.end()) return XR_ERROR_HANDLE_INVALID;
    const Snapshot& s = it->second;
    if (!has_type(condition, XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT) ||
        !has_type(result, XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT))
      return XR_ERROR_VALIDATION_FAILURE;
    if (condition->componentTypeCount > 0 && condition->componentTypes == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const auto context = state().contexts.find(s.context);
    if (context == state().contexts.end()) return XR_ERROR_HANDLE_INVALID;
    const std::vector<Component> wanted(condition->componentTypes, condition->componentTypes + condition->componentTypeCount);
    for (Component c : wanted)
      if (!contains(context->second.components, c)) return XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT;

    // The component lists chained on the result; each must be one the condition names.
    const auto [bounds, alignments, polygons, meshes, labels, lists] = xr::plane_component_lists(result->next);
    if (const XrResult r = xr::lists_named(lists, wanted, result->next,
                                           {XR_TYPE_SPATIAL_COMPONENT_BOUNDED_3D_LIST_EXT, XR_TYPE_SPATIAL_COMPONENT_PARENT_LIST_EXT,
                                            XR_TYPE_SPATIAL_COMPONENT_MESH_3D_LIST_EXT});
        r != XR_SUCCESS)
      return r;

    // Every plane has every plane component: an entity matches when the snapshot holds all the condition names.
    std::vector<std::size_t> matches;
    const auto* filter = find_next<const XrSpatialFilterTrackingStateEXT>(condition->next, XR_TYPE_SPATIAL_FILTER_TRACKING_STATE_EXT);
    const bool held = std::all_of(wanted.begin(), wanted.end(), [&](Component c) { return contains(s.components, c); });
    if (held && (filter == nullptr || filter->trackingState == XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT)) matches = s.entities;
    const auto n = static_cast<uint32_t>(matches.size());

    if ((result->entityIdCapacityInput > 0 && result->entityIds == nullptr) ||
        (result->entityStateCapacityInput > 0 && result->entityStates == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    result->entityIdCountOutput = n;
    result->entityStateCountOutput = n;
    if (result->entityIdCapacityInput == 0) return XR_SUCCESS;
    if (result->entityIdCapacityInput < n || (result->entityStateCapacityInput > 0 && result->entityStateCapacityInput < n))
      return XR_ERROR_SIZE_INSUFFICIENT;
    if (const XrResult r = xr::lists_fit(lists, n); r != XR_SUCCESS) return r;
    for (uint32_t i = 0; i < n; ++i) {
      const std::size_t index = matches[i];
      const ServedPlane& plane = s.planes->planes[index];
      const XrPosef pose = base_pose(s, plane);
      result->entityIds[i] = static_cast<XrSpatialEntityIdEXT>(index + 1);
      if (result->entityStateCapacityInput > 0) result->entityStates[i] = XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT;
      if (bounds) bounds->bounds[i] = {pose, plane.extents};
      if (alignments) alignments->planeAlignments[i] = plane.alignment;
      if (polygons) polygons->polygons[i] = {pose, {buffer_id(index, kPolygon), XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT}};
      if (meshes)
        meshes->meshes[i] = {pose, {buffer_id(index, kMeshVertices), XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT},
                             {buffer_id(index, kMeshIndices), buffer_type(plane, kMeshIndices)}};
      if (labels) labels->semanticLabels[i] = plane.label;
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySpatialSnapshotEXT(XrSpatialSnapshotEXT snapshot) {
  return guarded("xrDestroySpatialSnapshotEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    return state().snapshots.erase(id_of(snapshot)) == 1 ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
  });
}

// ---- buffers

XrResult XRAPI_CALL xrGetSpatialBufferStringEXT(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, char* b) {
  return get_buffer("xrGetSpatialBufferStringEXT", s, i, c, n, b);
}
XrResult XRAPI_CALL xrGetSpatialBufferUint8EXT(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, uint8_t* b) {
  return get_buffer("xrGetSpatialBufferUint8EXT", s, i, c, n, b);
}
XrResult XRAPI_CALL xrGetSpatialBufferUint16EXT(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, uint16_t* b) {
  return get_buffer("xrGetSpatialBufferUint16EXT", s, i, c, n, b);
}
XrResult XRAPI_CALL xrGetSpatialBufferUint32EXT(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, uint32_t* b) {
  return get_buffer("xrGetSpatialBufferUint32EXT", s, i, c, n, b);
}
XrResult XRAPI_CALL xrGetSpatialBufferFloatEXT(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, float* b) {
  return get_buffer("xrGetSpatialBufferFloatEXT", s, i, c, n, b);
}
XrResult XRAPI_CALL xrGetSpatialBufferVector2fEXT(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, XrVector2f* b) {
  return get_buffer("xrGetSpatialBufferVector2fEXT", s, i, c, n, b);
}
XrResult XRAPI_CALL xrGetSpatialBufferVector3fEXT(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, XrVector3f* b) {
  return get_buffer("xrGetSpatialBufferVector3fEXT", s, i, c, n, b);
}

// ---- entities and update snapshots

XrResult XRAPI_CALL xrCreateSpatialEntityFromIdEXT(XrSpatialContextEXT spatialContext, const XrSpatialEntityFromIdCreateInfoEXT* createInfo,
                                                   XrSpatialEntityEXT* spatialEntity) {
  return guarded("xrCreateSpatialEntityFromIdEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().contexts.find(id_of(spatialContext));
    if (it == state().contexts.end()) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_SPATIAL_ENTITY_FROM_ID_CREATE_INFO_EXT) || spatialEntity == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    const InstanceState* instance = Runtime::find(runtime().instances, it->second.instance);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    const std::uint64_t entity = static_cast<std::uint64_t>(createInfo->entityId);
    if (entity == XR_NULL_SPATIAL_ENTITY_ID_EXT || entity > planes_of(*instance)->planes.size())
      return XR_ERROR_SPATIAL_ENTITY_ID_INVALID_EXT;
    const std::uint64_t id = runtime().new_id();
    state().entities[id] = Entity{id_of(spatialContext), it->second.session, static_cast<std::size_t>(entity - 1)};
    *spatialEntity = handle_of<XrSpatialEntityEXT>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySpatialEntityEXT(XrSpatialEntityEXT spatialEntity) {
  return guarded("xrDestroySpatialEntityEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    return state().entities.erase(id_of(spatialEntity)) == 1 ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
  });
}

XrResult XRAPI_CALL xrCreateSpatialUpdateSnapshotEXT(XrSpatialContextEXT spatialContext, const XrSpatialUpdateSnapshotCreateInfoEXT* createInfo,
                                                     XrSpatialSnapshotEXT* snapshot) {
  return guarded("xrCreateSpatialUpdateSnapshotEXT", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().contexts.find(id_of(spatialContext));
    if (it == state().contexts.end()) return XR_ERROR_HANDLE_INVALID;
    const Context& context = it->second;
    if (!has_type(createInfo, XR_TYPE_SPATIAL_UPDATE_SNAPSHOT_CREATE_INFO_EXT) || snapshot == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->entityCount == 0 || createInfo->entities == nullptr ||
        (createInfo->componentTypeCount > 0 && createInfo->componentTypes == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    Snapshot s;
    for (uint32_t i = 0; i < createInfo->componentTypeCount; ++i) {
      if (!contains(context.components, createInfo->componentTypes[i])) return XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT;
      if (!contains(s.components, createInfo->componentTypes[i])) s.components.push_back(createInfo->componentTypes[i]);
    }
    if (s.components.empty()) s.components = context.components;
    for (uint32_t i = 0; i < createInfo->entityCount; ++i) {
      const auto entity = state().entities.find(id_of(createInfo->entities[i]));
      if (entity == state().entities.end() || entity->second.context != id_of(spatialContext)) return XR_ERROR_HANDLE_INVALID;
      if (std::find(s.entities.begin(), s.entities.end(), entity->second.plane) == s.entities.end())
        s.entities.push_back(entity->second.plane);
    }
    if (XrResult r = resolve_base(createInfo->baseSpace, createInfo->time, context.session, s.world_to_base); r != XR_SUCCESS) return r;
    const InstanceState* instance = Runtime::find(runtime().instances, context.instance);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    s.context = id_of(spatialContext);
    s.session = context.session;
    s.planes = planes_of(*instance);
    const std::uint64_t id = runtime().new_id();
    state().snapshots.emplace(id, std::move(s));
    *snapshot = handle_of<XrSpatialSnapshotEXT>(id);
    return XR_SUCCESS;
  });
}

// A session's contexts (with their snapshots, entities and pending events) go with it.
void forget_session(std::uint64_t session) {
  std::lock_guard lock(runtime().mutex);
  std::vector<std::uint64_t> gone;
  for (const auto& [id, context] : state().contexts)
    if (context.session == session) gone.push_back(id);
  for (std::uint64_t id : gone) destroy_context(id);
  std::erase_if(state().snapshots, [&](const auto& e) { return e.second.session == session; });
  std::erase_if(state().entities, [&](const auto& e) { return e.second.session == session; });
}

// With no context left, the extracted planes are let go (the room cache keeps the rooms themselves).
void forget_instance(std::uint64_t) {
  std::lock_guard lock(runtime().mutex);
  if (state().contexts.empty()) state().planes.clear();
}

}  // namespace

#define SIM_SERVE(name) ServedFunction{#name, reinterpret_cast<PFN_xrVoidFunction>(&name)},

const ServedExtension& ext_spatial_entity_extension() {
  static const ServedExtension e{
      XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME,
      XR_EXT_spatial_entity_SPEC_VERSION,
      true,
      {SIM_SERVE(xrEnumerateSpatialCapabilitiesEXT) SIM_SERVE(xrEnumerateSpatialCapabilityComponentTypesEXT)
           SIM_SERVE(xrEnumerateSpatialCapabilityFeaturesEXT) SIM_SERVE(xrCreateSpatialContextAsyncEXT)
               SIM_SERVE(xrCreateSpatialContextCompleteEXT) SIM_SERVE(xrDestroySpatialContextEXT)
                   SIM_SERVE(xrCreateSpatialDiscoverySnapshotAsyncEXT) SIM_SERVE(xrCreateSpatialDiscoverySnapshotCompleteEXT)
                       SIM_SERVE(xrQuerySpatialComponentDataEXT) SIM_SERVE(xrDestroySpatialSnapshotEXT)
                           SIM_SERVE(xrCreateSpatialEntityFromIdEXT) SIM_SERVE(xrDestroySpatialEntityEXT)
                               SIM_SERVE(xrCreateSpatialUpdateSnapshotEXT) SIM_SERVE(xrGetSpatialBufferStringEXT)
                                   SIM_SERVE(xrGetSpatialBufferUint8EXT) SIM_SERVE(xrGetSpatialBufferUint16EXT)
                                       SIM_SERVE(xrGetSpatialBufferUint32EXT) SIM_SERVE(xrGetSpatialBufferFloatEXT)
                                           SIM_SERVE(xrGetSpatialBufferVector2fEXT) SIM_SERVE(xrGetSpatialBufferVector3fEXT)},
      &forget_session,
      &forget_instance};
  return e;
}

const ServedExtension& ext_spatial_plane_tracking_extension() {
  static const ServedExtension e{XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME,
                                 XR_EXT_spatial_plane_tracking_SPEC_VERSION,
                                 true,
                                 {},
                                 nullptr,
                                 nullptr,
                                 {XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME}};
  return e;
}

#undef SIM_SERVE

}  // namespace roomsense::sim
