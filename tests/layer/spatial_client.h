// A small client of the standard spatial-entity API (XR_EXT_spatial_entity, XR_EXT_spatial_plane_tracking,
// XR_EXT_future) for the layer tests, written against the registry's declarations only (the xrsupport ext
// headers) and the spatial block of <openxr/XR_EXTX_room_understanding.h> (the placement-areas capability). It is
// the application of an engine that reads planes through XR_EXT_spatial_plane_tracking: an instance through the
// loader with the extensions it names, a context for one capability and its components, discovery and update
// snapshots, component queries with the two-call idiom, and the spatial buffers.
//
// Each step returns its XrResult (and the context and snapshot steps their future), so that tests can look at
// every result, cancel a future or destroy a handle mid-way; the convenience functions at the end throw instead.
//
// Include this header before anything that includes <openxr/XR_EXTX_room_understanding.h> (layer_harness.h,
// compare.h): that header declares its spatial structures only where XR_EXT_spatial_entity is already declared.
#pragma once
#include <openxr/openxr.h>

#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <openxr/XR_EXTX_room_understanding.h>
#include "roomsense/xr/spatial_component_lists.h"

#include "layer_harness.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

// Fails to compile, with this name, where the header above was included before the registry declarations.
static_assert(std::is_trivially_copyable_v<XrSpatialComponentPlacementAreaListEXTX>,
              "spatial_client.h must be included before <openxr/XR_EXTX_room_understanding.h>");

namespace layertest {

using SpatialComponent = XrSpatialComponentTypeEXT;

// What an OpenXR 1.1 plane app enables (headless here).
inline std::vector<const char*> spatial_extensions() {
  return {XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME, XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME,
          XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME};
}

// The plane components of XR_EXT_spatial_plane_tracking, and those of the placement-areas capability.
inline const std::vector<SpatialComponent> kPlaneComponents = {
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT,
    XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT,
    XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT};
inline const std::vector<SpatialComponent> kPlacementComponents = {
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX, XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT,
    XR_SPATIAL_COMPONENT_TYPE_ROOM_LOCATION_EXTX};

inline bool has_component(const std::vector<SpatialComponent>& list, SpatialComponent c) {
  return std::find(list.begin(), list.end(), c) != list.end();
}

// The configuration structure type of a capability (they all share the base header's layout).
inline XrStructureType config_type_of(XrSpatialCapabilityEXT capability) {
  if (capability == XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX) return XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLACEMENT_AREAS_EXTX;
  return XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT;
}

// Every function of the three extensions, from xrGetInstanceProcAddr.
struct SpatialFunctions {
  PFN_xrPollFutureEXT pollFuture = nullptr;
  PFN_xrCancelFutureEXT cancelFuture = nullptr;
  PFN_xrEnumerateSpatialCapabilitiesEXT capabilities = nullptr;
  PFN_xrEnumerateSpatialCapabilityComponentTypesEXT componentTypes = nullptr;
  PFN_xrEnumerateSpatialCapabilityFeaturesEXT features = nullptr;
  PFN_xrCreateSpatialContextAsyncEXT createContext = nullptr;
  PFN_xrCreateSpatialContextCompleteEXT completeContext = nullptr;
  PFN_xrDestroySpatialContextEXT destroyContext = nullptr;
  PFN_xrCreateSpatialDiscoverySnapshotAsyncEXT createDiscovery = nullptr;
  PFN_xrCreateSpatialDiscoverySnapshotCompleteEXT completeDiscovery = nullptr;
  PFN_xrQuerySpatialComponentDataEXT query = nullptr;
  PFN_xrDestroySpatialSnapshotEXT destroySnapshot = nullptr;
  PFN_xrCreateSpatialEntityFromIdEXT createEntity = nullptr;
  PFN_xrDestroySpatialEntityEXT destroyEntity = nullptr;
  PFN_xrCreateSpatialUpdateSnapshotEXT createUpdate = nullptr;
  PFN_xrGetSpatialBufferVector2fEXT vector2f = nullptr;
  PFN_xrGetSpatialBufferVector3fEXT vector3f = nullptr;
  PFN_xrGetSpatialBufferUint16EXT uint16 = nullptr;
  PFN_xrGetSpatialBufferUint32EXT uint32 = nullptr;

  void load(XrInstance i) {
    pollFuture = proc<PFN_xrPollFutureEXT>(i, "xrPollFutureEXT");
    cancelFuture = proc<PFN_xrCancelFutureEXT>(i, "xrCancelFutureEXT");
    capabilities = proc<PFN_xrEnumerateSpatialCapabilitiesEXT>(i, "xrEnumerateSpatialCapabilitiesEXT");
    componentTypes = proc<PFN_xrEnumerateSpatialCapabilityComponentTypesEXT>(i, "xrEnumerateSpatialCapabilityComponentTypesEXT");
    features = proc<PFN_xrEnumerateSpatialCapabilityFeaturesEXT>(i, "xrEnumerateSpatialCapabilityFeaturesEXT");
    createContext = proc<PFN_xrCreateSpatialContextAsyncEXT>(i, "xrCreateSpatialContextAsyncEXT");
    completeContext = proc<PFN_xrCreateSpatialContextCompleteEXT>(i, "xrCreateSpatialContextCompleteEXT");
    destroyContext = proc<PFN_xrDestroySpatialContextEXT>(i, "xrDestroySpatialContextEXT");
    createDiscovery = proc<PFN_xrCreateSpatialDiscoverySnapshotAsyncEXT>(i, "xrCreateSpatialDiscoverySnapshotAsyncEXT");
    completeDiscovery = proc<PFN_xrCreateSpatialDiscoverySnapshotCompleteEXT>(i, "xrCreateSpatialDiscoverySnapshotCompleteEXT");
    query = proc<PFN_xrQuerySpatialComponentDataEXT>(i, "xrQuerySpatialComponentDataEXT");
    destroySnapshot = proc<PFN_xrDestroySpatialSnapshotEXT>(i, "xrDestroySpatialSnapshotEXT");
    createEntity = proc<PFN_xrCreateSpatialEntityFromIdEXT>(i, "xrCreateSpatialEntityFromIdEXT");
    destroyEntity = proc<PFN_xrDestroySpatialEntityEXT>(i, "xrDestroySpatialEntityEXT");
    createUpdate = proc<PFN_xrCreateSpatialUpdateSnapshotEXT>(i, "xrCreateSpatialUpdateSnapshotEXT");
    vector2f = proc<PFN_xrGetSpatialBufferVector2fEXT>(i, "xrGetSpatialBufferVector2fEXT");
    vector3f = proc<PFN_xrGetSpatialBufferVector3fEXT>(i, "xrGetSpatialBufferVector3fEXT");
    uint16 = proc<PFN_xrGetSpatialBufferUint16EXT>(i, "xrGetSpatialBufferUint16EXT");
    uint32 = proc<PFN_xrGetSpatialBufferUint32EXT>(i, "xrGetSpatialBufferUint32EXT");
  }
};

// The steps of an asynchronous creation (a context, or a discovery snapshot). A step not taken keeps
// XR_RESULT_MAX_ENUM; `wait` is XR_TIMEOUT_EXPIRED when the future was still pending at the deadline.
struct AsyncSteps {
  XrResult start = XR_RESULT_MAX_ENUM;     // xrCreateSpatialContextAsyncEXT / xrCreateSpatialDiscoverySnapshotAsyncEXT
  XrResult wait = XR_RESULT_MAX_ENUM;      // xrPollFutureEXT until READY
  XrResult complete = XR_RESULT_MAX_ENUM;  // the *CompleteEXT call
  XrResult future_result = XR_RESULT_MAX_ENUM;  // its completion's futureResult
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  bool ok() const { return start == XR_SUCCESS && wait == XR_SUCCESS && complete == XR_SUCCESS && future_result == XR_SUCCESS; }
  // The first step that did not succeed, for messages.
  std::string failure() const {
    if (start != XR_SUCCESS) return "start returned " + std::to_string(start);
    if (wait != XR_SUCCESS) return wait == XR_TIMEOUT_EXPIRED ? "the future was not ready in time" : "xrPollFutureEXT returned " + std::to_string(wait);
    if (complete != XR_SUCCESS) return "complete returned " + std::to_string(complete);
    if (future_result != XR_SUCCESS) return "futureResult " + std::to_string(future_result);
    return "ok";
  }
};
struct ContextSteps : AsyncSteps {
  XrSpatialContextEXT context = XR_NULL_HANDLE;
};
struct SnapshotSteps : AsyncSteps {
  XrSpatialSnapshotEXT snapshot = XR_NULL_HANDLE;
};

// One query's results: ids and states, and one list per component the query named (empty otherwise).
struct SpatialQuery : roomsense::xr::SpatialComponentData {
  XrResult result = XR_RESULT_MAX_ENUM;
};

// A plane as an engine keeps it.
struct Plane {
  XrSpatialEntityIdEXT id = XR_NULL_SPATIAL_ENTITY_ID_EXT;
  XrSpatialPlaneSemanticLabelEXT label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT;
  XrSpatialPlaneAlignmentEXT alignment = XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT;
  XrPosef pose{{0, 0, 0, 1}, {0, 0, 0}};  // BOUNDED_2D centre in the snapshot's base space, +Z the normal
  XrExtent2Df extents{0, 0};
  std::vector<XrVector2f> polygon;        // POLYGON_2D, in the plane's XY
};

struct SpatialClient : App {
  SpatialFunctions fn;

  explicit SpatialClient(std::vector<const char*> extensions = spatial_extensions()) : App(extensions) { fn.load(instance); }

  // ---- capabilities

  std::vector<XrSpatialCapabilityEXT> capabilities() const {
    uint32_t n = 0;
    LT_CHECK(fn.capabilities(instance, system, 0, &n, nullptr));
    std::vector<XrSpatialCapabilityEXT> list(n);
    if (n > 0) LT_CHECK(fn.capabilities(instance, system, n, &n, list.data()));
    list.resize(n);
    return list;
  }
  bool lists(XrSpatialCapabilityEXT capability) const {
    const auto list = capabilities();
    return std::find(list.begin(), list.end(), capability) != list.end();
  }

  // xrEnumerateSpatialCapabilityComponentTypesEXT, two calls; `out` holds the types where it succeeds.
  XrResult component_types(XrSpatialCapabilityEXT capability, std::vector<SpatialComponent>& out) const {
    XrSpatialCapabilityComponentTypesEXT types{XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT, nullptr};
    if (XrResult r = fn.componentTypes(instance, system, capability, &types); r != XR_SUCCESS) return r;
    out.assign(types.componentTypeCountOutput, XR_SPATIAL_COMPONENT_TYPE_MAX_ENUM_EXT);
    types.componentTypeCapacityInput = static_cast<uint32_t>(out.size());
    types.componentTypes = out.data();
    if (!out.empty())
      if (XrResult r = fn.componentTypes(instance, system, capability, &types); r != XR_SUCCESS) return r;
    out.resize(types.componentTypeCountOutput);
    return XR_SUCCESS;
  }
  std::vector<SpatialComponent> component_types(XrSpatialCapabilityEXT capability) const {
    std::vector<SpatialComponent> out;
    LT_CHECK(component_types(capability, out));
    return out;
  }

  // ---- futures

  // Polls until READY: XR_SUCCESS, XR_TIMEOUT_EXPIRED at the deadline, or xrPollFutureEXT's error.
  XrResult wait_future(XrFutureEXT future, std::chrono::milliseconds timeout = std::chrono::seconds(30)) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    const XrFuturePollInfoEXT info{XR_TYPE_FUTURE_POLL_INFO_EXT, nullptr, future};
    for (;;) {
      XrFuturePollResultEXT poll{XR_TYPE_FUTURE_POLL_RESULT_EXT, nullptr, XR_FUTURE_STATE_PENDING_EXT};
      if (XrResult r = fn.pollFuture(instance, &info, &poll); r != XR_SUCCESS) return r;
      if (poll.state == XR_FUTURE_STATE_READY_EXT) return XR_SUCCESS;
      if (std::chrono::steady_clock::now() >= deadline) return XR_TIMEOUT_EXPIRED;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  XrResult cancel(XrFutureEXT future) const {
    const XrFutureCancelInfoEXT info{XR_TYPE_FUTURE_CANCEL_INFO_EXT, nullptr, future};
    return fn.cancelFuture(instance, &info);
  }

  // ---- contexts: start, (wait,) complete; or all at once

  ContextSteps start_context(XrSpatialCapabilityEXT capability, const std::vector<SpatialComponent>& components) const {
    XrSpatialCapabilityConfigurationBaseHeaderEXT config{config_type_of(capability), nullptr, capability,
                                                         static_cast<uint32_t>(components.size()), components.data()};
    const XrSpatialCapabilityConfigurationBaseHeaderEXT* configs[] = {&config};
    const XrSpatialContextCreateInfoEXT info{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT, nullptr, 1, configs};
    ContextSteps steps;
    steps.start = fn.createContext(session, &info, &steps.future);
    return steps;
  }
  void complete_context(ContextSteps& steps) const {
    XrCreateSpatialContextCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT, nullptr};
    steps.complete = fn.completeContext(session, steps.future, &completion);
    if (steps.complete != XR_SUCCESS) return;
    steps.future_result = completion.futureResult;
    steps.context = completion.spatialContext;
  }
  ContextSteps create_context(XrSpatialCapabilityEXT capability, const std::vector<SpatialComponent>& components,
                              std::chrono::milliseconds timeout = std::chrono::seconds(30)) const {
    ContextSteps steps = start_context(capability, components);
    if (steps.start != XR_SUCCESS) return steps;
    steps.wait = wait_future(steps.future, timeout);
    if (steps.wait == XR_SUCCESS) complete_context(steps);
    return steps;
  }
  XrSpatialContextEXT context(XrSpatialCapabilityEXT capability, const std::vector<SpatialComponent>& components) const {
    const ContextSteps steps = create_context(capability, components);
    if (!steps.ok()) throw std::runtime_error("spatial context: " + steps.failure());
    return steps.context;
  }

  // ---- discovery snapshots: start, (wait,) complete; or all at once. An empty component list asks for every
  // enabled component. The snapshot is located in `base` (the LOCAL space when null) at `time` (now when 0).

  SnapshotSteps start_discovery(XrSpatialContextEXT context, const std::vector<SpatialComponent>& components) const {
    XrSpatialDiscoverySnapshotCreateInfoEXT info{XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT, nullptr};
    info.componentTypeCount = static_cast<uint32_t>(components.size());
    info.componentTypes = components.data();
    SnapshotSteps steps;
    steps.start = fn.createDiscovery(context, &info, &steps.future);
    return steps;
  }
  void complete_discovery(XrSpatialContextEXT context, SnapshotSteps& steps, XrSpace base = XR_NULL_HANDLE, XrTime time = 0) const {
    XrCreateSpatialDiscoverySnapshotCompletionInfoEXT info{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT, nullptr};
    info.baseSpace = base != XR_NULL_HANDLE ? base : local;
    info.time = time != 0 ? time : now();
    info.future = steps.future;
    XrCreateSpatialDiscoverySnapshotCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT, nullptr};
    steps.complete = fn.completeDiscovery(context, &info, &completion);
    if (steps.complete != XR_SUCCESS) return;
    steps.future_result = completion.futureResult;
    steps.snapshot = completion.snapshot;
  }
  SnapshotSteps discover(XrSpatialContextEXT context, const std::vector<SpatialComponent>& components = {},
                         XrSpace base = XR_NULL_HANDLE, XrTime time = 0,
                         std::chrono::milliseconds timeout = std::chrono::seconds(30)) const {
    SnapshotSteps steps = start_discovery(context, components);
    if (steps.start != XR_SUCCESS) return steps;
    steps.wait = wait_future(steps.future, timeout);
    if (steps.wait == XR_SUCCESS) complete_discovery(context, steps, base, time);
    return steps;
  }
  XrSpatialSnapshotEXT snapshot(XrSpatialContextEXT context, const std::vector<SpatialComponent>& components = {}) const {
    const SnapshotSteps steps = discover(context, components);
    if (!steps.ok()) throw std::runtime_error("spatial discovery snapshot: " + steps.failure());
    return steps.snapshot;
  }

  // ---- entities and update snapshots

  XrResult entity(XrSpatialContextEXT context, XrSpatialEntityIdEXT id, XrSpatialEntityEXT& out) const {
    const XrSpatialEntityFromIdCreateInfoEXT info{XR_TYPE_SPATIAL_ENTITY_FROM_ID_CREATE_INFO_EXT, nullptr, id};
    return fn.createEntity(context, &info, &out);
  }
  XrResult update(XrSpatialContextEXT context, const std::vector<XrSpatialEntityEXT>& entities,
                  const std::vector<SpatialComponent>& components, XrSpatialSnapshotEXT& out, XrSpace base = XR_NULL_HANDLE,
                  XrTime time = 0) const {
    XrSpatialUpdateSnapshotCreateInfoEXT info{XR_TYPE_SPATIAL_UPDATE_SNAPSHOT_CREATE_INFO_EXT, nullptr};
    info.entityCount = static_cast<uint32_t>(entities.size());
    info.entities = entities.data();
    info.componentTypeCount = static_cast<uint32_t>(components.size());
    info.componentTypes = components.data();
    info.baseSpace = base != XR_NULL_HANDLE ? base : local;
    info.time = time != 0 ? time : now();
    return fn.createUpdate(context, &info, &out);
  }

  // ---- queries: the entities with `components` (two-call idiom on the ids), one list chained per component

  SpatialQuery query(XrSpatialSnapshotEXT snapshot, const std::vector<SpatialComponent>& components) const {
    SpatialQuery q;
    const XrSpatialComponentDataQueryConditionEXT condition{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT, nullptr,
                                                            static_cast<uint32_t>(components.size()), components.data()};
    XrSpatialComponentDataQueryResultEXT result{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT, nullptr};
    q.result = fn.query(snapshot, &condition, &result);
    if (q.result != XR_SUCCESS) return q;
    const uint32_t n = result.entityIdCountOutput;
    const roomsense::xr::SpatialComponentLists lists(q, n, components, result);
    if (n > 0) q.result = fn.query(snapshot, &condition, &result);
    return q;
  }

  // ---- buffers, two calls each

  template <typename T, typename Get>
  XrResult read_buffer(Get get, XrSpatialSnapshotEXT snapshot, XrSpatialBufferIdEXT id, std::vector<T>& out) const {
    const XrSpatialBufferGetInfoEXT info{XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT, nullptr, id};
    uint32_t count = 0;
    if (XrResult r = get(snapshot, &info, 0, &count, nullptr); r != XR_SUCCESS) return r;
    out.resize(count);
    if (count > 0)
      if (XrResult r = get(snapshot, &info, count, &count, out.data()); r != XR_SUCCESS) return r;
    out.resize(count);
    return XR_SUCCESS;
  }
  std::vector<XrVector2f> vector2f(XrSpatialSnapshotEXT snapshot, XrSpatialBufferIdEXT id) const {
    std::vector<XrVector2f> out;
    LT_CHECK(read_buffer(fn.vector2f, snapshot, id, out));
    return out;
  }
  std::vector<XrVector3f> vector3f(XrSpatialSnapshotEXT snapshot, XrSpatialBufferIdEXT id) const {
    std::vector<XrVector3f> out;
    LT_CHECK(read_buffer(fn.vector3f, snapshot, id, out));
    return out;
  }
  // An index buffer, UINT16 or UINT32 as its type says.
  std::vector<uint32_t> indices(XrSpatialSnapshotEXT snapshot, const XrSpatialBufferEXT& buffer) const {
    std::vector<uint32_t> out;
    if (buffer.bufferType == XR_SPATIAL_BUFFER_TYPE_UINT16_EXT) {
      std::vector<uint16_t> small;
      LT_CHECK(read_buffer(fn.uint16, snapshot, buffer.bufferId, small));
      out.assign(small.begin(), small.end());
    } else {
      LT_CHECK(read_buffer(fn.uint32, snapshot, buffer.bufferId, out));
    }
    return out;
  }

  // ---- planes

  // The planes of a snapshot (label, alignment, BOUNDED_2D and POLYGON_2D as far as `components` has them).
  std::vector<Plane> planes(XrSpatialSnapshotEXT snapshot, const std::vector<SpatialComponent>& components = kPlaneComponents) const {
    std::vector<SpatialComponent> wanted;
    for (SpatialComponent c : {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT,
                               XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT, XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT})
      if (has_component(components, c)) wanted.push_back(c);
    const SpatialQuery q = query(snapshot, wanted);
    LT_CHECK(q.result);
    std::vector<Plane> out(q.ids.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      out[i].id = q.ids[i];
      if (!q.labels.empty()) out[i].label = q.labels[i];
      if (!q.alignments.empty()) out[i].alignment = q.alignments[i];
      if (!q.bounds.empty()) {
        out[i].pose = q.bounds[i].center;
        out[i].extents = q.bounds[i].extents;
      }
      if (!q.polygons.empty()) out[i].polygon = vector2f(snapshot, q.polygons[i].vertexBuffer.bufferId);
    }
    return out;
  }

  // The whole read of an OpenXR 1.1 plane app: a plane-tracking context with every component the system lists,
  // one discovery snapshot, its planes; the snapshot and context destroyed.
  std::vector<Plane> read_planes() const {
    const auto components = component_types(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT);
    const XrSpatialContextEXT ctx = context(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, components);
    const XrSpatialSnapshotEXT snap = snapshot(ctx, components);
    std::vector<Plane> out = planes(snap, components);
    LT_CHECK(fn.destroySnapshot(snap));
    LT_CHECK(fn.destroyContext(ctx));
    return out;
  }
};

}  // namespace layertest
