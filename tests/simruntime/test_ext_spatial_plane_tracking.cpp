// XR_EXT_spatial_entity + XR_EXT_spatial_plane_tracking through the loader: capabilities, a context and a
// discovery snapshot through futures, the synthetic default room's planes (floor, ceiling, walls at the
// generator's heights), buffers, entities from ids, validation, a Quest capture's labelled planes, and a runtime
// that plays an OpenXR 1.1 device (ROOMSENSE_SIM_EXTENSIONS).
#include "rooms.h"
#include "roomsense/synthetic.h"
#include "sim_env.h"
#include "xr_harness.h"

#include "roomsense/xr/ext/XR_EXT_future.h"
#include "roomsense/xr/ext/XR_EXT_spatial_entity.h"
#include "roomsense/xr/ext/XR_EXT_spatial_plane_tracking.h"

#include <glm/gtc/quaternion.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using simtest::proc;
using simtest::ScopedEnv;

// The default room's ground truth.
const float kFloorY = roomsense::synth::default_room().floor_y;
const float kCeilingY = roomsense::synth::default_room().ceiling_y;

const std::vector<XrSpatialComponentTypeEXT> kAll = {
    XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_PLANE_ALIGNMENT_EXT,
    XR_SPATIAL_COMPONENT_TYPE_POLYGON_2D_EXT, XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT,
    XR_SPATIAL_COMPONENT_TYPE_PLANE_SEMANTIC_LABEL_EXT};

struct Plane {
  XrSpatialEntityIdEXT id = 0;
  XrSpatialBounded2DDataEXT bounds{};
  XrSpatialPlaneAlignmentEXT alignment{};
  XrSpatialPolygon2DDataEXT polygon{};
  XrSpatialMeshDataEXT mesh{};
  XrSpatialPlaneSemanticLabelEXT label{};
};

glm::vec3 normal_of(const XrPosef& p) {
  return glm::quat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z) * glm::vec3(0, 0, 1);
}

glm::vec3 apply(const XrPosef& p, glm::vec3 v) {
  return glm::quat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z) * v +
         glm::vec3(p.position.x, p.position.y, p.position.z);
}

struct Device : simtest::App {
  PFN_xrPollFutureEXT poll = nullptr;
  PFN_xrEnumerateSpatialCapabilitiesEXT capabilities = nullptr;
  PFN_xrEnumerateSpatialCapabilityComponentTypesEXT componentTypes = nullptr;
  PFN_xrEnumerateSpatialCapabilityFeaturesEXT features = nullptr;
  PFN_xrCreateSpatialContextAsyncEXT createContext = nullptr;
  PFN_xrCreateSpatialContextCompleteEXT completeContext = nullptr;
  PFN_xrDestroySpatialContextEXT destroyContext = nullptr;
  PFN_xrCreateSpatialDiscoverySnapshotAsyncEXT discover = nullptr;
  PFN_xrCreateSpatialDiscoverySnapshotCompleteEXT completeDiscover = nullptr;
  PFN_xrQuerySpatialComponentDataEXT query = nullptr;
  PFN_xrDestroySpatialSnapshotEXT destroySnapshot = nullptr;
  PFN_xrCreateSpatialEntityFromIdEXT entityFromId = nullptr;
  PFN_xrDestroySpatialEntityEXT destroyEntity = nullptr;
  PFN_xrCreateSpatialUpdateSnapshotEXT update = nullptr;
  PFN_xrGetSpatialBufferVector2fEXT vector2f = nullptr;
  PFN_xrGetSpatialBufferUint16EXT uint16 = nullptr;
  PFN_xrGetSpatialBufferUint32EXT uint32 = nullptr;
  PFN_xrGetSpatialBufferFloatEXT floats = nullptr;

  explicit Device(std::vector<const char*> extensions = {XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME,
                                                         XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME,
                                                         XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME})
      : simtest::App(extensions) {
    poll = proc<PFN_xrPollFutureEXT>(instance, "xrPollFutureEXT");
    capabilities = proc<PFN_xrEnumerateSpatialCapabilitiesEXT>(instance, "xrEnumerateSpatialCapabilitiesEXT");
    componentTypes = proc<PFN_xrEnumerateSpatialCapabilityComponentTypesEXT>(instance, "xrEnumerateSpatialCapabilityComponentTypesEXT");
    features = proc<PFN_xrEnumerateSpatialCapabilityFeaturesEXT>(instance, "xrEnumerateSpatialCapabilityFeaturesEXT");
    createContext = proc<PFN_xrCreateSpatialContextAsyncEXT>(instance, "xrCreateSpatialContextAsyncEXT");
    completeContext = proc<PFN_xrCreateSpatialContextCompleteEXT>(instance, "xrCreateSpatialContextCompleteEXT");
    destroyContext = proc<PFN_xrDestroySpatialContextEXT>(instance, "xrDestroySpatialContextEXT");
    discover = proc<PFN_xrCreateSpatialDiscoverySnapshotAsyncEXT>(instance, "xrCreateSpatialDiscoverySnapshotAsyncEXT");
    completeDiscover = proc<PFN_xrCreateSpatialDiscoverySnapshotCompleteEXT>(instance, "xrCreateSpatialDiscoverySnapshotCompleteEXT");
    query = proc<PFN_xrQuerySpatialComponentDataEXT>(instance, "xrQuerySpatialComponentDataEXT");
    destroySnapshot = proc<PFN_xrDestroySpatialSnapshotEXT>(instance, "xrDestroySpatialSnapshotEXT");
    entityFromId = proc<PFN_xrCreateSpatialEntityFromIdEXT>(instance, "xrCreateSpatialEntityFromIdEXT");
    destroyEntity = proc<PFN_xrDestroySpatialEntityEXT>(instance, "xrDestroySpatialEntityEXT");
    update = proc<PFN_xrCreateSpatialUpdateSnapshotEXT>(instance, "xrCreateSpatialUpdateSnapshotEXT");
    vector2f = proc<PFN_xrGetSpatialBufferVector2fEXT>(instance, "xrGetSpatialBufferVector2fEXT");
    uint16 = proc<PFN_xrGetSpatialBufferUint16EXT>(instance, "xrGetSpatialBufferUint16EXT");
    uint32 = proc<PFN_xrGetSpatialBufferUint32EXT>(instance, "xrGetSpatialBufferUint32EXT");
    floats = proc<PFN_xrGetSpatialBufferFloatEXT>(instance, "xrGetSpatialBufferFloatEXT");
  }

  void wait(XrFutureEXT future) const {
    XrFuturePollInfoEXT info{XR_TYPE_FUTURE_POLL_INFO_EXT};
    info.future = future;
    XrFuturePollResultEXT result{XR_TYPE_FUTURE_POLL_RESULT_EXT};
    for (int i = 0; i < 5000; ++i) {
      SIM_CHECK(poll(instance, &info, &result));
      if (result.state == XR_FUTURE_STATE_READY_EXT) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    throw std::runtime_error("future never ready");
  }

  XrFutureEXT start_context(const std::vector<XrSpatialComponentTypeEXT>& components = kAll) const {
    XrSpatialCapabilityConfigurationPlaneTrackingEXT config{XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT};
    config.capability = XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT;
    config.enabledComponentCount = static_cast<uint32_t>(components.size());
    config.enabledComponents = components.data();
    const auto* header = reinterpret_cast<const XrSpatialCapabilityConfigurationBaseHeaderEXT*>(&config);
    XrSpatialContextCreateInfoEXT info{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT};
    info.capabilityConfigCount = 1;
    info.capabilityConfigs = &header;
    XrFutureEXT future = XR_NULL_FUTURE_EXT;
    SIM_CHECK(createContext(session, &info, &future));
    return future;
  }

  XrSpatialContextEXT context(const std::vector<XrSpatialComponentTypeEXT>& components = kAll) const {
    const XrFutureEXT future = start_context(components);
    wait(future);
    XrCreateSpatialContextCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT};
    SIM_CHECK(completeContext(session, future, &completion));
    SIM_CHECK(completion.futureResult);
    return completion.spatialContext;
  }

  XrSpatialSnapshotEXT snapshot(XrSpatialContextEXT context) const {
    XrSpatialDiscoverySnapshotCreateInfoEXT info{XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT};
    XrFutureEXT future = XR_NULL_FUTURE_EXT;
    SIM_CHECK(discover(context, &info, &future));
    wait(future);
    XrCreateSpatialDiscoverySnapshotCompletionInfoEXT complete{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT};
    complete.baseSpace = local;
    complete.time = 1;
    complete.future = future;
    XrCreateSpatialDiscoverySnapshotCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT};
    SIM_CHECK(completeDiscover(context, &complete, &completion));
    SIM_CHECK(completion.futureResult);
    return completion.snapshot;
  }

  std::vector<Plane> planes(XrSpatialSnapshotEXT snapshot) const {
    XrSpatialComponentDataQueryConditionEXT condition{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT};
    condition.componentTypeCount = static_cast<uint32_t>(kAll.size());
    condition.componentTypes = kAll.data();
    XrSpatialComponentDataQueryResultEXT result{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT};
    SIM_CHECK(query(snapshot, &condition, &result));
    const uint32_t n = result.entityIdCountOutput;
    std::vector<XrSpatialEntityIdEXT> ids(n);
    std::vector<XrSpatialEntityTrackingStateEXT> states(n);
    std::vector<XrSpatialBounded2DDataEXT> bounds(n);
    std::vector<XrSpatialPlaneAlignmentEXT> alignments(n);
    std::vector<XrSpatialPolygon2DDataEXT> polygons(n);
    std::vector<XrSpatialMeshDataEXT> meshes(n);
    std::vector<XrSpatialPlaneSemanticLabelEXT> labels(n);
    XrSpatialComponentPlaneSemanticLabelListEXT label_list{XR_TYPE_SPATIAL_COMPONENT_PLANE_SEMANTIC_LABEL_LIST_EXT, nullptr, n, labels.data()};
    XrSpatialComponentMesh2DListEXT mesh_list{XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT, &label_list, n, meshes.data()};
    XrSpatialComponentPolygon2DListEXT polygon_list{XR_TYPE_SPATIAL_COMPONENT_POLYGON_2D_LIST_EXT, &mesh_list, n, polygons.data()};
    XrSpatialComponentPlaneAlignmentListEXT alignment_list{XR_TYPE_SPATIAL_COMPONENT_PLANE_ALIGNMENT_LIST_EXT, &polygon_list, n, alignments.data()};
    XrSpatialComponentBounded2DListEXT bound_list{XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT, &alignment_list, n, bounds.data()};
    result.next = &bound_list;
    result.entityIdCapacityInput = n;
    result.entityIds = ids.data();
    result.entityStateCapacityInput = n;
    result.entityStates = states.data();
    SIM_CHECK(query(snapshot, &condition, &result));
    std::vector<Plane> out;
    for (uint32_t i = 0; i < n; ++i) {
      EXPECT_EQ(states[i], XR_SPATIAL_ENTITY_TRACKING_STATE_TRACKING_EXT);
      out.push_back({ids[i], bounds[i], alignments[i], polygons[i], meshes[i], labels[i]});
    }
    return out;
  }

  std::vector<XrVector2f> points(XrSpatialSnapshotEXT snapshot, XrSpatialBufferIdEXT id) const {
    XrSpatialBufferGetInfoEXT info{XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT};
    info.bufferId = id;
    uint32_t count = 0;
    SIM_CHECK(vector2f(snapshot, &info, 0, &count, nullptr));
    std::vector<XrVector2f> out(count);
    SIM_CHECK(vector2f(snapshot, &info, count, &count, out.data()));
    return out;
  }

  std::vector<uint32_t> indices(XrSpatialSnapshotEXT snapshot, const XrSpatialBufferEXT& buffer) const {
    XrSpatialBufferGetInfoEXT info{XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT};
    info.bufferId = buffer.bufferId;
    uint32_t count = 0;
    if (buffer.bufferType == XR_SPATIAL_BUFFER_TYPE_UINT16_EXT) {
      SIM_CHECK(uint16(snapshot, &info, 0, &count, nullptr));
      std::vector<uint16_t> small(count);
      SIM_CHECK(uint16(snapshot, &info, count, &count, small.data()));
      return {small.begin(), small.end()};
    }
    SIM_CHECK(uint32(snapshot, &info, 0, &count, nullptr));
    std::vector<uint32_t> out(count);
    SIM_CHECK(uint32(snapshot, &info, count, &count, out.data()));
    return out;
  }
};

std::vector<std::string> advertised() {
  uint32_t count = 0;
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr));
  std::vector<XrExtensionProperties> props(count, XrExtensionProperties{XR_TYPE_EXTENSION_PROPERTIES});
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()));
  std::vector<std::string> names;
  for (const auto& p : props) names.emplace_back(p.extensionName);
  return names;
}

TEST(ExtSpatialPlaneTracking, CapabilitiesComponentsAndFeatures) {
  Device d;
  uint32_t count = 0;
  SIM_CHECK(d.capabilities(d.instance, d.system, 0, &count, nullptr));
  ASSERT_EQ(count, 1u);
  XrSpatialCapabilityEXT capability{};
  SIM_CHECK(d.capabilities(d.instance, d.system, 1, &count, &capability));
  EXPECT_EQ(capability, XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT);
  EXPECT_EQ(d.capabilities(d.instance, d.system + 7, 0, &count, nullptr), XR_ERROR_SYSTEM_INVALID);

  XrSpatialCapabilityComponentTypesEXT types{XR_TYPE_SPATIAL_CAPABILITY_COMPONENT_TYPES_EXT};
  SIM_CHECK(d.componentTypes(d.instance, d.system, XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, &types));
  std::vector<XrSpatialComponentTypeEXT> list(types.componentTypeCountOutput);
  types.componentTypeCapacityInput = static_cast<uint32_t>(list.size());
  types.componentTypes = list.data();
  SIM_CHECK(d.componentTypes(d.instance, d.system, XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, &types));
  for (XrSpatialComponentTypeEXT c : kAll) EXPECT_NE(std::find(list.begin(), list.end(), c), list.end()) << c;
  EXPECT_EQ(list.size(), kAll.size());
  XrSpatialCapabilityComponentTypesEXT wrong{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT};
  EXPECT_EQ(d.componentTypes(d.instance, d.system, XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, &wrong), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(d.componentTypes(d.instance, d.system, XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, nullptr), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(d.componentTypes(d.instance, d.system, XR_SPATIAL_CAPABILITY_ANCHOR_EXT, &types), XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT);

  SIM_CHECK(d.features(d.instance, d.system, XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, 0, &count, nullptr));
  EXPECT_EQ(count, 0u);
}

TEST(ExtSpatialPlaneTracking, NoPlaneCapabilityWithoutThePlaneExtension) {
  Device d({XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME, XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME});
  uint32_t count = 7;
  SIM_CHECK(d.capabilities(d.instance, d.system, 0, &count, nullptr));
  EXPECT_EQ(count, 0u);
  XrSpatialCapabilityConfigurationPlaneTrackingEXT config{XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT};
  config.capability = XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT;
  config.enabledComponentCount = 1;
  config.enabledComponents = kAll.data();
  const auto* header = reinterpret_cast<const XrSpatialCapabilityConfigurationBaseHeaderEXT*>(&config);
  XrSpatialContextCreateInfoEXT info{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT};
  info.capabilityConfigCount = 1;
  info.capabilityConfigs = &header;
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  EXPECT_EQ(d.createContext(d.session, &info, &future), XR_ERROR_SPATIAL_CAPABILITY_UNSUPPORTED_EXT);
}

TEST(ExtSpatialPlaneTracking, SyntheticRoomPlanesAtTheRightHeights) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Device d;
  const XrSpatialContextEXT context = d.context();
  // One discovery-recommended event for the new context.
  int recommended = 0;
  for (;;) {
    XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
    const XrResult r = xrPollEvent(d.instance, &e);
    if (r == XR_EVENT_UNAVAILABLE) break;
    SIM_CHECK(r);
    if (e.type == XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT) {
      ++recommended;
      EXPECT_EQ(reinterpret_cast<const XrEventDataSpatialDiscoveryRecommendedEXT*>(&e)->spatialContext, context);
    }
  }
  EXPECT_EQ(recommended, 1);

  const XrSpatialSnapshotEXT snapshot = d.snapshot(context);
  const std::vector<Plane> planes = d.planes(snapshot);
  int floors = 0, ceilings = 0, walls = 0;
  double floor_area = 0.0;
  for (const Plane& p : planes) {
    const glm::vec3 n = normal_of(p.bounds.center);
    EXPECT_GT(p.bounds.extents.width * p.bounds.extents.height, 0.2f);
    switch (p.label) {
      case XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT:
        ++floors;
        EXPECT_NEAR(p.bounds.center.position.y, kFloorY, 0.02);
        EXPECT_GT(n.y, 0.99f);
        EXPECT_EQ(p.alignment, XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT);
        break;
      case XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT:
        ++ceilings;
        EXPECT_NEAR(p.bounds.center.position.y, kCeilingY, 0.02);
        EXPECT_LT(n.y, -0.99f);
        EXPECT_EQ(p.alignment, XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT);
        break;
      case XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT:
        ++walls;
        EXPECT_LT(std::fabs(n.y), 0.05f);
        EXPECT_EQ(p.alignment, XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT);
        break;
      default: break;
    }
    // The polygon and the mesh: 2D buffers in the plane, placed by their origin.
    EXPECT_GE(d.points(snapshot, p.polygon.vertexBuffer.bufferId).size(), 3u);
    ASSERT_EQ(p.mesh.vertexBuffer.bufferType, XR_SPATIAL_BUFFER_TYPE_VECTOR2F_EXT);
    const std::vector<XrVector2f> vertices = d.points(snapshot, p.mesh.vertexBuffer.bufferId);
    const std::vector<uint32_t> indices = d.indices(snapshot, p.mesh.indexBuffer);
    ASSERT_EQ(indices.size() % 3, 0u);
    double area = 0.0;
    for (std::size_t i = 0; i < indices.size(); i += 3) {
      ASSERT_LT(std::max({indices[i], indices[i + 1], indices[i + 2]}), vertices.size());
      const XrVector2f &a = vertices[indices[i]], &b = vertices[indices[i + 1]], &c = vertices[indices[i + 2]];
      const double cross = (double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x);
      EXPECT_GT(cross, 0.0) << "triangles are counter-clockwise seen from +Z";
      area += cross * 0.5;
    }
    if (p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT) {
      floor_area += area;
      const glm::vec3 v = apply(p.mesh.origin, {vertices[0].x, vertices[0].y, 0.0f});
      EXPECT_NEAR(v.y, kFloorY, 0.02);
      EXPECT_LT(std::fabs(v.x), 2.6f);
      EXPECT_LT(std::fabs(v.z), 2.1f);
    }
  }
  EXPECT_GE(floors, 1);
  EXPECT_EQ(ceilings, 1);
  EXPECT_GE(walls, 4);
  EXPECT_GT(floor_area, 12.0);  // 5 x 4 m, less what the furniture hides
  EXPECT_LT(floor_area, 20.5);

  // An entity from an id, located again by an update snapshot.
  XrSpatialEntityFromIdCreateInfoEXT from{XR_TYPE_SPATIAL_ENTITY_FROM_ID_CREATE_INFO_EXT};
  from.entityId = planes.front().id;
  XrSpatialEntityEXT entity = XR_NULL_HANDLE;
  SIM_CHECK(d.entityFromId(context, &from, &entity));
  XrSpatialUpdateSnapshotCreateInfoEXT update{XR_TYPE_SPATIAL_UPDATE_SNAPSHOT_CREATE_INFO_EXT};
  update.entityCount = 1;
  update.entities = &entity;
  update.baseSpace = d.local;
  update.time = 1;
  XrSpatialSnapshotEXT updated = XR_NULL_HANDLE;
  SIM_CHECK(d.update(context, &update, &updated));
  const std::vector<Plane> again = d.planes(updated);
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].id, planes.front().id);
  EXPECT_EQ(again[0].bounds.center.position.y, planes.front().bounds.center.position.y);
  from.entityId = 999999;
  XrSpatialEntityEXT bad = XR_NULL_HANDLE;
  EXPECT_EQ(d.entityFromId(context, &from, &bad), XR_ERROR_SPATIAL_ENTITY_ID_INVALID_EXT);
  SIM_CHECK(d.destroyEntity(entity));
  EXPECT_EQ(d.destroyEntity(entity), XR_ERROR_HANDLE_INVALID);
  SIM_CHECK(d.destroySnapshot(updated));
  SIM_CHECK(d.destroySnapshot(snapshot));
  EXPECT_EQ(d.destroySnapshot(snapshot), XR_ERROR_HANDLE_INVALID);
  SIM_CHECK(d.destroyContext(context));
  EXPECT_EQ(d.destroyContext(context), XR_ERROR_HANDLE_INVALID);
}

TEST(ExtSpatialPlaneTracking, ValidationErrors) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv delay("ROOMSENSE_SIM_COMPUTE_DELAY_MS", std::string("300"));
  Device d;
  // Wrong structure types and null pointers.
  XrSpatialContextCreateInfoEXT wrong{XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT};
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  EXPECT_EQ(d.createContext(d.session, &wrong, &future), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(d.createContext(d.session, nullptr, &future), XR_ERROR_VALIDATION_FAILURE);
  XrSpatialContextCreateInfoEXT empty{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT};
  EXPECT_EQ(d.createContext(d.session, &empty, &future), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(d.createContext(XR_NULL_HANDLE, &empty, &future), XR_ERROR_HANDLE_INVALID);
  // A component plane tracking does not have.
  XrSpatialCapabilityConfigurationPlaneTrackingEXT config{XR_TYPE_SPATIAL_CAPABILITY_CONFIGURATION_PLANE_TRACKING_EXT};
  config.capability = XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT;
  const XrSpatialComponentTypeEXT box = XR_SPATIAL_COMPONENT_TYPE_BOUNDED_3D_EXT;
  config.enabledComponentCount = 1;
  config.enabledComponents = &box;
  const auto* header = reinterpret_cast<const XrSpatialCapabilityConfigurationBaseHeaderEXT*>(&config);
  XrSpatialContextCreateInfoEXT info{XR_TYPE_SPATIAL_CONTEXT_CREATE_INFO_EXT};
  info.capabilityConfigCount = 1;
  info.capabilityConfigs = &header;
  EXPECT_EQ(d.createContext(d.session, &info, &future), XR_ERROR_SPATIAL_COMPONENT_UNSUPPORTED_FOR_CAPABILITY_EXT);
  config.enabledComponentCount = 0;
  EXPECT_EQ(d.createContext(d.session, &info, &future), XR_ERROR_SPATIAL_CAPABILITY_CONFIGURATION_INVALID_EXT);
  EXPECT_EQ(d.createContext(d.session, &info, nullptr), XR_ERROR_VALIDATION_FAILURE);

  // A pending future, then a completed one completed twice.
  future = d.start_context({XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT});
  XrCreateSpatialContextCompletionEXT completion{XR_TYPE_CREATE_SPATIAL_CONTEXT_COMPLETION_EXT};
  EXPECT_EQ(d.completeContext(d.session, future, &completion), XR_ERROR_FUTURE_PENDING_EXT);
  XrCreateSpatialContextCompletionEXT wrong_completion{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT};
  d.wait(future);
  EXPECT_EQ(d.completeContext(d.session, future, &wrong_completion), XR_ERROR_VALIDATION_FAILURE);
  SIM_CHECK(d.completeContext(d.session, future, &completion));
  const XrSpatialContextEXT context = completion.spatialContext;
  EXPECT_EQ(d.completeContext(d.session, future, &completion), XR_ERROR_FUTURE_INVALID_EXT);

  // Discovery: a component the context did not enable; a bad handle; a bad base space.
  const XrSpatialComponentTypeEXT mesh = XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT;
  XrSpatialDiscoverySnapshotCreateInfoEXT discover{XR_TYPE_SPATIAL_DISCOVERY_SNAPSHOT_CREATE_INFO_EXT};
  discover.componentTypeCount = 1;
  discover.componentTypes = &mesh;
  EXPECT_EQ(d.discover(context, &discover, &future), XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT);
  discover.componentTypeCount = 0;
  EXPECT_EQ(d.discover(XR_NULL_HANDLE, &discover, &future), XR_ERROR_HANDLE_INVALID);
  SIM_CHECK(d.discover(context, &discover, &future));
  XrCreateSpatialDiscoverySnapshotCompletionInfoEXT complete{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_INFO_EXT};
  complete.baseSpace = d.local;
  complete.time = 1;
  complete.future = future;
  XrCreateSpatialDiscoverySnapshotCompletionEXT snapshot_completion{XR_TYPE_CREATE_SPATIAL_DISCOVERY_SNAPSHOT_COMPLETION_EXT};
  EXPECT_EQ(d.completeDiscover(context, &complete, &snapshot_completion), XR_ERROR_FUTURE_PENDING_EXT);
  d.wait(future);
  complete.time = 0;
  EXPECT_EQ(d.completeDiscover(context, &complete, &snapshot_completion), XR_ERROR_TIME_INVALID);
  complete.time = 1;
  complete.baseSpace = XR_NULL_HANDLE;
  EXPECT_EQ(d.completeDiscover(context, &complete, &snapshot_completion), XR_ERROR_HANDLE_INVALID);
  complete.baseSpace = d.local;
  EXPECT_EQ(d.completeDiscover(context, nullptr, &snapshot_completion), XR_ERROR_VALIDATION_FAILURE);
  SIM_CHECK(d.completeDiscover(context, &complete, &snapshot_completion));
  const XrSpatialSnapshotEXT snapshot = snapshot_completion.snapshot;
  EXPECT_EQ(d.completeDiscover(context, &complete, &snapshot_completion), XR_ERROR_FUTURE_INVALID_EXT);

  // Queries: a list the condition does not name, a component the context lacks, short capacities.
  const XrSpatialComponentTypeEXT bounded = XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT;
  XrSpatialComponentDataQueryConditionEXT condition{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_CONDITION_EXT};
  condition.componentTypeCount = 1;
  condition.componentTypes = &bounded;
  XrSpatialComponentDataQueryResultEXT result{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT};
  SIM_CHECK(d.query(snapshot, &condition, &result));
  ASSERT_GT(result.entityIdCountOutput, 2u);
  std::vector<XrSpatialEntityIdEXT> ids(result.entityIdCountOutput);
  std::vector<XrSpatialBounded2DDataEXT> bounds(ids.size() - 1);
  XrSpatialComponentBounded2DListEXT bound_list{XR_TYPE_SPATIAL_COMPONENT_BOUNDED_2D_LIST_EXT, nullptr,
                                                static_cast<uint32_t>(bounds.size()), bounds.data()};
  result.next = &bound_list;
  result.entityIdCapacityInput = static_cast<uint32_t>(ids.size());
  result.entityIds = ids.data();
  EXPECT_EQ(d.query(snapshot, &condition, &result), XR_ERROR_SIZE_INSUFFICIENT);
  result.entityIdCapacityInput = 1;
  EXPECT_EQ(d.query(snapshot, &condition, &result), XR_ERROR_SIZE_INSUFFICIENT);
  result.entityIdCapacityInput = static_cast<uint32_t>(ids.size());
  XrSpatialComponentMesh2DListEXT mesh_list{XR_TYPE_SPATIAL_COMPONENT_MESH_2D_LIST_EXT, nullptr, 0, nullptr};
  result.next = &mesh_list;
  EXPECT_EQ(d.query(snapshot, &condition, &result), XR_ERROR_VALIDATION_FAILURE);
  condition.componentTypes = &mesh;
  result.next = nullptr;
  EXPECT_EQ(d.query(snapshot, &condition, &result), XR_ERROR_SPATIAL_COMPONENT_NOT_ENABLED_EXT);
  XrSpatialComponentDataQueryConditionEXT wrong_condition{XR_TYPE_SPATIAL_COMPONENT_DATA_QUERY_RESULT_EXT};
  EXPECT_EQ(d.query(snapshot, &wrong_condition, &result), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(d.query(snapshot, &condition, nullptr), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(d.query(XR_NULL_HANDLE, &condition, &result), XR_ERROR_HANDLE_INVALID);

  // Buffers: an id no snapshot has.
  XrSpatialBufferGetInfoEXT buffer{XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT};
  buffer.bufferId = 12345678;
  uint32_t count = 0;
  EXPECT_EQ(d.vector2f(snapshot, &buffer, 0, &count, nullptr), XR_ERROR_SPATIAL_BUFFER_ID_INVALID_EXT);
  EXPECT_EQ(d.vector2f(snapshot, nullptr, 0, &count, nullptr), XR_ERROR_VALIDATION_FAILURE);
  SIM_CHECK(d.destroyContext(context));  // takes the snapshot with it
  EXPECT_EQ(d.destroySnapshot(snapshot), XR_ERROR_HANDLE_INVALID);
}

TEST(ExtSpatialPlaneTracking, BufferGettersMatchTheBufferType) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Device d;
  const XrSpatialContextEXT context = d.context();
  const XrSpatialSnapshotEXT snapshot = d.snapshot(context);
  const std::vector<Plane> planes = d.planes(snapshot);
  ASSERT_FALSE(planes.empty());
  XrSpatialBufferGetInfoEXT info{XR_TYPE_SPATIAL_BUFFER_GET_INFO_EXT};
  info.bufferId = planes[0].polygon.vertexBuffer.bufferId;
  uint32_t count = 0;
  EXPECT_EQ(d.floats(snapshot, &info, 0, &count, nullptr), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(d.uint32(snapshot, &info, 0, &count, nullptr), XR_ERROR_VALIDATION_FAILURE);
  SIM_CHECK(d.vector2f(snapshot, &info, 0, &count, nullptr));
  std::vector<XrVector2f> small(count > 0 ? count - 1 : 0);
  EXPECT_EQ(d.vector2f(snapshot, &info, static_cast<uint32_t>(small.size()), &count, small.data()), XR_ERROR_SIZE_INSUFFICIENT);
  info.bufferId = planes[0].mesh.indexBuffer.bufferId;
  EXPECT_EQ(d.vector2f(snapshot, &info, 0, &count, nullptr), XR_ERROR_VALIDATION_FAILURE);
  SIM_CHECK(d.destroySnapshot(snapshot));
  // A destroyed snapshot's buffers are gone with it.
  EXPECT_EQ(d.vector2f(snapshot, &info, 0, &count, nullptr), XR_ERROR_HANDLE_INVALID);
}

TEST(ExtSpatialPlaneTracking, QuestCaptureServesItsLabelledPlanes) {
  ROOMSENSE_REQUIRE_ROOM(path, "quest-iwer/living_room.json");
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  Device d;
  const XrSpatialContextEXT context = d.context();
  const XrSpatialSnapshotEXT snapshot = d.snapshot(context);
  int floors = 0, ceilings = 0, walls = 0;
  for (const Plane& p : d.planes(snapshot)) {
    floors += p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT;
    ceilings += p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT;
    walls += p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT;
    if (p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT) {
      EXPECT_GT(normal_of(p.bounds.center).y, 0.99f);
    }
    if (p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT) {
      EXPECT_LT(normal_of(p.bounds.center).y, -0.99f);
    }
    EXPECT_EQ(d.points(snapshot, p.polygon.vertexBuffer.bufferId).size(), 4u);  // the capture's rectangles
  }
  EXPECT_EQ(floors, 1);
  EXPECT_EQ(ceilings, 1);
  EXPECT_GE(walls, 3);
}

TEST(ExtSpatialPlaneTracking, TheVariablePlaysAnOpenXr11Device) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_EXT_spatial_entity,XR_EXT_spatial_plane_tracking"));
  const auto names = advertised();
  auto has = [&](const char* n) { return std::find(names.begin(), names.end(), n) != names.end(); };
  EXPECT_TRUE(has(XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME));
  EXPECT_TRUE(has(XR_EXT_SPATIAL_PLANE_TRACKING_EXTENSION_NAME));
  EXPECT_TRUE(has(XR_EXT_FUTURE_EXTENSION_NAME));
  EXPECT_FALSE(has(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME));
  EXPECT_FALSE(has("XR_META_spatial_entity_mesh"));
  // Naming the plane extension alone brings the spatial entity one it builds on.
  ScopedEnv plane_only("ROOMSENSE_SIM_EXTENSIONS", std::string("XR_EXT_spatial_plane_tracking"));
  const auto fewer = advertised();
  EXPECT_NE(std::find(fewer.begin(), fewer.end(), XR_EXT_SPATIAL_ENTITY_EXTENSION_NAME), fewer.end());
}

}  // namespace
