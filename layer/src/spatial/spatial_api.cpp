// XR_EXT_spatial_entity served by the layer (spatial_instance.h says when): capabilities, contexts, discovery
// and update snapshots, component queries, buffers, entities from ids, and the futures of the layer's own
// asynchronous calls. A handle, future or capability that is not the layer's goes on down the chain
// untouched. The layer's handles are values the runtime cannot hand out (kHandleBase: not a canonical address
// and far above any counter), kept in one table behind a mutex; the data come from the session's
// SpatialService, whose entity sets are immutable once published.
#include "../functions.h"
#include "../guard.h"
#include "../log.h"
#include "../state.h"
#include "spatial_api.h"
#include "spatial_instance.h"
#include "spatial_service.h"

#include "roomsense/platform.h"
#include "roomsense/xr/spatial_query.h"

#include <algorithm>
#include <cstring>
#include <mutex>
#include <optional>
#include <type_traits>
#include <unordered_map>
#include <variant>

namespace roomsense::layer {
namespace {

using Component = XrSpatialComponentTypeEXT;
using Capability = XrSpatialCapabilityEXT;

constexpr std::uint64_t kHandleBase = 0x5253'0000'0000'0000ull;  // "RS"
constexpr std::size_t kMaxObjects = 1u << 16;                    // live handles of the layer's, all kinds together

const std::vector<Component> kPlaneComponents = {
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT,
    XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT,
    XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT, XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX};
const std::vector<Component> kPlacementComponents = {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT,
                                                     XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX,
                                                     XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT,
                                                     XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX};

enum BufferKind : std::uint64_t { kPolygon = 1, kMeshVertices = 2, kMeshIndices = 3 };

bool contains(const std::vector<Component>& list, Component c) { return std::find(list.begin(), list.end(), c) != list.end(); }

struct ContextObject {
  std::shared_ptr<SessionState> session;
  std::shared_ptr<SpatialService> service;
  std::vector<Capability> capabilities;
  std::vector<Component> components;  // enabled, over all capabilities
  std::uint64_t recommended = 0;      // the service's published() it last recommended a discovery for
};

struct SnapshotObject {
  std::uint64_t context = 0;
  std::shared_ptr<const EntitySet> set;
  std::vector<XrSpatialEntityIdEXT> ids;  // held, in order
  std::vector<Component> components;
  Rigid analysis_to_base;
  bool located = true;
};

struct EntityObject {
  std::uint64_t context = 0;
  XrSpatialEntityIdEXT id = XR_NULL_SPATIAL_ENTITY_ID_EXT;
};

struct ContextFuture {
  std::shared_ptr<SessionState> session;
  std::shared_ptr<SpatialService> service;
  std::vector<Capability> capabilities;
  std::vector<Component> components;
};

struct DiscoveryFuture {
  std::uint64_t context = 0;
  std::vector<Component> components;
  std::optional<XrSpatialEntityTrackingStateEXT> filter;
};

// One of the two (held by pointer: cheap to move in and out of the table).
struct FutureObject {
  XrInstance instance = XR_NULL_HANDLE;
  std::shared_ptr<const ContextFuture> context;
  std::shared_ptr<const DiscoveryFuture> discovery;
};

using Object = std::variant<ContextObject, SnapshotObject, EntityObject, FutureObject>;

struct Objects {
  std::mutex mutex;
  std::unordered_map<std::uint64_t, Object> live;
  std::uint64_t next = kHandleBase + 1;

  template <typename T>
  T* find(std::uint64_t handle) {
    const auto it = live.find(handle);
    return it == live.end() ? nullptr : std::get_if<T>(&it->second);
  }
  template <typename T>
  std::uint64_t add(T&& object) {
    if (live.size() >= kMaxObjects) return 0;
    const std::uint64_t handle = next++;
    live.emplace(handle, std::forward<T>(object));
    return handle;
  }
};

Objects& objects() {
  static platform::ProcessWide<Objects> o;  // its contexts' services own threads: platform::ProcessWide says why
  return o.value;
}

template <typename H>
std::uint64_t raw(H handle) {
  if constexpr (std::is_pointer_v<H>) return reinterpret_cast<std::uint64_t>(handle);
  else return static_cast<std::uint64_t>(handle);
}
template <typename H>
H handle_of(std::uint64_t value) {
  if constexpr (std::is_pointer_v<H>) return reinterpret_cast<H>(value);
  else return static_cast<H>(value);
}
template <typename H>
bool is_ours(H handle) {
  const std::uint64_t v = raw(handle);
  return v > kHandleBase && v < kHandleBase + (1ull << 40);
}

// A call not for the layer: passed on where something below has the function.
template <typename PFN, typename... Args>
XrResult pass_on(PFN next, XrResult otherwise, Args... args) {
  return next != nullptr ? next(args...) : otherwise;
}

// Which instance a foreign handle of a child object belongs to cannot be known without the runtime: every
// instance with the layer's spatial state shares one way down per function, so take the first such instance's
// (they all lead to the same runtime).
template <typename PFN>
PFN forward_any(PFN SpatialInstance::Forward::*member) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  for (const auto& [handle, instance] : r.instances)
    if (instance->spatial && instance->spatial->forward.*member != nullptr) return instance->spatial->forward.*member;
  return nullptr;
}

std::vector<Component> components_for(const SpatialInstance& spatial, Capability capability) {
  if (capability == XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT && spatial.planes) return kPlaneComponents;
  if (capability == XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX) return kPlacementComponents;
  return {};
}

XrStructureType config_type(Capability capability) {
  return capability == XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT ? XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT
                                                                : XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLACEMENT_AREAS_EXTX;
}

// The runtime's components for its own plane tracking, or nothing when it has none.
std::vector<Component> runtime_plane_components(const InstanceState& instance, XrSystemId system) {
  const SpatialInstance& spatial = *instance.spatial;
  if (spatial.planes || spatial.forward.xrEnumerateSpatialCapabilityComponentTypesEXT == nullptr) return {};
  auto list = xr_struct<XrSpatialCapabilityComponentTypesEXT>(XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT);
  if (XR_FAILED(spatial.forward.xrEnumerateSpatialCapabilityComponentTypesEXT(instance.handle, system,
                                                                             XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, &list)))
    return {};
  std::vector<Component> out(std::min<std::uint32_t>(list.componentTypeCountOutput, 64));
  list.componentTypeCapacityInput = static_cast<std::uint32_t>(out.size());
  list.componentTypes = out.data();
  if (XR_FAILED(spatial.forward.xrEnumerateSpatialCapabilityComponentTypesEXT(instance.handle, system,
                                                                             XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, &list)))
    return {};
  out.resize(std::min<std::size_t>(out.size(), list.componentTypeCountOutput));
  return out;
}

std::shared_ptr<SpatialService> service_of(const std::shared_ptr<SessionState>& session) {
  std::lock_guard lock(session->mutex);
  if (!session->spatial) session->spatial = std::make_shared<SpatialService>(session);
  return session->spatial;
}

std::uint64_t buffer_id(XrSpatialEntityIdEXT entity, BufferKind kind) { return (static_cast<std::uint64_t>(entity) << 2) | kind; }

// Where the analysis's space is in `base` at `time`.
XrResult locate(const SessionState& session, XrSpace analysis, XrSpace base, XrTime time, Rigid& out, bool& located) {
  auto where = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
  const XrResult r = session.instance->next.xrLocateSpace(analysis, base, time, &where);
  if (XR_FAILED(r)) return r;
  constexpr XrSpaceLocationFlags kBoth = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
  located = (where.locationFlags & kBoth) == kBoth;
  out = located ? to_rigid(where.pose) : Rigid{};
  return XR_SUCCESS;
}

XrSpatialEntityTrackingStateEXT state_in(const SnapshotObject& s, const ServedEntity* e) {
  if (e == nullptr) return XR_SPATIAL_ENTITY_TRACKING_STATE_STOPPED_EXT;
  return s.located ? XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT : XR_SPATIAL_ENTITY_TRACKING_STATE_PAUSED_EXT;
}

bool holds_any(const ServedEntity& e, const std::vector<Component>& components) {
  return std::any_of(components.begin(), components.end(), [&](Component c) { return e.has(c); });
}

}  // namespace

// ---- capabilities

XrResult XRAPI_CALL xrEnumerateSpatialCapabilitiesEXT(XrInstance instance, XrSystemId systemId, uint32_t capacity,
                                                      uint32_t* countOutput, XrSpatialCapabilityEXT* capabilities) {
  return guarded("xrEnumerateSpatialCapabilitiesEXT", [&]() -> XrResult {
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state || !state->spatial) return XR_ERROR_HANDLE_INVALID;
    if (systemId == XR_NULL_SYSTEM_ID) return XR_ERROR_SYSTEM_INVALID;
    const SpatialInstance& spatial = *state->spatial;
    std::vector<Capability> list;
    if (const auto next = spatial.forward.xrEnumerateSpatialCapabilitiesEXT; next != nullptr) {
      list = xr::read_two_call<Capability>(
          "xrEnumerateSpatialCapabilitiesEXT",
          [&](std::uint32_t cap, std::uint32_t* n, Capability* out) { return next(instance, systemId, cap, n, out); }, 1024);
    }
    if (spatial.planes && std::find(list.begin(), list.end(), XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT) == list.end())
      list.push_back(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT);
    list.push_back(XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX);
    return xr::two_call(capacity, countOutput, capabilities, list);
  });
}

XrResult XRAPI_CALL xrEnumerateSpatialCapabilityComponentTypesEXT(XrInstance instance, XrSystemId systemId,
                                                                  XrSpatialCapabilityEXT capability,
                                                                  XrSpatialCapabilityComponentTypesEXT* components) {
  return guarded("xrEnumerateSpatialCapabilityComponentTypesEXT", [&]() -> XrResult {
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state || !state->spatial) return XR_ERROR_HANDLE_INVALID;
    const std::vector<Component> ours = components_for(*state->spatial, capability);
    if (ours.empty())
      return pass_on(state->spatial->forward.xrEnumerateSpatialCapabilityComponentTypesEXT,
                     XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT, instance, systemId, capability, components);
    if (systemId == XR_NULL_SYSTEM_ID) return XR_ERROR_SYSTEM_INVALID;
    if (!has_type(components, XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    return xr::two_call(components->componentTypeCapacityInput, &components->componentTypeCountOutput,
                        components->componentTypes, ours);
  });
}

XrResult XRAPI_CALL xrEnumerateSpatialCapabilityFeaturesEXT(XrInstance instance, XrSystemId systemId,
                                                            XrSpatialCapabilityEXT capability, uint32_t capacity,
                                                            uint32_t* countOutput, XrSpatialCapabilityFeatureEXT* features) {
  return guarded("xrEnumerateSpatialCapabilityFeaturesEXT", [&]() -> XrResult {
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state || !state->spatial) return XR_ERROR_HANDLE_INVALID;
    if (components_for(*state->spatial, capability).empty())
      return pass_on(state->spatial->forward.xrEnumerateSpatialCapabilityFeaturesEXT, XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT,
                     instance, systemId, capability, capacity, countOutput, features);
    if (systemId == XR_NULL_SYSTEM_ID) return XR_ERROR_SYSTEM_INVALID;
    return xr::two_call(capacity, countOutput, features, std::vector<XrSpatialCapabilityFeatureEXT>{});
  });
}

// ---- contexts

XrResult XRAPI_CALL xrCreateSpatialContextAsyncEXT(XrSession session, const XrSpatialContextCreateInfoEXT* createInfo,
                                                   XrFutureEXT* future) {
  return guarded("xrCreateSpatialContextAsyncEXT", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s || !s->instance->spatial) return XR_ERROR_HANDLE_INVALID;
    const SpatialInstance& spatial = *s->instance->spatial;
    if (!has_type(createInfo, XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT) || future == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->capabilityConfigCount == 0 || createInfo->capabilityConfigs == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    // The layer's context when it asks for a capability the layer serves, or for plane-tracking components the
    // runtime's own plane tracking lacks; otherwise the runtime's.
    bool ours = false;
    std::vector<Component> runtime_planes;
    bool runtime_planes_read = false;
    for (uint32_t i = 0; i < createInfo->capabilityConfigCount; ++i) {
      const XrSpatialCapabilityConfigurationBaseHeaderEXT* config = createInfo->capabilityConfigs[i];
      if (config == nullptr) return XR_ERROR_VALIDATION_FAILURE;
      if (!components_for(spatial, config->capability).empty()) ours = true;
      if (config->capability == XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT && !spatial.planes && config->enabledComponents != nullptr) {
        if (!runtime_planes_read) runtime_planes = runtime_plane_components(*s->instance, s->system), runtime_planes_read = true;
        for (uint32_t c = 0; c < config->enabledComponentCount; ++c)
          if (!contains(runtime_planes, config->enabledComponents[c]) && contains(kPlaneComponents, config->enabledComponents[c]))
            ours = true;
      }
    }
    if (!ours)
      return pass_on(spatial.forward.xrCreateSpatialContextAsyncEXT, XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT, session,
                     createInfo, future);
    if (s->lost.load()) return XR_ERROR_SESSION_LOST;

    ContextFuture request;
    request.session = s;
    for (uint32_t i = 0; i < createInfo->capabilityConfigCount; ++i) {
      const XrSpatialCapabilityConfigurationBaseHeaderEXT* config = createInfo->capabilityConfigs[i];
      const Capability capability = config->capability;
      std::vector<Component> offered = components_for(spatial, capability);
      if (capability == XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT) offered = kPlaneComponents;  // served by the layer here
      if (offered.empty()) {
        log_warn("xrCreateSpatialContextAsyncEXT: a context of the layer's capabilities cannot also hold the runtime's; "
                 "create one context for each");
        return XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT;
      }
      if (config->type != config_type(capability)) return XR_ERROR_VALIDATION_FAILURE;
      if (std::find(request.capabilities.begin(), request.capabilities.end(), capability) != request.capabilities.end())
        return XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT;  // one configuration per capability
      request.capabilities.push_back(capability);
      if (config->enabledComponentCount == 0 || config->enabledComponents == nullptr)
        return XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT;
      for (uint32_t c = 0; c < config->enabledComponentCount; ++c) {
        const Component component = config->enabledComponents[c];
        if (!contains(offered, component)) return XR_ERROR_SPATIAL_COMPONENT_UNSUPPORTED_FOR_CAPABILITY_EXT;
        if (!contains(request.components, component)) request.components.push_back(component);
      }
    }
    // The analysis starts now, off the application's thread; the context itself is ready at once.
    request.service = service_of(s);
    request.service->context_created();
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const std::uint64_t handle = o.add(FutureObject{s->instance->handle, std::make_shared<const ContextFuture>(std::move(request)), nullptr});
    if (handle == 0) return XR_ERROR_LIMIT_REACHED;
    *future = handle_of<XrFutureEXT>(handle);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCreateSpatialContextCompleteEXT(XrSession session, XrFutureEXT future,
                                                      XrCreateSpatialContextCompletionEXT* completion) {
  return guarded("xrCreateSpatialContextCompleteEXT", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s || !s->instance->spatial) return XR_ERROR_HANDLE_INVALID;
    if (!is_ours(future))
      return pass_on(s->instance->spatial->forward.xrCreateSpatialContextCompleteEXT, XR_ERROR_FUTURE_INVALID_EXT, session,
                     future, completion);
    if (!has_type(completion, XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    FutureObject* f = o.find<FutureObject>(raw(future));
    const ContextFuture* request = f == nullptr ? nullptr : f->context.get();
    if (request == nullptr || request->session != s) return XR_ERROR_FUTURE_INVALID_EXT;
    ContextObject context{request->session, request->service, request->capabilities, request->components, 0};
    o.live.erase(raw(future));
    const std::uint64_t handle = o.add(std::move(context));
    if (handle == 0) return XR_ERROR_LIMIT_REACHED;
    completion->futureResult = XR_SUCCESS;
    completion->spatialContext = handle_of<XrSpatialContextEXT>(handle);
    return XR_SUCCESS;
  });
}

namespace {

// A context's snapshots and entities go with it; its service hears of it.
void destroy_context_locked(Objects& o, std::uint64_t handle) {
  ContextObject* c = o.find<ContextObject>(handle);
  if (c == nullptr) return;
  c->service->context_destroyed();
  std::erase_if(o.live, [&](const auto& e) {
    if (const auto* s = std::get_if<SnapshotObject>(&e.second)) return s->context == handle;
    if (const auto* n = std::get_if<EntityObject>(&e.second)) return n->context == handle;
    if (const auto* f = std::get_if<FutureObject>(&e.second))
      return f->discovery && f->discovery->context == handle;
    return false;
  });
  o.live.erase(handle);
}

}  // namespace

XrResult XRAPI_CALL xrDestroySpatialContextEXT(XrSpatialContextEXT spatialContext) {
  return guarded("xrDestroySpatialContextEXT", [&]() -> XrResult {
    if (!is_ours(spatialContext))
      return pass_on(forward_any(&SpatialInstance::Forward::xrDestroySpatialContextEXT), XR_ERROR_HANDLE_INVALID, spatialContext);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    if (o.find<ContextObject>(raw(spatialContext)) == nullptr) return XR_ERROR_HANDLE_INVALID;
    destroy_context_locked(o, raw(spatialContext));
    return XR_SUCCESS;
  });
}

// ---- discovery snapshots

XrResult XRAPI_CALL xrCreateSpatialDiscoverySnapshotAsyncEXT(XrSpatialContextEXT spatialContext,
                                                             const XrSpatialDiscoverySnapshotCreateInfoEXT* createInfo,
                                                             XrFutureEXT* future) {
  return guarded("xrCreateSpatialDiscoverySnapshotAsyncEXT", [&]() -> XrResult {
    if (!is_ours(spatialContext))
      return pass_on(forward_any(&SpatialInstance::Forward::xrCreateSpatialDiscoverySnapshotAsyncEXT), XR_ERROR_HANDLE_INVALID,
                     spatialContext, createInfo, future);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const ContextObject* c = o.find<ContextObject>(raw(spatialContext));
    if (c == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT) || future == nullptr ||
        (createInfo->componentTypeCount > 0 && createInfo->componentTypes == nullptr))
      return XR_ERROR_VALIDATION_FAILURE;
    DiscoveryFuture request;
    request.context = raw(spatialContext);
    for (uint32_t i = 0; i < createInfo->componentTypeCount; ++i) {
      if (!contains(c->components, createInfo->componentTypes[i])) return XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT;
      if (!contains(request.components, createInfo->componentTypes[i])) request.components.push_back(createInfo->componentTypes[i]);
    }
    if (request.components.empty()) request.components = c->components;
    if (const auto* filter = find_next<const XrSpatialFilterTrackingStateEXT>(createInfo->next, XR_TYPE_SPATIAL_FILTER_TRACKING_STATE_EXT))
      request.filter = filter->trackingState;
    const std::uint64_t handle = o.add(FutureObject{c->session->instance->handle, nullptr, std::make_shared<const DiscoveryFuture>(std::move(request))});
    if (handle == 0) return XR_ERROR_LIMIT_REACHED;
    *future = handle_of<XrFutureEXT>(handle);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCreateSpatialDiscoverySnapshotCompleteEXT(XrSpatialContextEXT spatialContext,
                                                                const XrCreateSpatialDiscoverySnapshotCompletionInfoEXT* info,
                                                                XrCreateSpatialDiscoverySnapshotCompletionEXT* completion) {
  return guarded("xrCreateSpatialDiscoverySnapshotCompleteEXT", [&]() -> XrResult {
    if (!is_ours(spatialContext))
      return pass_on(forward_any(&SpatialInstance::Forward::xrCreateSpatialDiscoverySnapshotCompleteEXT), XR_ERROR_HANDLE_INVALID,
                     spatialContext, info, completion);
    std::shared_ptr<SessionState> session;
    std::shared_ptr<SpatialService> service;
    DiscoveryFuture request;
    {
      Objects& o = objects();
      std::lock_guard lock(o.mutex);
      const ContextObject* c = o.find<ContextObject>(raw(spatialContext));
      if (c == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (!has_type(info, XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT) ||
          !has_type(completion, XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT))
        return XR_ERROR_VALIDATION_FAILURE;
      const FutureObject* f = o.find<FutureObject>(raw(info->future));
      const DiscoveryFuture* d = f == nullptr ? nullptr : f->discovery.get();
      if (d == nullptr || d->context != raw(spatialContext)) return XR_ERROR_FUTURE_INVALID_EXT;
      if (c->service->finished() == 0) return XR_ERROR_FUTURE_PENDING_EXT;
      session = c->session;
      service = c->service;
      request = *d;
    }
    if (info->time <= 0) return XR_ERROR_TIME_INVALID;
    SnapshotObject snapshot;
    snapshot.context = raw(spatialContext);
    snapshot.components = request.components;
    snapshot.set = service->entities();
    if (const XrResult r = locate(*session, service->space(), info->baseSpace, info->time, snapshot.analysis_to_base, snapshot.located);
        XR_FAILED(r))
      return r;
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const ContextObject* c = o.find<ContextObject>(raw(spatialContext));
    if (c == nullptr || o.find<FutureObject>(raw(info->future)) == nullptr) return XR_ERROR_FUTURE_INVALID_EXT;  // gone meanwhile
    for (const ServedEntity& e : snapshot.set->entities) {
      if (std::find(c->capabilities.begin(), c->capabilities.end(), e.capability()) == c->capabilities.end()) continue;
      if (!holds_any(e, snapshot.components)) continue;
      if (request.filter && *request.filter != state_in(snapshot, &e)) continue;
      snapshot.ids.push_back(e.id);
    }
    o.live.erase(raw(info->future));
    const std::uint64_t handle = o.add(std::move(snapshot));
    if (handle == 0) return XR_ERROR_LIMIT_REACHED;
    completion->futureResult = XR_SUCCESS;
    completion->snapshot = handle_of<XrSpatialSnapshotEXT>(handle);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrQuerySpatialComponentDataEXT(XrSpatialSnapshotEXT snapshot, const XrSpatialComponentDataQueryConditionEXT* condition,
                                                   XrSpatialComponentDataQueryResultEXT* result) {
  return guarded("xrQuerySpatialComponentDataEXT", [&]() -> XrResult {
    if (!is_ours(snapshot))
      return pass_on(forward_any(&SpatialInstance::Forward::xrQuerySpatialComponentDataEXT), XR_ERROR_HANDLE_INVALID, snapshot,
                     condition, result);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const SnapshotObject* s = o.find<SnapshotObject>(raw(snapshot));
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(condition, XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT) ||
        !has_type(result, XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT))
      return XR_ERROR_VALIDATION_FAILURE;
    if (condition->componentTypeCount > 0 && condition->componentTypes == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const ContextObject* context = o.find<ContextObject>(s->context);
    if (context == nullptr) return XR_ERROR_HANDLE_INVALID;
    const std::vector<Component> wanted(condition->componentTypes, condition->componentTypes + condition->componentTypeCount);
    for (Component c : wanted)
      if (!contains(context->components, c)) return XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT;

    // The component lists chained on the result: each must be one the condition names.
    const auto [bounds, alignments, polygons, meshes, labels, described] = xr::plane_component_lists(result->next);
    XrSpatialComponentPlacementAreaListEXTX* areas = nullptr;
    XrSpatialComponentMesh3DListEXT* rooms = nullptr;
    XrSpatialComponentRoomLocationListEXTX* locations = nullptr;
    const xr::ChainedList lists[] = {
        described[0], described[1], described[2], described[3], described[4],
        xr::chained_list(result->next, XR_TYPE_SPATIAL_COMPONENT_PLACEMENT_AREA_LIST_EXTX, XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX,
                         areas, &XrSpatialComponentPlacementAreaListEXTX::placementAreaCount,
                         &XrSpatialComponentPlacementAreaListEXTX::placementAreas),
        xr::chained_list(result->next, XR_TYPE_SPATIAL_COMPONENT_MESH_3D_LIST_EXT, XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT, rooms,
                         &XrSpatialComponentMesh3DListEXT::meshCount, &XrSpatialComponentMesh3DListEXT::meshes),
        xr::chained_list(result->next, XR_TYPE_SPATIAL_COMPONENT_ROOM_LOCATION_LIST_EXTX,
                         XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX, locations,
                         &XrSpatialComponentRoomLocationListEXTX::locationCount,
                         &XrSpatialComponentRoomLocationListEXTX::locations)};
    if (const XrResult r = xr::lists_named(lists, wanted, result->next,
                                           {XR_TYPE_SPATIAL_COMPONENT_BOUNDED_3D_LIST_EXT, XR_TYPE_SPATIAL_COMPONENT_PARENT_LIST_EXT});
        r != XR_SUCCESS)
      return r;

    // Entities of the snapshot with every component the condition names (in the tracking state it filters
    // for); one that is no longer served is listed STOPPED, with its component data zeroed.
    const auto* filter = find_next<const XrSpatialFilterTrackingStateEXT>(condition->next, XR_TYPE_SPATIAL_FILTER_TRACKING_STATE_EXT);
    std::vector<std::pair<XrSpatialEntityIdEXT, const ServedEntity*>> matches;
    for (XrSpatialEntityIdEXT id : s->ids) {
      const ServedEntity* e = s->set->find(id);
      if (e != nullptr && !std::all_of(wanted.begin(), wanted.end(), [&](Component c) { return e->has(c) && contains(s->components, c); }))
        continue;
      if (filter != nullptr && filter->trackingState != state_in(*s, e)) continue;
      matches.emplace_back(id, e);
    }
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
      const auto [id, e] = matches[i];
      result->entityIds[i] = id;
      if (result->entityStateCapacityInput > 0) result->entityStates[i] = state_in(*s, e);
      const ServedEntity none;
      const ServedEntity& entity = e != nullptr ? *e : none;
      const XrPosef pose = e != nullptr ? to_pose(s->analysis_to_base * entity.pose) : to_pose(Rigid{});
      const XrSpatialBufferIdEXT no_buffer = XR_NULL_SPATIAL_BUFFER_ID_EXT;
      if (bounds) bounds->bounds[i] = {pose, entity.extents};
      if (alignments) alignments->planeAlignments[i] = entity.alignment;
      if (polygons)
        polygons->polygons[i] = {pose, {e ? buffer_id(id, kPolygon) : no_buffer, XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT}};
      if (meshes)
        meshes->meshes[i] = {pose, {e ? buffer_id(id, kMeshVertices) : no_buffer, XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT},
                             {e ? buffer_id(id, kMeshIndices) : no_buffer, XR_SPATIAL_BUFFER_TYPE_UINT16_EXT}};
      if (labels) labels->semanticLabels[i] = entity.label;
      if (areas) areas->placementAreas[i] = entity.area;
      if (locations) locations->locations[i] = entity.location;
      if (rooms)
        rooms->meshes[i] = {pose, {e ? buffer_id(id, kMeshVertices) : no_buffer, XR_SPATIAL_BUFFER_TYPE_VECTOR3F_EXT},
                            {e ? buffer_id(id, kMeshIndices) : no_buffer, XR_SPATIAL_BUFFER_TYPE_UINT32_EXT}};
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySpatialSnapshotEXT(XrSpatialSnapshotEXT snapshot) {
  return guarded("xrDestroySpatialSnapshotEXT", [&]() -> XrResult {
    if (!is_ours(snapshot))
      return pass_on(forward_any(&SpatialInstance::Forward::xrDestroySpatialSnapshotEXT), XR_ERROR_HANDLE_INVALID, snapshot);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    if (o.find<SnapshotObject>(raw(snapshot)) == nullptr) return XR_ERROR_HANDLE_INVALID;
    o.live.erase(raw(snapshot));
    return XR_SUCCESS;
  });
}

// ---- buffers

namespace {

// The element type each buffer kind is served in, for entities of each kind.
template <typename T>
XrResult serve_buffer(const ServedEntity& e, BufferKind kind, uint32_t capacity, uint32_t* count, T* out) {
  if (e.kind == EntityKind::Plane) {
    if constexpr (std::is_same_v<T, XrVector2f>) {
      if (kind == kPolygon) return xr::two_call(capacity, count, out, e.polygon);
      if (kind == kMeshVertices) return xr::two_call(capacity, count, out, e.mesh_vertices);
    } else if constexpr (std::is_same_v<T, std::uint16_t>) {
      if (kind == kMeshIndices) return xr::two_call(capacity, count, out, e.mesh_indices);  // MESH_2D: UINT16
    }
  } else if (e.kind == EntityKind::Room) {
    if constexpr (std::is_same_v<T, XrVector3f>) {
      if (kind == kMeshVertices) return xr::two_call(capacity, count, out, e.room_vertices);
    } else if constexpr (std::is_same_v<T, std::uint32_t>) {
      if (kind == kMeshIndices) return xr::two_call(capacity, count, out, e.room_indices);
    }
  }
  return XR_ERROR_VALIDATION_FAILURE;  // a buffer of another type
}

}  // namespace

namespace {

template <typename T, typename PFN>
XrResult get_buffer(const char* function, PFN SpatialInstance::Forward::*next, XrSpatialSnapshotEXT snapshot,
                    const XrSpatialBufferGetInfoEXT* info, uint32_t capacity, uint32_t* count, T* out) {
  return guarded(function, [&]() -> XrResult {
    if (!is_ours(snapshot)) return pass_on(forward_any(next), XR_ERROR_HANDLE_INVALID, snapshot, info, capacity, count, out);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const SnapshotObject* s = o.find<SnapshotObject>(raw(snapshot));
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    // A buffer id is valid in the snapshots that hold its entity and the component it belongs to.
    const auto id = static_cast<std::uint64_t>(info->bufferId);
    const auto kind = static_cast<BufferKind>(id & 3u);
    const auto entity = static_cast<XrSpatialEntityIdEXT>(id >> 2);
    const ServedEntity* e = s->set->find(entity);
    if (kind == 0 || e == nullptr || std::find(s->ids.begin(), s->ids.end(), entity) == s->ids.end())
      return XR_ERROR_SPATIAL_BUFFER_ID_INVALID_EXT;
    const Component component = kind == kPolygon                  ? XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT
                                : e->kind == EntityKind::Room     ? XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT
                                                                  : XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT;
    if (!e->has(component) || !contains(s->components, component)) return XR_ERROR_SPATIAL_BUFFER_ID_INVALID_EXT;
    return serve_buffer<T>(*e, kind, capacity, count, out);
  });
}

}  // namespace

#define ROOMSENSE_BUFFER_GETTER(name, T)                                                                            \
  XrResult XRAPI_CALL name(XrSpatialSnapshotEXT s, const XrSpatialBufferGetInfoEXT* i, uint32_t c, uint32_t* n, T* b) { \
    return get_buffer(#name, &SpatialInstance::Forward::name, s, i, c, n, b);                                       \
  }
ROOMSENSE_BUFFER_GETTER(xrGetSpatialBufferStringEXT, char)
ROOMSENSE_BUFFER_GETTER(xrGetSpatialBufferUint8EXT, uint8_t)
ROOMSENSE_BUFFER_GETTER(xrGetSpatialBufferUint16EXT, uint16_t)
ROOMSENSE_BUFFER_GETTER(xrGetSpatialBufferUint32EXT, uint32_t)
ROOMSENSE_BUFFER_GETTER(xrGetSpatialBufferFloatEXT, float)
ROOMSENSE_BUFFER_GETTER(xrGetSpatialBufferVector2fEXT, XrVector2f)
ROOMSENSE_BUFFER_GETTER(xrGetSpatialBufferVector3fEXT, XrVector3f)
#undef ROOMSENSE_BUFFER_GETTER

// ---- entities and update snapshots

XrResult XRAPI_CALL xrCreateSpatialEntityFromIdEXT(XrSpatialContextEXT spatialContext, const XrSpatialEntityFromIdCreateInfoEXT* createInfo,
                                                   XrSpatialEntityEXT* spatialEntity) {
  return guarded("xrCreateSpatialEntityFromIdEXT", [&]() -> XrResult {
    if (!is_ours(spatialContext))
      return pass_on(forward_any(&SpatialInstance::Forward::xrCreateSpatialEntityFromIdEXT), XR_ERROR_HANDLE_INVALID,
                     spatialContext, createInfo, spatialEntity);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const ContextObject* c = o.find<ContextObject>(raw(spatialContext));
    if (c == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_SPATIAL_ENTITY_FROM_ID_CREATE_INFO_EXT) || spatialEntity == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    const ServedEntity* e = c->service->entities()->find(createInfo->entityId);
    if (e == nullptr || std::find(c->capabilities.begin(), c->capabilities.end(), e->capability()) == c->capabilities.end())
      return XR_ERROR_SPATIAL_ENTITY_ID_INVALID_EXT;
    const std::uint64_t handle = o.add(EntityObject{raw(spatialContext), createInfo->entityId});
    if (handle == 0) return XR_ERROR_LIMIT_REACHED;
    *spatialEntity = handle_of<XrSpatialEntityEXT>(handle);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySpatialEntityEXT(XrSpatialEntityEXT spatialEntity) {
  return guarded("xrDestroySpatialEntityEXT", [&]() -> XrResult {
    if (!is_ours(spatialEntity))
      return pass_on(forward_any(&SpatialInstance::Forward::xrDestroySpatialEntityEXT), XR_ERROR_HANDLE_INVALID, spatialEntity);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    if (o.find<EntityObject>(raw(spatialEntity)) == nullptr) return XR_ERROR_HANDLE_INVALID;
    o.live.erase(raw(spatialEntity));
    return XR_SUCCESS;
  });
}

// The entities' latest state: what the newest analysis says of each, located in baseSpace at time. Synchronous
// and cheap (no analysis runs here): made for once a frame.
XrResult XRAPI_CALL xrCreateSpatialUpdateSnapshotEXT(XrSpatialContextEXT spatialContext, const XrSpatialUpdateSnapshotCreateInfoEXT* createInfo,
                                                     XrSpatialSnapshotEXT* snapshot) {
  return guarded("xrCreateSpatialUpdateSnapshotEXT", [&]() -> XrResult {
    if (!is_ours(spatialContext))
      return pass_on(forward_any(&SpatialInstance::Forward::xrCreateSpatialUpdateSnapshotEXT), XR_ERROR_HANDLE_INVALID,
                     spatialContext, createInfo, snapshot);
    SnapshotObject s;
    std::shared_ptr<SessionState> session;
    std::shared_ptr<SpatialService> service;
    {
      Objects& o = objects();
      std::lock_guard lock(o.mutex);
      const ContextObject* c = o.find<ContextObject>(raw(spatialContext));
      if (c == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (!has_type(createInfo, XR_TYPE_SPATIAL_UPDATE_SNAPSHOT_CREATE_INFO_EXT) || snapshot == nullptr ||
          createInfo->entityCount == 0 || createInfo->entities == nullptr ||
          (createInfo->componentTypeCount > 0 && createInfo->componentTypes == nullptr))
        return XR_ERROR_VALIDATION_FAILURE;
      for (uint32_t i = 0; i < createInfo->componentTypeCount; ++i) {
        if (!contains(c->components, createInfo->componentTypes[i])) return XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT;
        if (!contains(s.components, createInfo->componentTypes[i])) s.components.push_back(createInfo->componentTypes[i]);
      }
      if (s.components.empty()) s.components = c->components;
      for (uint32_t i = 0; i < createInfo->entityCount; ++i) {
        const EntityObject* e = is_ours(createInfo->entities[i]) ? o.find<EntityObject>(raw(createInfo->entities[i])) : nullptr;
        if (e == nullptr || e->context != raw(spatialContext)) return XR_ERROR_HANDLE_INVALID;
        if (std::find(s.ids.begin(), s.ids.end(), e->id) == s.ids.end()) s.ids.push_back(e->id);
      }
      s.context = raw(spatialContext);
      session = c->session;
      service = c->service;
    }
    if (createInfo->time <= 0) return XR_ERROR_TIME_INVALID;
    s.set = service->entities();
    if (const XrResult r = locate(*session, service->space(), createInfo->baseSpace, createInfo->time, s.analysis_to_base, s.located);
        XR_FAILED(r))
      return r;
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    if (o.find<ContextObject>(raw(spatialContext)) == nullptr) return XR_ERROR_HANDLE_INVALID;  // destroyed meanwhile
    const std::uint64_t handle = o.add(std::move(s));
    if (handle == 0) return XR_ERROR_LIMIT_REACHED;
    *snapshot = handle_of<XrSpatialSnapshotEXT>(handle);
    return XR_SUCCESS;
  });
}

// ---- futures: the layer's own, or passed on

XrResult XRAPI_CALL xrPollFutureEXT(XrInstance instance, const XrFuturePollInfoEXT* pollInfo, XrFuturePollResultEXT* pollResult) {
  return guarded("xrPollFutureEXT", [&]() -> XrResult {
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state || !state->spatial) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(pollInfo, XR_TYPE_FUTURE_POLL_INFO_EXT) || !has_type(pollResult, XR_TYPE_FUTURE_POLL_RESULT_EXT))
      return XR_ERROR_VALIDATION_FAILURE;
    if (!is_ours(pollInfo->future))
      return pass_on(state->spatial->forward.xrPollFutureEXT, XR_ERROR_FUTURE_INVALID_EXT, instance, pollInfo, pollResult);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const FutureObject* f = o.find<FutureObject>(raw(pollInfo->future));
    if (f == nullptr || f->instance != instance) return XR_ERROR_FUTURE_INVALID_EXT;
    bool ready = true;  // a context is ready at once
    if (const DiscoveryFuture* d = f->discovery.get()) {
      const ContextObject* c = o.find<ContextObject>(d->context);
      ready = c == nullptr || c->service->finished() > 0;  // a destroyed context's future completes with an error
    }
    pollResult->state = ready ? XR_FUTURE_STATE_READY_EXT : XR_FUTURE_STATE_PENDING_EXT;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCancelFutureEXT(XrInstance instance, const XrFutureCancelInfoEXT* cancelInfo) {
  return guarded("xrCancelFutureEXT", [&]() -> XrResult {
    const std::shared_ptr<InstanceState> state = registry().instance(instance);
    if (!state || !state->spatial) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(cancelInfo, XR_TYPE_FUTURE_CANCEL_INFO_EXT)) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_ours(cancelInfo->future))
      return pass_on(state->spatial->forward.xrCancelFutureEXT, XR_ERROR_FUTURE_INVALID_EXT, instance, cancelInfo);
    Objects& o = objects();
    std::lock_guard lock(o.mutex);
    const FutureObject* f = o.find<FutureObject>(raw(cancelInfo->future));
    if (f == nullptr || f->instance != instance) return XR_ERROR_FUTURE_INVALID_EXT;
    if (f->context) f->context->service->context_destroyed();  // never to be a context
    o.live.erase(raw(cancelInfo->future));
    return XR_SUCCESS;
  });
}

// ---- what the rest of the layer calls

bool next_spatial_event(XrInstance instance, XrEventDataBuffer& event) {
  Objects& o = objects();
  std::lock_guard lock(o.mutex);
  for (auto& [handle, object] : o.live) {
    auto* c = std::get_if<ContextObject>(&object);
    if (c == nullptr || c->session->instance->handle != instance) continue;
    const std::uint64_t published = c->service->published();
    if (published <= c->recommended) continue;
    c->recommended = published;
    XrEventDataSpatialDiscoveryRecommendedEXT recommended{};
    recommended.type = XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT;
    recommended.spatialContext = handle_of<XrSpatialContextEXT>(handle);
    static_assert(sizeof recommended <= sizeof event);
    const void* next = event.next;
    std::memcpy(&event, &recommended, sizeof recommended);
    event.next = next;
    return true;
  }
  return false;
}

void forget_spatial_session(XrSession session) {
  Objects& o = objects();
  std::lock_guard lock(o.mutex);
  std::vector<std::uint64_t> contexts;
  for (const auto& [handle, object] : o.live)
    if (const auto* c = std::get_if<ContextObject>(&object); c != nullptr && c->session->handle == session) contexts.push_back(handle);
  for (std::uint64_t handle : contexts) destroy_context_locked(o, handle);
  std::erase_if(o.live, [&](const auto& e) {
    const auto* f = std::get_if<FutureObject>(&e.second);
    const ContextFuture* c = f == nullptr ? nullptr : f->context.get();
    return c != nullptr && c->session->handle == session;
  });
}

PFN_xrVoidFunction spatial_hook(std::string_view name) {
#define ROOMSENSE_SPATIAL_HOOK(fn) \
  if (name == #fn) return reinterpret_cast<PFN_xrVoidFunction>(&fn);
  ROOMSENSE_SPATIAL_FUNCTIONS(ROOMSENSE_SPATIAL_HOOK)
#undef ROOMSENSE_SPATIAL_HOOK
  return nullptr;
}

}  // namespace roomsense::layer
