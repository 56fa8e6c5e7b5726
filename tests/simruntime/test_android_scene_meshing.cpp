// XR_ANDROID_scene_meshing through the loader: submeshes of a snapshot, posed in LOCAL, are the room file;
// uuids stay across snapshots; per-vertex labels (a Quest capture's objects, or normals for a plain mesh);
// validation; a runtime that plays an Android XR headset (ROOMSENSE_SIM_EXTENSIONS).
#include "mesh_compare.h"
#include "rooms.h"
#include "roomsense/scanio.h"
#include "sim_env.h"
#include "xr_harness.h"

#include "roomsense/xr/ext/XR_ANDROID_scene_meshing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using simtest::proc;
using simtest::ScopedEnv;

struct Android : simtest::App {
  PFN_xrEnumerateSupportedSemanticLabelSetsANDROID labelSets = nullptr;
  PFN_xrCreateSceneMeshingTrackerANDROID createTracker = nullptr;
  PFN_xrDestroySceneMeshingTrackerANDROID destroyTracker = nullptr;
  PFN_xrCreateSceneMeshSnapshotANDROID createSnapshot = nullptr;
  PFN_xrDestroySceneMeshSnapshotANDROID destroySnapshot = nullptr;
  PFN_xrGetAllSubmeshStatesANDROID states = nullptr;
  PFN_xrGetSubmeshDataANDROID data = nullptr;

  Android() : simtest::App({XR_MND_HEADLESS_EXTENSION_NAME, XR_ANDROID_SCENE_MESHING_EXTENSION_NAME}) {
    labelSets = proc<PFN_xrEnumerateSupportedSemanticLabelSetsANDROID>(instance, "xrEnumerateSupportedSemanticLabelSetsANDROID");
    createTracker = proc<PFN_xrCreateSceneMeshingTrackerANDROID>(instance, "xrCreateSceneMeshingTrackerANDROID");
    destroyTracker = proc<PFN_xrDestroySceneMeshingTrackerANDROID>(instance, "xrDestroySceneMeshingTrackerANDROID");
    createSnapshot = proc<PFN_xrCreateSceneMeshSnapshotANDROID>(instance, "xrCreateSceneMeshSnapshotANDROID");
    destroySnapshot = proc<PFN_xrDestroySceneMeshSnapshotANDROID>(instance, "xrDestroySceneMeshSnapshotANDROID");
    states = proc<PFN_xrGetAllSubmeshStatesANDROID>(instance, "xrGetAllSubmeshStatesANDROID");
    data = proc<PFN_xrGetSubmeshDataANDROID>(instance, "xrGetSubmeshDataANDROID");
  }

  XrSceneMeshingTrackerANDROID tracker(XrSceneMeshSemanticLabelSetANDROID set, bool normals = false) const {
    XrSceneMeshingTrackerCreateInfoANDROID info{XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID};
    info.semanticLabelSet = set;
    info.enableNormals = normals ? XR_TRUE : XR_FALSE;
    XrSceneMeshingTrackerANDROID t = XR_NULL_HANDLE;
    SIM_CHECK(createTracker(session, &info, &t));
    return t;
  }

  XrSceneMeshSnapshotCreateInfoANDROID snapshot_info(float extent = 1000.0f) const {
    XrSceneMeshSnapshotCreateInfoANDROID info{XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID};
    info.baseSpace = local;
    info.time = 1;
    info.boundingBox.center.orientation.w = 1;
    info.boundingBox.extents = {extent, extent, extent};
    return info;
  }

  XrSceneMeshSnapshotANDROID snapshot(XrSceneMeshingTrackerANDROID t) const {
    const auto info = snapshot_info();
    XrSceneMeshSnapshotCreationResultANDROID result{XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID};
    SIM_CHECK(createSnapshot(t, &info, &result));
    EXPECT_EQ(result.trackingState, XR_SCENE_MESH_TRACKING_STATE_TRACKING_ANDROID);
    return result.snapshot;
  }

  std::vector<XrSceneSubmeshStateANDROID> all_states(XrSceneMeshSnapshotANDROID s) const {
    uint32_t count = 0;
    SIM_CHECK(states(s, 0, &count, nullptr));
    std::vector<XrSceneSubmeshStateANDROID> out(count, XrSceneSubmeshStateANDROID{XR_TYPE_SCENE_SUBMESH_STATE_ANDROID});
    if (count > 0) SIM_CHECK(states(s, count, &count, out.data()));
    return out;
  }

  struct Submesh {
    simtest::ComponentMesh mesh;  // pose in LOCAL, vertices in the submesh's space
    std::vector<uint8_t> labels;
    std::vector<XrVector3f> normals;
  };

  Submesh read(XrSceneMeshSnapshotANDROID s, const XrSceneSubmeshStateANDROID& state, bool labels, bool normals) const {
    XrSceneSubmeshDataANDROID d{XR_TYPE_SCENE_SUBMESH_DATA_ANDROID};
    d.submeshId = state.submeshId;
    SIM_CHECK(data(s, 1, &d));
    Submesh m;
    m.mesh.pose = state.submeshPoseInBaseSpace;
    m.mesh.vertices.resize(d.vertexCountOutput);
    m.mesh.indices.resize(d.indexCountOutput);
    if (labels) m.labels.resize(d.vertexCountOutput);
    if (normals) m.normals.resize(d.vertexCountOutput);
    d.vertexCapacityInput = d.vertexCountOutput;
    d.vertexPositions = m.mesh.vertices.data();
    d.vertexSemantics = labels ? m.labels.data() : nullptr;
    d.vertexNormals = normals ? m.normals.data() : nullptr;
    d.indexCapacityInput = d.indexCountOutput;
    d.indices = m.mesh.indices.data();
    SIM_CHECK(data(s, 1, &d));
    return m;
  }

  std::vector<Submesh> read_all(XrSceneMeshSnapshotANDROID s, bool labels = false, bool normals = false) const {
    std::vector<Submesh> out;
    for (const auto& state : all_states(s)) out.push_back(read(s, state, labels, normals));
    return out;
  }
};

std::string key(const XrUuid& u) { return std::string(reinterpret_cast<const char*>(u.data), sizeof u.data); }

TEST(AndroidSceneMeshing, SubmeshesPosedInLocalAreTheRoom) {
  const auto path = simtest::write_box_room("android_box.obj");
  const roomsense::Scan file = simtest::join_identical_vertices(roomsense::scanio::load_mesh_file(path.string()));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  ScopedEnv chunk("ROOMSENSE_SIM_CHUNK_SIZE", std::string("1.0"));
  Android a;
  uint32_t count = 0;
  SIM_CHECK(a.labelSets(a.instance, a.system, 0, &count, nullptr));
  std::vector<XrSceneMeshSemanticLabelSetANDROID> sets(count);
  SIM_CHECK(a.labelSets(a.instance, a.system, count, &count, sets.data()));
  EXPECT_EQ(sets, (std::vector<XrSceneMeshSemanticLabelSetANDROID>{XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID,
                                                                    XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID}));
  XrSystemSceneMeshingPropertiesANDROID meshing{XR_TYPE_SYSTEM_SCENE_MESHING_PROPERTIES_ANDROID};
  XrSystemProperties properties{XR_TYPE_SYSTEM_PROPERTIES, &meshing};
  SIM_CHECK(xrGetSystemProperties(a.instance, a.system, &properties));
  EXPECT_EQ(meshing.supportsSceneMeshing, XR_TRUE);
  const auto tracker = a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID);
  const auto snapshot = a.snapshot(tracker);
  std::vector<simtest::ComponentMesh> meshes;
  for (auto& m : a.read_all(snapshot)) meshes.push_back(std::move(m.mesh));
  EXPECT_GT(meshes.size(), 1u);
  const simtest::MeshComparison c = simtest::compare_with_file(file, meshes);
  EXPECT_EQ(c.matched_file_vertices, file.vertices.size());
  EXPECT_EQ(c.served_triangles, file.indices.size() / 3);
  EXPECT_TRUE(c.same_triangles);
  EXPECT_LT(c.max_error, 1e-5);
  EXPECT_GT(c.max_error_without_pose, 0.1) << "vertices must be in the submesh's space";
  // A small box around one corner of the room holds fewer submeshes.
  auto info = a.snapshot_info(0.5f);
  info.boundingBox.center.position = {-1.9f, 0.1f, -1.4f};
  XrSceneMeshSnapshotCreationResultANDROID result{XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID};
  SIM_CHECK(a.createSnapshot(tracker, &info, &result));
  const auto some = a.all_states(result.snapshot);
  EXPECT_GE(some.size(), 1u);
  EXPECT_LT(some.size(), meshes.size());
  EXPECT_EQ(a.destroySnapshot(result.snapshot), XR_SUCCESS);
  EXPECT_EQ(a.destroySnapshot(snapshot), XR_SUCCESS);
  EXPECT_EQ(a.destroyTracker(tracker), XR_SUCCESS);
}

TEST(AndroidSceneMeshing, UuidsAndUpdateTimesStayAcrossSnapshots) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  std::map<std::string, XrTime> times;
  std::size_t submeshes = 0;
  {
  Android a;
  const auto first = a.all_states(a.snapshot(a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID)));
  const auto second = a.all_states(a.snapshot(a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID)));
  ASSERT_GT(first.size(), 1u);
  ASSERT_EQ(first.size(), second.size());
  submeshes = first.size();
  for (const auto& s : first) times[key(s.submeshId)] = s.lastUpdatedTime;
  EXPECT_EQ(times.size(), first.size()) << "uuids must be distinct";
  for (const auto& s : second) {
    ASSERT_EQ(times.count(key(s.submeshId)), 1u);
    EXPECT_EQ(times[key(s.submeshId)], s.lastUpdatedTime);
    EXPECT_GT(s.lastUpdatedTime, 0);
    EXPECT_GT(s.bounds.width * s.bounds.height * s.bounds.depth, 0.0f);
  }
  }
  // A new instance on the same room: the same uuids, as a device keeps its mesh.
  Android b;
  const auto third = b.all_states(b.snapshot(b.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID)));
  ASSERT_EQ(third.size(), submeshes);
  for (const auto& s : third) EXPECT_EQ(times.count(key(s.submeshId)), 1u);
}

TEST(AndroidSceneMeshing, PlainMeshLabelsComeFromNormalsAndNormalsAreUnit) {
  const auto path = simtest::write_box_room("android_box_labels.obj");
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  Android a;
  const auto snapshot = a.snapshot(a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID, true));
  std::map<uint8_t, std::size_t> seen;
  for (const auto& m : a.read_all(snapshot, true, true)) {
    ASSERT_EQ(m.labels.size(), m.mesh.vertices.size());
    for (std::size_t v = 0; v < m.labels.size(); ++v) {
      ++seen[m.labels[v]];
      const glm::dvec3 p = simtest::posed(m.mesh.pose, m.mesh.vertices[v]);
      EXPECT_NEAR(glm::length(glm::dvec3(m.normals[v].x, m.normals[v].y, m.normals[v].z)), 1.0, 1e-5);
      if (m.labels[v] == XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID) {
        EXPECT_NEAR(p.y, 0.0, 1e-4);
      }
      if (m.labels[v] == XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID) {
        EXPECT_NEAR(p.y, 2.5, 1e-4);
      }
    }
  }
  EXPECT_GT(seen[XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID], 0u);
  EXPECT_GT(seen[XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID], 0u);
  EXPECT_GT(seen[XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID], 0u);
}

TEST(AndroidSceneMeshing, AQuestCapturesObjectsLabelItsVertices) {
  ROOMSENSE_REQUIRE_ROOM(path, "quest-iwer/office_small.json");
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  Android a;
  const auto snapshot = a.snapshot(a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID));
  std::map<uint8_t, std::size_t> seen;
  double floor_y = 1e9, ceiling_y = -1e9;
  for (const auto& m : a.read_all(snapshot, true)) {
    ASSERT_EQ(m.labels.size(), m.mesh.vertices.size());
    for (std::size_t v = 0; v < m.labels.size(); ++v) {
      ++seen[m.labels[v]];
      const double y = simtest::posed(m.mesh.pose, m.mesh.vertices[v]).y;
      if (m.labels[v] == XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID) floor_y = std::min(floor_y, y);
      if (m.labels[v] == XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID) ceiling_y = std::max(ceiling_y, y);
    }
  }
  for (uint8_t label : {XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID, XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID,
                        XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID})
    EXPECT_GT(seen[label], 0u) << int(label);
  EXPECT_GT(ceiling_y - floor_y, 1.5);
  // A tracker without labels writes none.
  const auto plain = a.snapshot(a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID));
  const auto state = a.all_states(plain).front();
  std::vector<uint8_t> labels(1u << 16, 0xee);
  XrSceneSubmeshDataANDROID d{XR_TYPE_SCENE_SUBMESH_DATA_ANDROID};
  d.submeshId = state.submeshId;
  SIM_CHECK(a.data(plain, 1, &d));
  std::vector<XrVector3f> vertices(d.vertexCountOutput);
  ASSERT_LE(vertices.size(), labels.size());
  d.vertexCapacityInput = d.vertexCountOutput;
  d.vertexPositions = vertices.data();
  d.vertexSemantics = labels.data();
  SIM_CHECK(a.data(plain, 1, &d));
  EXPECT_TRUE(std::all_of(labels.begin(), labels.end(), [](uint8_t l) { return l == 0xee; }));
}

TEST(AndroidSceneMeshing, Validation) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Android a;
  XrSceneMeshingTrackerCreateInfoANDROID bad{XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID};
  bad.semanticLabelSet = static_cast<XrSceneMeshSemanticLabelSetANDROID>(7);
  XrSceneMeshingTrackerANDROID t = XR_NULL_HANDLE;
  EXPECT_EQ(a.createTracker(a.session, &bad, &t), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(a.createTracker(a.session, nullptr, &t), XR_ERROR_VALIDATION_FAILURE);
  bad.semanticLabelSet = XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID;
  bad.type = XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID;
  EXPECT_EQ(a.createTracker(a.session, &bad, &t), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(a.labelSets(a.instance, 42, 0, nullptr, nullptr), XR_ERROR_SYSTEM_INVALID);
  uint32_t count = 0;
  XrSceneMeshSemanticLabelSetANDROID one{};
  EXPECT_EQ(a.labelSets(a.instance, a.system, 1, &count, &one), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(count, 2u);

  const auto tracker = a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID);
  XrSceneMeshSnapshotCreationResultANDROID result{XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID};
  auto info = a.snapshot_info();
  info.time = 0;
  EXPECT_EQ(a.createSnapshot(tracker, &info, &result), XR_ERROR_TIME_INVALID);
  info = a.snapshot_info();
  info.boundingBox.center.orientation.w = 0;
  EXPECT_EQ(a.createSnapshot(tracker, &info, &result), XR_ERROR_POSE_INVALID);
  info = a.snapshot_info();
  info.boundingBox.extents.width = -1;
  EXPECT_EQ(a.createSnapshot(tracker, &info, &result), XR_ERROR_VALIDATION_FAILURE);
  info = a.snapshot_info();
  info.baseSpace = XR_NULL_HANDLE;
  EXPECT_EQ(a.createSnapshot(tracker, &info, &result), XR_ERROR_HANDLE_INVALID);
  info = a.snapshot_info();
  XrSceneMeshSnapshotCreationResultANDROID wrong{XR_TYPE_SCENE_SUBMESH_STATE_ANDROID};
  EXPECT_EQ(a.createSnapshot(tracker, &info, &wrong), XR_ERROR_VALIDATION_FAILURE);

  const auto snapshot = a.snapshot(tracker);
  const auto states = a.all_states(snapshot);
  ASSERT_GE(states.size(), 2u);
  std::vector<XrSceneSubmeshStateANDROID> untyped(states.size(), XrSceneSubmeshStateANDROID{XR_TYPE_SCENE_SUBMESH_DATA_ANDROID});
  EXPECT_EQ(a.states(snapshot, static_cast<uint32_t>(untyped.size()), &count, untyped.data()), XR_ERROR_VALIDATION_FAILURE);
  std::vector<XrSceneSubmeshStateANDROID> small(1, XrSceneSubmeshStateANDROID{XR_TYPE_SCENE_SUBMESH_STATE_ANDROID});
  EXPECT_EQ(a.states(snapshot, 1, &count, small.data()), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(count, states.size());

  XrSceneSubmeshDataANDROID d[2] = {{XR_TYPE_SCENE_SUBMESH_DATA_ANDROID}, {XR_TYPE_SCENE_SUBMESH_DATA_ANDROID}};
  d[0].submeshId = d[1].submeshId = states[0].submeshId;
  EXPECT_EQ(a.data(snapshot, 2, d), XR_ERROR_VALIDATION_FAILURE) << "the same submesh twice";
  d[1].submeshId = states[1].submeshId;
  EXPECT_EQ(a.data(snapshot, 2, d), XR_SUCCESS) << "counts of two submeshes at once";
  EXPECT_GT(d[1].vertexCountOutput, 0u);
  EXPECT_EQ(a.data(snapshot, 0, d), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(a.data(snapshot, 1, nullptr), XR_ERROR_VALIDATION_FAILURE);
  XrSceneSubmeshDataANDROID unknown{XR_TYPE_SCENE_SUBMESH_DATA_ANDROID};
  EXPECT_EQ(a.data(snapshot, 1, &unknown), XR_ERROR_VALIDATION_FAILURE) << "an id of no submesh";
  std::vector<XrSceneSubmeshDataANDROID> too_many(states.size() + 1, XrSceneSubmeshDataANDROID{XR_TYPE_SCENE_SUBMESH_DATA_ANDROID});
  EXPECT_EQ(a.data(snapshot, static_cast<uint32_t>(too_many.size()), too_many.data()), XR_ERROR_VALIDATION_FAILURE);
  d[0].type = XR_TYPE_SCENE_SUBMESH_STATE_ANDROID;
  EXPECT_EQ(a.data(snapshot, 1, d), XR_ERROR_VALIDATION_FAILURE);
  d[0].type = XR_TYPE_SCENE_SUBMESH_DATA_ANDROID;
  d[0].vertexCapacityInput = 1;
  EXPECT_EQ(a.data(snapshot, 1, d), XR_ERROR_VALIDATION_FAILURE) << "a capacity with no array";
  XrVector3f v{};
  d[0].vertexPositions = &v;
  EXPECT_EQ(a.data(snapshot, 1, d), XR_ERROR_SIZE_INSUFFICIENT);

  // Destroying the tracker takes its snapshots with it.
  EXPECT_EQ(a.destroyTracker(tracker), XR_SUCCESS);
  EXPECT_EQ(a.destroyTracker(tracker), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(a.states(snapshot, 0, &count, nullptr), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(a.destroySnapshot(snapshot), XR_ERROR_HANDLE_INVALID);
}

TEST(AndroidSceneMeshing, ASessionsTrackersGoWithIt) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Android a;
  const auto tracker = a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID);
  const auto snapshot = a.snapshot(tracker);
  SIM_CHECK(xrDestroySession(a.session));
  EXPECT_EQ(a.destroySnapshot(snapshot), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(a.destroyTracker(tracker), XR_ERROR_HANDLE_INVALID);
  a.start_session();
  EXPECT_GT(a.all_states(a.snapshot(a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID))).size(), 1u);
}

TEST(AndroidSceneMeshing, PlayingAnAndroidHeadsetHidesTheOtherSceneExtensions) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME));
  uint32_t count = 0;
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr));
  std::vector<XrExtensionProperties> props(count, XrExtensionProperties{XR_TYPE_EXTENSION_PROPERTIES});
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()));
  std::set<std::string> names;
  for (const auto& p : props) names.insert(p.extensionName);
  EXPECT_EQ(names.count(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME), 1u);
  EXPECT_EQ(names.count(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME), 0u);
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(simtest::create_instance(&instance, {XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME}),
            XR_ERROR_EXTENSION_NOT_PRESENT);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  Android a;
  EXPECT_GT(a.all_states(a.snapshot(a.tracker(XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID))).size(), 1u);
}

}  // namespace
