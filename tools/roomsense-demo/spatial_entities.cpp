// roomsense-demo --spatial-entities: the standard spatial-entity API only. The registry's declarations of
// XR_EXT_future, XR_EXT_spatial_entity and XR_EXT_spatial_plane_tracking (Debian's headers are 1.0.20) come first,
// so that <openxr/XR_EXTX_room_understanding.h> declares its spatial block (the placement-areas capability); none
// of that header's functions is used, and XR_EXTX_room_understanding is not enabled.
#include "spatial_entities.h"

#include "checked_calls.h"
#include "environment.h"
#include "instance.h"

#include <openxr/openxr.h>

#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <openxr/XR_EXTX_room_understanding.h>
#include "roomsense/xr/spatial_component_lists.h"

#include "roomsense/areas.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace roomsense::demo {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using Component = XrSpatialComponentTypeEXT;

constexpr auto kFutureTimeout = std::chrono::seconds(30);
constexpr auto kEventTimeout = std::chrono::seconds(2);
constexpr int kUpdateIterations = 200;

// ---- names

std::string capability_name(XrSpatialCapabilityEXT c) {
  switch (static_cast<int64_t>(c)) {
    case XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT: return "XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT";
    case XR_SPATIAL_CAPABILITY_MARKER_TRACKING_QR_CODE_EXT: return "XR_SPATIAL_CAPABILITY_MARKER_TRACKING_QR_CODE_EXT";
    case XR_SPATIAL_CAPABILITY_MARKER_TRACKING_MICRO_QR_CODE_EXT: return "XR_SPATIAL_CAPABILITY_MARKER_TRACKING_MICRO_QR_CODE_EXT";
    case XR_SPATIAL_CAPABILITY_MARKER_TRACKING_ARUCO_MARKER_EXT: return "XR_SPATIAL_CAPABILITY_MARKER_TRACKING_ARUCO_MARKER_EXT";
    case XR_SPATIAL_CAPABILITY_MARKER_TRACKING_APRIL_TAG_EXT: return "XR_SPATIAL_CAPABILITY_MARKER_TRACKING_APRIL_TAG_EXT";
    case XR_SPATIAL_CAPABILITY_ANCHOR_EXT: return "XR_SPATIAL_CAPABILITY_ANCHOR_EXT";
    case XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX: return "XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX";
    default: return "capability " + std::to_string(static_cast<int64_t>(c));
  }
}

std::string component_name(Component c) {
  switch (static_cast<int64_t>(c)) {
    case XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT: return "BOUNDED_2D";
    case XR_SPATIAL_COMPONENT_TYPE_BOUNDED_3D_EXT: return "BOUNDED_3D";
    case XR_SPATIAL_COMPONENT_TYPE_PARENT_EXT: return "PARENT";
    case XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT: return "MESH_3D";
    case XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT: return "PLANE_ALIGNMENT";
    case XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT: return "MESH_2D";
    case XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT: return "POLYGON_2D";
    case XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT: return "PLANE_SEMANTIC_LABEL";
    case XR_SPATIAL_COMPONENT_TYPE_MARKER_EXT: return "MARKER";
    case XR_SPATIAL_COMPONENT_TYPE_ANCHOR_EXT: return "ANCHOR";
    case XR_SPATIAL_COMPONENT_TYPE_PERSISTENCE_EXT: return "PERSISTENCE";
    case XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX: return "PLACEMENT_AREA_EXTX";
    default: return "component " + std::to_string(static_cast<int64_t>(c));
  }
}

std::string label_name(XrSpatialPlaneSemanticLabelEXT l) {
  switch (l) {
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT: return "UNCATEGORIZED";
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT: return "FLOOR";
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT: return "WALL";
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT: return "CEILING";
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT: return "TABLE";
    default: return "label " + std::to_string(static_cast<int>(l));
  }
}

std::string alignment_name(XrSpatialPlaneAlignmentEXT a) {
  switch (a) {
    case XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT: return "HORIZONTAL_UPWARD";
    case XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT: return "HORIZONTAL_DOWNWARD";
    case XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT: return "VERTICAL";
    case XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT: return "ARBITRARY";
    default: return "alignment " + std::to_string(static_cast<int>(a));
  }
}

bool contains(const std::vector<Component>& list, Component c) { return std::find(list.begin(), list.end(), c) != list.end(); }

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// ---- checked calls


#define RS_LOAD(name) name = proc<PFN_##name>(check, instance, #name)

struct Functions {
  PFN_xrPollFutureEXT xrPollFutureEXT = nullptr;
  PFN_xrEnumerateSpatialCapabilitiesEXT xrEnumerateSpatialCapabilitiesEXT = nullptr;
  PFN_xrEnumerateSpatialCapabilityComponentTypesEXT xrEnumerateSpatialCapabilityComponentTypesEXT = nullptr;
  PFN_xrCreateSpatialContextAsyncEXT xrCreateSpatialContextAsyncEXT = nullptr;
  PFN_xrCreateSpatialContextCompleteEXT xrCreateSpatialContextCompleteEXT = nullptr;
  PFN_xrDestroySpatialContextEXT xrDestroySpatialContextEXT = nullptr;
  PFN_xrCreateSpatialDiscoverySnapshotAsyncEXT xrCreateSpatialDiscoverySnapshotAsyncEXT = nullptr;
  PFN_xrCreateSpatialDiscoverySnapshotCompleteEXT xrCreateSpatialDiscoverySnapshotCompleteEXT = nullptr;
  PFN_xrQuerySpatialComponentDataEXT xrQuerySpatialComponentDataEXT = nullptr;
  PFN_xrDestroySpatialSnapshotEXT xrDestroySpatialSnapshotEXT = nullptr;
  PFN_xrCreateSpatialEntityFromIdEXT xrCreateSpatialEntityFromIdEXT = nullptr;
  PFN_xrDestroySpatialEntityEXT xrDestroySpatialEntityEXT = nullptr;
  PFN_xrCreateSpatialUpdateSnapshotEXT xrCreateSpatialUpdateSnapshotEXT = nullptr;
  PFN_xrGetSpatialBufferVector2fEXT xrGetSpatialBufferVector2fEXT = nullptr;
  PFN_xrGetSpatialBufferVector3fEXT xrGetSpatialBufferVector3fEXT = nullptr;
  PFN_xrGetSpatialBufferUint16EXT xrGetSpatialBufferUint16EXT = nullptr;
  PFN_xrGetSpatialBufferUint32EXT xrGetSpatialBufferUint32EXT = nullptr;

  void load(const Checker& check, XrInstance instance) {
    RS_LOAD(xrPollFutureEXT);
    RS_LOAD(xrEnumerateSpatialCapabilitiesEXT);
    RS_LOAD(xrEnumerateSpatialCapabilityComponentTypesEXT);
    RS_LOAD(xrCreateSpatialContextAsyncEXT);
    RS_LOAD(xrCreateSpatialContextCompleteEXT);
    RS_LOAD(xrDestroySpatialContextEXT);
    RS_LOAD(xrCreateSpatialDiscoverySnapshotAsyncEXT);
    RS_LOAD(xrCreateSpatialDiscoverySnapshotCompleteEXT);
    RS_LOAD(xrQuerySpatialComponentDataEXT);
    RS_LOAD(xrDestroySpatialSnapshotEXT);
    RS_LOAD(xrCreateSpatialEntityFromIdEXT);
    RS_LOAD(xrDestroySpatialEntityEXT);
    RS_LOAD(xrCreateSpatialUpdateSnapshotEXT);
    RS_LOAD(xrGetSpatialBufferVector2fEXT);
    RS_LOAD(xrGetSpatialBufferVector3fEXT);
    RS_LOAD(xrGetSpatialBufferUint16EXT);
    RS_LOAD(xrGetSpatialBufferUint32EXT);
  }
};

#undef RS_LOAD

std::vector<std::string> offered_extensions() {
  uint32_t count = 0;
  if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr))) return {};
  std::vector<XrExtensionProperties> props(count, {XR_TYPE_EXTENSION_PROPERTIES, nullptr});
  if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()))) return {};
  std::vector<std::string> names;
  for (uint32_t i = 0; i < count; ++i) names.emplace_back(props[i].extensionName);
  return names;
}

// ---- the app

struct Plane {
  XrSpatialEntityIdEXT id = XR_NULL_SPATIAL_ENTITY_ID_EXT;
  XrSpatialPlaneSemanticLabelEXT label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT;
  XrSpatialPlaneAlignmentEXT alignment = XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT;
  bool has_label = false, has_alignment = false, has_bounds = false;
  XrPosef pose{{0, 0, 0, 1}, {0, 0, 0}};
  XrExtent2Df extents{0, 0};
  std::vector<XrVector2f> polygon;
  std::optional<std::size_t> mesh_triangles;  // MESH_2D, where enabled
};

struct PlacementArea {
  XrSpatialEntityIdEXT id = XR_NULL_SPATIAL_ENTITY_ID_EXT;
  XrPosef pose{{0, 0, 0, 1}, {0, 0, 0}};
  XrExtent2Df extents{0, 0};
  XrSpatialPlacementAreaDataEXTX data{};
};

struct RoomMesh {
  XrSpatialEntityIdEXT id = XR_NULL_SPATIAL_ENTITY_ID_EXT;
  std::size_t vertices = 0, triangles = 0;
};

class SpatialApp {
 public:
  SpatialApp() = default;

  void open() {
    const std::vector<const char*> wanted = {XR_EXT_FUTURE_EXTENSION_NAME, XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME,
                                             XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME};
    const std::vector<std::string> offered = offered_extensions();
    std::string missing;
    for (const char* e : wanted)
      if (std::find(offered.begin(), offered.end(), e) == offered.end()) missing += (missing.empty() ? "" : ", ") + std::string(e);

    XrInstanceCreateInfo create{XR_TYPE_INSTANCE_CREATE_INFO, nullptr};
    std::strncpy(create.applicationInfo.applicationName, "roomsense-demo --spatial-entities", XR_MAX_APPLICATION_NAME_SIZE - 1);
    create.applicationInfo.applicationVersion = 1;
    create.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);  // Debian's 1.0.20 loader refuses 1.1
    create.enabledExtensionCount = static_cast<uint32_t>(wanted.size());
    create.enabledExtensionNames = wanted.data();
    const XrResult r = xrCreateInstance(&create, &instance_.handle);
    if (XR_FAILED(r)) {
      std::string why = "xrCreateInstance failed: " + result_name(XR_NULL_HANDLE, r);
      if (!missing.empty()) {
        why += " (offered neither by the runtime nor by a layer: " + missing;
        if (missing.find(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME) != std::string::npos)
          why += "; the runtime has no plane tracking, and the roomsense layer, which serves it where a runtime has none, is "
                 "disabled, missing or too old";
        why += ")";
      }
      throw std::runtime_error(why);
    }
    check_.instance = instance_.handle;
    fn_.load(check_, instance_.handle);

    XrInstanceProperties properties{XR_TYPE_INSTANCE_PROPERTIES, nullptr};
    check_(xrGetInstanceProperties(instance_.handle, &properties), "xrGetInstanceProperties");
    runtime_name_ = properties.runtimeName;

    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO, nullptr};
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    check_(xrGetSystem(instance_.handle, &system_info, &system_), "xrGetSystem");
    XrSessionCreateInfo session_info{XR_TYPE_SESSION_CREATE_INFO, nullptr};  // headless: no graphics binding
    session_info.systemId = system_;
    check_(xrCreateSession(instance_.handle, &session_info, &session_), "xrCreateSession");
    poll_events();
    if (state_ != XR_SESSION_STATE_READY) throw std::runtime_error("the session did not become READY");
    XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO, nullptr};
    begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    check_(xrBeginSession(session_, &begin), "xrBeginSession");

    XrReferenceSpaceCreateInfo space_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO, nullptr};
    space_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    space_info.poseInReferenceSpace.orientation.w = 1.0f;
    check_(xrCreateReferenceSpace(session_, &space_info, &local_), "xrCreateReferenceSpace");
  }

  void close() {
    check_(xrDestroySpace(local_), "xrDestroySpace");
    check_(xrRequestExitSession(session_), "xrRequestExitSession");
    poll_events();
    check_(xrEndSession(session_), "xrEndSession");
    check_(xrDestroySession(session_), "xrDestroySession");
  }

  const std::string& runtime_name() const { return runtime_name_; }

  std::vector<XrSpatialCapabilityEXT> capabilities() {
    uint32_t n = 0;
    check_(fn_.xrEnumerateSpatialCapabilitiesEXT(instance_.handle, system_, 0, &n, nullptr), "xrEnumerateSpatialCapabilitiesEXT");
    std::vector<XrSpatialCapabilityEXT> list(n);
    if (n > 0)
      check_(fn_.xrEnumerateSpatialCapabilitiesEXT(instance_.handle, system_, n, &n, list.data()), "xrEnumerateSpatialCapabilitiesEXT");
    list.resize(n);
    return list;
  }

  std::vector<Component> components(XrSpatialCapabilityEXT capability) {
    XrSpatialCapabilityComponentTypesEXT types{XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT, nullptr};
    check_(fn_.xrEnumerateSpatialCapabilityComponentTypesEXT(instance_.handle, system_, capability, &types),
           "xrEnumerateSpatialCapabilityComponentTypesEXT");
    std::vector<Component> list(types.componentTypeCountOutput);
    types.componentTypeCapacityInput = static_cast<uint32_t>(list.size());
    types.componentTypes = list.data();
    if (!list.empty())
      check_(fn_.xrEnumerateSpatialCapabilityComponentTypesEXT(instance_.handle, system_, capability, &types),
             "xrEnumerateSpatialCapabilityComponentTypesEXT");
    list.resize(types.componentTypeCountOutput);
    return list;
  }

  // One capability configuration (`config_type` is its structure type), all of `components` enabled.
  XrSpatialContextEXT create_context(XrStructureType config_type, XrSpatialCapabilityEXT capability,
                                     const std::vector<Component>& components) {
    // XrSpatialCapabilityConfigurationPlaneTrackingEXT and ...PlacementAreasEXTX share the base header's layout.
    XrSpatialCapabilityConfigurationBaseHeaderEXT config{config_type, nullptr, capability,
                                                         static_cast<uint32_t>(components.size()), components.data()};
    const XrSpatialCapabilityConfigurationBaseHeaderEXT* configs[] = {&config};
    XrSpatialContextCreateInfoEXT info{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT, nullptr, 1, configs};
    XrFutureEXT future = XR_NULL_FUTURE_EXT;
    check_(fn_.xrCreateSpatialContextAsyncEXT(session_, &info, &future), "xrCreateSpatialContextAsyncEXT");
    wait_future(future, "xrCreateSpatialContextAsyncEXT");
    XrCreateSpatialContextCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT, nullptr};
    check_(fn_.xrCreateSpatialContextCompleteEXT(session_, future, &completion), "xrCreateSpatialContextCompleteEXT");
    check_(completion.futureResult, "xrCreateSpatialContextCompleteEXT (futureResult)");
    return completion.spatialContext;
  }

  void destroy_context(XrSpatialContextEXT context) {
    check_(fn_.xrDestroySpatialContextEXT(context), "xrDestroySpatialContextEXT");
  }

  // Waits (bounded) for the runtime to recommend a discovery in `context`; false when it did not.
  bool wait_discovery_recommended(XrSpatialContextEXT context, std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    do {
      if (poll_events(context)) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    } while (Clock::now() < deadline);
    return false;
  }

  // A discovery snapshot of `components` in the LOCAL space at `time`.
  XrSpatialSnapshotEXT discover(XrSpatialContextEXT context, const std::vector<Component>& components, XrTime time) {
    XrSpatialDiscoverySnapshotCreateInfoEXT info{XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT, nullptr};
    info.componentTypeCount = static_cast<uint32_t>(components.size());
    info.componentTypes = components.data();
    XrFutureEXT future = XR_NULL_FUTURE_EXT;
    check_(fn_.xrCreateSpatialDiscoverySnapshotAsyncEXT(context, &info, &future), "xrCreateSpatialDiscoverySnapshotAsyncEXT");
    wait_future(future, "xrCreateSpatialDiscoverySnapshotAsyncEXT");
    XrCreateSpatialDiscoverySnapshotCompletionInfoEXT completion_info{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT,
                                                                      nullptr};
    completion_info.baseSpace = local_;
    completion_info.time = time;
    completion_info.future = future;
    XrCreateSpatialDiscoverySnapshotCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT, nullptr};
    check_(fn_.xrCreateSpatialDiscoverySnapshotCompleteEXT(context, &completion_info, &completion),
           "xrCreateSpatialDiscoverySnapshotCompleteEXT");
    check_(completion.futureResult, "xrCreateSpatialDiscoverySnapshotCompleteEXT (futureResult)");
    return completion.snapshot;
  }

  void destroy_snapshot(XrSpatialSnapshotEXT snapshot) {
    check_(fn_.xrDestroySpatialSnapshotEXT(snapshot), "xrDestroySpatialSnapshotEXT");
  }

  // The entities of a snapshot that have every component of `components` (two-call idiom on the ids), with one
  // list chained per component.
  struct Query : roomsense::xr::SpatialComponentData {
    bool tracking(std::size_t i) const { return states[i] == XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT; }
  };

  Query query(XrSpatialSnapshotEXT snapshot, const std::vector<Component>& components) {
    const XrSpatialComponentDataQueryConditionEXT condition{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT, nullptr,
                                                            static_cast<uint32_t>(components.size()), components.data()};
    XrSpatialComponentDataQueryResultEXT result{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT, nullptr};
    check_(fn_.xrQuerySpatialComponentDataEXT(snapshot, &condition, &result), "xrQuerySpatialComponentDataEXT");
    const uint32_t n = result.entityIdCountOutput;
    Query q;
    const roomsense::xr::SpatialComponentLists lists(q, n, components, result);
    if (n > 0) check_(fn_.xrQuerySpatialComponentDataEXT(snapshot, &condition, &result), "xrQuerySpatialComponentDataEXT");
    if (result.entityIdCountOutput != n)
      throw std::runtime_error("xrQuerySpatialComponentDataEXT returned " + std::to_string(result.entityIdCountOutput) +
                               " entities after announcing " + std::to_string(n));
    return q;
  }

  // Every tracked plane of the snapshot. The guaranteed components (BOUNDED_2D, PLANE_ALIGNMENT) find the planes;
  // each optional component the context enabled is one more query, matched by id, so that a plane without it still
  // counts. The polygon and the 2D mesh's index buffer are read with the two-call idiom.
  std::vector<Plane> planes(XrSpatialSnapshotEXT snapshot, const std::vector<Component>& enabled) {
    std::vector<Component> guaranteed;
    for (Component c : {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT})
      if (contains(enabled, c)) guaranteed.push_back(c);
    const Query found = query(snapshot, guaranteed);
    std::vector<Plane> out;
    for (std::size_t i = 0; i < found.ids.size(); ++i) {
      if (!found.tracking(i)) continue;  // component data is valid only while tracking
      Plane p;
      p.id = found.ids[i];
      if (!found.bounds.empty()) {
        p.has_bounds = true;
        p.pose = found.bounds[i].center;
        p.extents = found.bounds[i].extents;
      }
      if (!found.alignments.empty()) {
        p.has_alignment = true;
        p.alignment = found.alignments[i];
      }
      out.push_back(std::move(p));
    }
    const auto plane_of = [&](XrSpatialEntityIdEXT id) -> Plane* {
      for (Plane& p : out)
        if (p.id == id) return &p;
      return nullptr;
    };
    if (contains(enabled, XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT)) {
      const Query q = query(snapshot, {XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT});
      for (std::size_t i = 0; i < q.ids.size(); ++i)
        if (Plane* p = plane_of(q.ids[i]); p != nullptr && q.tracking(i)) {
          p->has_label = true;
          p->label = q.labels[i];
        }
    }
    if (contains(enabled, XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT)) {
      const Query q = query(snapshot, {XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT});
      for (std::size_t i = 0; i < q.ids.size(); ++i)
        if (Plane* p = plane_of(q.ids[i]); p != nullptr && q.tracking(i))
          p->polygon = read_buffer<XrVector2f>(fn_.xrGetSpatialBufferVector2fEXT, "xrGetSpatialBufferVector2fEXT", snapshot,
                                               q.polygons[i].vertexBuffer);
    }
    if (contains(enabled, XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT)) {
      const Query q = query(snapshot, {XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT});
      for (std::size_t i = 0; i < q.ids.size(); ++i)
        if (Plane* p = plane_of(q.ids[i]); p != nullptr && q.tracking(i))
          p->mesh_triangles = read_indices(snapshot, q.meshes2d[i].indexBuffer).size() / 3;
    }
    return out;
  }

  // The placement areas (PLACEMENT_AREA_EXTX, with BOUNDED_2D where enabled) and the room entity (MESH_3D).
  void placement(XrSpatialSnapshotEXT snapshot, const std::vector<Component>& enabled, std::vector<PlacementArea>& areas,
                 std::optional<RoomMesh>& room) {
    if (contains(enabled, XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX)) {
      std::vector<Component> wanted = {XR_SPATIAL_COMPONENT_TYPE_PLACEMENT_AREA_EXTX};
      if (contains(enabled, XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT)) wanted.push_back(XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT);
      const Query q = query(snapshot, wanted);
      for (std::size_t i = 0; i < q.ids.size(); ++i) {
        if (!q.tracking(i)) continue;
        PlacementArea a;
        a.id = q.ids[i];
        a.data = q.areas[i];
        a.extents = q.areas[i].extents;
        if (!q.bounds.empty()) {
          a.pose = q.bounds[i].center;
          a.extents = q.bounds[i].extents;
        }
        areas.push_back(a);
      }
    }
    if (contains(enabled, XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT)) {
      const Query q = query(snapshot, {XR_SPATIAL_COMPONENT_TYPE_MESH_3D_EXT});
      for (std::size_t i = 0; i < q.ids.size() && !room; ++i) {
        if (!q.tracking(i)) continue;
        if (q.meshes3d[i].vertexBuffer.bufferType != XR_SPATIAL_BUFFER_TYPE_VECTOR3F_EXT)
          throw std::runtime_error("xrQuerySpatialComponentDataEXT: the room mesh's vertex buffer is not VECTOR3F");
        RoomMesh m;
        m.id = q.ids[i];
        m.vertices = read_buffer<XrVector3f>(fn_.xrGetSpatialBufferVector3fEXT, "xrGetSpatialBufferVector3fEXT", snapshot,
                                             q.meshes3d[i].vertexBuffer)
                         .size();
        m.triangles = read_indices(snapshot, q.meshes3d[i].indexBuffer).size() / 3;
        room = m;
      }
    }
  }

  // The mean cost of one update snapshot of `entities` (created from `ids`), its query and its destruction.
  double update_cost_us(XrSpatialContextEXT context, const std::vector<XrSpatialEntityIdEXT>& ids,
                        const std::vector<Component>& enabled, int iterations) {
    std::vector<XrSpatialEntityEXT> entities;
    for (XrSpatialEntityIdEXT id : ids) {
      XrSpatialEntityFromIdCreateInfoEXT info{XR_TYPE_SPATIAL_ENTITY_FROM_ID_CREATE_INFO_EXT, nullptr, id};
      XrSpatialEntityEXT entity = XR_NULL_HANDLE;
      check_(fn_.xrCreateSpatialEntityFromIdEXT(context, &info, &entity), "xrCreateSpatialEntityFromIdEXT");
      entities.push_back(entity);
    }
    // What a per-frame update reads: where each plane is and how big.
    std::vector<Component> wanted = {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT};
    if (!contains(enabled, wanted[0])) wanted.clear();
    XrSpatialUpdateSnapshotCreateInfoEXT info{XR_TYPE_SPATIAL_UPDATE_SNAPSHOT_CREATE_INFO_EXT, nullptr};
    info.entityCount = static_cast<uint32_t>(entities.size());
    info.entities = entities.data();
    info.componentTypeCount = static_cast<uint32_t>(wanted.size());
    info.componentTypes = wanted.data();
    info.baseSpace = local_;
    info.time = frame_time();
    const auto n = static_cast<uint32_t>(entities.size());
    std::vector<XrSpatialEntityIdEXT> got(n);
    std::vector<XrSpatialEntityTrackingStateEXT> states(n);
    std::vector<XrSpatialBounded2DDataEXT> bounds(n);
    const auto t0 = Clock::now();
    for (int i = 0; i < iterations; ++i) {
      XrSpatialSnapshotEXT snapshot = XR_NULL_HANDLE;
      check_(fn_.xrCreateSpatialUpdateSnapshotEXT(context, &info, &snapshot), "xrCreateSpatialUpdateSnapshotEXT");
      XrSpatialComponentDataQueryConditionEXT condition{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT, nullptr,
                                                        static_cast<uint32_t>(wanted.size()), wanted.data()};
      XrSpatialComponentBounded2DListEXT bound_list{XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT, nullptr, n, bounds.data()};
      XrSpatialComponentDataQueryResultEXT result{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT,
                                                  wanted.empty() ? nullptr : &bound_list};
      result.entityIdCapacityInput = n;
      result.entityIds = got.data();
      result.entityStateCapacityInput = n;
      result.entityStates = states.data();
      check_(fn_.xrQuerySpatialComponentDataEXT(snapshot, &condition, &result), "xrQuerySpatialComponentDataEXT");
      if (result.entityIdCountOutput != n)
        throw std::runtime_error("xrQuerySpatialComponentDataEXT on an update snapshot returned " +
                                 std::to_string(result.entityIdCountOutput) + " entities, not " + std::to_string(n));
      check_(fn_.xrDestroySpatialSnapshotEXT(snapshot), "xrDestroySpatialSnapshotEXT");
    }
    const double mean = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / std::max(iterations, 1);
    for (XrSpatialEntityEXT e : entities) check_(fn_.xrDestroySpatialEntityEXT(e), "xrDestroySpatialEntityEXT");
    return mean;
  }

  // The predicted display time of one frame: the time an app asks for its snapshots.
  XrTime frame_time() {
    XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO, nullptr};
    XrFrameState frame_state{XR_TYPE_FRAME_STATE, nullptr};
    check_(xrWaitFrame(session_, &wait, &frame_state), "xrWaitFrame");
    XrFrameBeginInfo frame_begin{XR_TYPE_FRAME_BEGIN_INFO, nullptr};
    check_(xrBeginFrame(session_, &frame_begin), "xrBeginFrame");
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO, nullptr};
    end.displayTime = frame_state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    check_(xrEndFrame(session_, &end), "xrEndFrame");
    return frame_state.predictedDisplayTime;
  }

 private:
  // Polls the future until it is ready; a clear error after kFutureTimeout.
  void wait_future(XrFutureEXT future, const char* started_by) {
    const auto deadline = Clock::now() + kFutureTimeout;
    XrFuturePollInfoEXT info{XR_TYPE_FUTURE_POLL_INFO_EXT, nullptr, future};
    for (;;) {
      XrFuturePollResultEXT poll{XR_TYPE_FUTURE_POLL_RESULT_EXT, nullptr, XR_FUTURE_STATE_PENDING_EXT};
      check_(fn_.xrPollFutureEXT(instance_.handle, &info, &poll), "xrPollFutureEXT");
      if (poll.state == XR_FUTURE_STATE_READY_EXT) return;
      if (Clock::now() >= deadline)
        throw std::runtime_error(std::string("xrPollFutureEXT: the future of ") + started_by + " was not ready after " +
                                 std::to_string(std::chrono::duration_cast<std::chrono::seconds>(kFutureTimeout).count()) + " s");
      poll_events();  // an app keeps its event queue drained while it waits
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  // Drains the event queue; true when it held a discovery recommendation for `context`.
  bool poll_events(XrSpatialContextEXT context = XR_NULL_HANDLE) {
    bool recommended = false;
    for (;;) {
      XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER, nullptr};
      const XrResult r = xrPollEvent(instance_.handle, &event);
      check_(r, "xrPollEvent");
      if (r != XR_SUCCESS) break;
      if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
        state_ = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
      } else if (event.type == XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT) {
        const auto& e = reinterpret_cast<const XrEventDataSpatialDiscoveryRecommendedEXT&>(event);
        if (context != XR_NULL_HANDLE && e.spatialContext == context) recommended = true;
        else pending_recommendations_.push_back(e.spatialContext);
      }
    }
    // One that arrived while waiting on something else counts too.
    if (context != XR_NULL_HANDLE) {
      const auto it = std::find(pending_recommendations_.begin(), pending_recommendations_.end(), context);
      if (it != pending_recommendations_.end()) {
        pending_recommendations_.erase(it);
        recommended = true;
      }
    }
    return recommended;
  }

  template <typename T, typename Get>
  std::vector<T> read_buffer(Get get, const char* name, XrSpatialSnapshotEXT snapshot, const XrSpatialBufferEXT& buffer) {
    const XrSpatialBufferGetInfoEXT info{XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT, nullptr, buffer.bufferId};
    uint32_t count = 0;
    check_(get(snapshot, &info, 0, &count, nullptr), name);
    std::vector<T> out(count);
    if (count > 0) check_(get(snapshot, &info, count, &count, out.data()), name);
    out.resize(count);
    return out;
  }

  std::vector<uint32_t> read_indices(XrSpatialSnapshotEXT snapshot, const XrSpatialBufferEXT& buffer) {
    if (buffer.bufferType == XR_SPATIAL_BUFFER_TYPE_UINT16_EXT) {
      const auto small = read_buffer<uint16_t>(fn_.xrGetSpatialBufferUint16EXT, "xrGetSpatialBufferUint16EXT", snapshot, buffer);
      return {small.begin(), small.end()};
    }
    if (buffer.bufferType == XR_SPATIAL_BUFFER_TYPE_UINT32_EXT)
      return read_buffer<uint32_t>(fn_.xrGetSpatialBufferUint32EXT, "xrGetSpatialBufferUint32EXT", snapshot, buffer);
    throw std::runtime_error("xrQuerySpatialComponentDataEXT: an index buffer of type " +
                             std::to_string(static_cast<int>(buffer.bufferType)) + ", neither UINT16 nor UINT32");
  }

  Instance instance_;
  Checker check_;
  Functions fn_;
  std::string runtime_name_;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace local_ = XR_NULL_HANDLE;
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  std::vector<XrSpatialContextEXT> pending_recommendations_;
};

// ---- output

nlohmann::json pose_json(const XrPosef& p) {
  return {{"position", {p.position.x, p.position.y, p.position.z}},
          {"orientation", {p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w}}};
}

std::string components_text(const std::vector<Component>& list) {
  std::string s;
  for (Component c : list) s += (s.empty() ? "" : ", ") + component_name(c);
  return s.empty() ? "none" : s;
}

const char* area_type(XrRoomAreaTypeEXTX t) { return to_string(static_cast<AreaType>(t)).data(); }
const char* area_size(XrRoomAreaSizeEXTX s) { return to_string(static_cast<AreaSize>(s)).data(); }
const char* area_reach(XrRoomInteractionEXTX r) { return to_string(static_cast<Reach>(r)).data(); }

}  // namespace

void run_spatial_entities(const std::string& room, const fs::path& output) {
  SpatialApp app;
  app.open();
  const std::string layer = loaded_layer_library();
  std::printf("runtime     %s\n", app.runtime_name().c_str());
  std::printf("layer       %s\n", layer.empty() ? "none loaded" : layer.c_str());
  std::printf("room        %s\n", room.c_str());
  std::printf("extensions  %s, %s, %s, %s (not %s)\n", XR_EXT_FUTURE_EXTENSION_NAME, XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME,
              XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME,
              XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME);

  const std::vector<XrSpatialCapabilityEXT> capabilities = app.capabilities();
  std::printf("capabilities %zu\n", capabilities.size());
  for (XrSpatialCapabilityEXT c : capabilities) std::printf("            %s\n", capability_name(c).c_str());
  const auto listed = [&](XrSpatialCapabilityEXT c) { return std::find(capabilities.begin(), capabilities.end(), c) != capabilities.end(); };
  if (!listed(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT))
    throw std::runtime_error("xrEnumerateSpatialCapabilitiesEXT does not list XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT");

  // ---- planes
  const std::vector<Component> plane_components = app.components(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT);
  std::printf("planes      components: %s\n", components_text(plane_components).c_str());
  if (plane_components.empty())
    throw std::runtime_error("xrEnumerateSpatialCapabilityComponentTypesEXT lists no component for plane tracking");
  const XrTime time = app.frame_time();  // the snapshots' time: a frame's predicted display time, as in any app
  const auto t0 = Clock::now();
  const XrSpatialContextEXT context =
      app.create_context(XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT, XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, plane_components);
  const double context_ms = ms_since(t0);
  const bool recommended = app.wait_discovery_recommended(context, kEventTimeout);
  const double event_ms = ms_since(t0);
  const XrSpatialSnapshotEXT snapshot = app.discover(context, plane_components, time);
  const double first_discovery_ms = ms_since(t0);
  std::vector<Plane> planes = app.planes(snapshot, plane_components);
  app.destroy_snapshot(snapshot);
  if (recommended)
    std::printf("            context ready after %.1f ms, discovery recommended (XrEventDataSpatialDiscoveryRecommendedEXT) at %.1f ms\n",
                context_ms, event_ms);
  else
    std::printf("            context ready after %.1f ms, no discovery recommendation within %lld s: discovering anyway\n", context_ms,
                static_cast<long long>(std::chrono::duration_cast<std::chrono::seconds>(kEventTimeout).count()));
  std::printf("            %zu planes in the first discovery snapshot, %.1f ms after the context was requested\n\n", planes.size(),
              first_discovery_ms);
  std::printf("      id  label          alignment            centre x, y, z (m)        width x height (m)  polygon  mesh\n");
  for (const Plane& p : planes) {
    const std::string mesh = p.mesh_triangles ? std::to_string(*p.mesh_triangles) + " tri" : "-";
    std::printf("%8llu  %-13s  %-19s  (%6.2f, %5.2f, %6.2f)     %5.2f x %-5.2f        %4zu     %s\n",
                static_cast<unsigned long long>(p.id), p.has_label ? label_name(p.label).c_str() : "-",
                p.has_alignment ? alignment_name(p.alignment).c_str() : "-", double(p.pose.position.x), double(p.pose.position.y),
                double(p.pose.position.z), double(p.extents.width), double(p.extents.height), p.polygon.size(), mesh.c_str());
  }

  std::vector<XrSpatialEntityIdEXT> ids;
  for (const Plane& p : planes) ids.push_back(p.id);
  double update_us = 0.0;
  if (!ids.empty()) {
    update_us = app.update_cost_us(context, ids, plane_components, kUpdateIterations);
    std::printf("\nupdate      %.1f us per update snapshot of all %zu planes (create + query BOUNDED_2D + destroy), mean of %d\n",
                update_us, ids.size(), kUpdateIterations);
  }
  app.destroy_context(context);

  // ---- placement areas and the room mesh, where listed
  nlohmann::json placement = nullptr;
  if (listed(XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX)) {
    const std::vector<Component> components = app.components(XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX);
    std::printf("\nplacement   components: %s\n", components_text(components).c_str());
    const XrTime areas_time = app.frame_time();
    const auto p0 = Clock::now();
    const XrSpatialContextEXT areas_context = app.create_context(XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLACEMENT_AREAS_EXTX,
                                                                 XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX, components);
    app.wait_discovery_recommended(areas_context, kEventTimeout);
    const XrSpatialSnapshotEXT areas_snapshot = app.discover(areas_context, components, areas_time);
    const double areas_ms = ms_since(p0);
    std::vector<PlacementArea> areas;
    std::optional<RoomMesh> room_mesh;
    app.placement(areas_snapshot, components, areas, room_mesh);
    app.destroy_snapshot(areas_snapshot);
    app.destroy_context(areas_context);
    std::printf("            %zu placement areas in the first discovery snapshot, %.1f ms after the context was requested\n\n",
                areas.size(), areas_ms);
    std::printf("      id  type       size    reach     centre x, y, z (m)        width x height (m)\n");
    placement = {{"discovery_ms", areas_ms}, {"areas", nlohmann::json::array()}, {"room_mesh", nullptr}};
    for (const PlacementArea& a : areas) {
      std::printf("%8llu  %-9s  %-6s  %-8s  (%6.2f, %5.2f, %6.2f)     %5.2f x %.2f\n", static_cast<unsigned long long>(a.id),
                  area_type(a.data.areaType), area_size(a.data.size), area_reach(a.data.interaction), double(a.pose.position.x),
                  double(a.pose.position.y), double(a.pose.position.z), double(a.extents.width), double(a.extents.height));
      placement["areas"].push_back({{"id", a.id},
                                    {"type", area_type(a.data.areaType)},
                                    {"size", area_size(a.data.size)},
                                    {"reach", area_reach(a.data.interaction)},
                                    {"pose", pose_json(a.pose)},
                                    {"extents", {a.extents.width, a.extents.height}},
                                    {"volume_height", a.data.volumeHeight},
                                    {"category_flags", a.data.categoryFlags}});
    }
    if (room_mesh) {
      std::printf("\nroom        entity %llu: MESH_3D with %zu vertices, %zu triangles\n", static_cast<unsigned long long>(room_mesh->id),
                  room_mesh->vertices, room_mesh->triangles);
      placement["room_mesh"] = {{"id", room_mesh->id}, {"vertices", room_mesh->vertices}, {"triangles", room_mesh->triangles}};
    } else {
      std::printf("\nroom        no entity with MESH_3D\n");
    }
  } else {
    std::printf("\nplacement   %s is not listed: no placement areas\n", capability_name(XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX).c_str());
  }
  app.close();

  // ---- spatial_entities.json
  nlohmann::json json;
  json["format"] = "roomsense.spatial_entities/1";
  json["runtime"] = app.runtime_name();
  json["layer"] = layer;
  json["room"] = room;
  json["base_space"] = "LOCAL";
  json["capabilities"] = nlohmann::json::array();
  for (XrSpatialCapabilityEXT c : capabilities) json["capabilities"].push_back(capability_name(c));
  json["plane_components"] = nlohmann::json::array();
  for (Component c : plane_components) json["plane_components"].push_back(component_name(c));
  json["planes"] = nlohmann::json::array();
  for (const Plane& p : planes) {
    nlohmann::json polygon = nlohmann::json::array();
    for (const XrVector2f& v : p.polygon) polygon.push_back({v.x, v.y});
    json["planes"].push_back({{"id", p.id},
                              {"label", p.has_label ? nlohmann::json(label_name(p.label)) : nlohmann::json(nullptr)},
                              {"alignment", p.has_alignment ? nlohmann::json(alignment_name(p.alignment)) : nlohmann::json(nullptr)},
                              {"pose", pose_json(p.pose)},
                              {"extents", {p.extents.width, p.extents.height}},
                              {"polygon", polygon},
                              {"mesh_triangles", p.mesh_triangles ? nlohmann::json(*p.mesh_triangles) : nlohmann::json(nullptr)}});
  }
  json["placement_areas"] = placement;
  json["timing"] = {{"context_ms", context_ms},
                    {"discovery_recommended", recommended},
                    {"first_discovery_ms", first_discovery_ms},
                    {"update_iterations", ids.empty() ? 0 : kUpdateIterations},
                    {"update_snapshot_query_destroy_us", update_us}};
  fs::create_directories(output);
  const fs::path path = output / "spatial_entities.json";
  std::ofstream out(path);
  if (!out || !(out << json.dump(1) << '\n')) throw std::runtime_error("cannot write " + path.string());
  std::printf("\nwrote %s\n", path.string().c_str());
}

}  // namespace roomsense::demo
