// XR_ANDROID_scene_meshing (see the header). The room is split into chunks (scene_data.h) once per room and
// chunk size; every snapshot of every tracker serves those chunks as submeshes, so their uuids and
// lastUpdatedTime stay the same across snapshots, as a device's do while the room does not change (while it is
// being scanned, scan_progress.h, a chunk's time is when it last changed).
// Per-vertex labels (DEFAULT label set): a Quest capture's labelled objects give the label of the triangles near
// their planes; elsewhere, and in plain mesh files, the triangle's normal decides (up-facing at floor level:
// floor, down-facing at the top: ceiling, vertical: wall, the rest: other). A vertex takes the label most of its
// triangles in the submesh have.
#include "android_scene_meshing.h"
#include "../process_state.h"

#include "stable_uuid.h"

#include "../faults.h"
#include "../functions.h"
#include "../log.h"
#include "../runtime.h"
#include "../spaces.h"
#include "../validate.h"
#include "roomsense/xr/ext/XR_ANDROID_scene_meshing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

namespace roomsense::sim {
namespace {

constexpr double kObjectReach = 0.25;   // metres: a triangle this close to a labelled plane takes its label
constexpr double kLevelBand = 0.30;     // metres above the lowest / below the highest point: floor / ceiling level
constexpr double kFlat = 0.8;           // |normal.y| above this: up- or down-facing
constexpr double kVertical = 0.3;       // |normal.y| below this: a wall

struct Submesh {
  XrUuid uuid{};
  XrTime updated = 0;                  // its lastUpdatedTime
  Rigid pose;                          // in world space, rounded to what an XrPosef holds
  std::vector<XrVector3f> vertices;    // in the submesh's space
  std::vector<XrVector3f> normals;
  std::vector<std::uint8_t> labels;    // XrSceneMeshSemanticLabelANDROID per vertex
  std::vector<std::uint32_t> indices;
  XrExtent3Df bounds{};                // a box about the pose holding every vertex
  glm::dvec3 world_centre{0.0};
  double world_radius = 0.0;
};

struct MeshScene {
  std::vector<Submesh> submeshes;
};

struct Tracker {
  std::uint64_t session = 0, instance = 0;
  XrSceneMeshSemanticLabelSetANDROID labels = XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID;
  bool normals = false;
};

struct Snapshot {
  std::uint64_t tracker = 0, session = 0;
  std::shared_ptr<const MeshScene> scene;
  Rigid world_to_base;
  std::vector<std::size_t> submeshes;  // indices into scene->submeshes inside the bounding box
};

// Guarded by runtime().mutex.
struct State {
  std::unordered_map<std::uint64_t, Tracker> trackers;
  std::unordered_map<std::uint64_t, Snapshot> snapshots;
  BuiltPerStep<MeshScene, Submesh> built;  // from the room as scanned (scan_progress.h)
};

State& state() {
  return process_wide<State>();
}




std::uint8_t label_of_name(const std::string& name) {
  auto has = [&](const char* word) { return name.find(word) != std::string::npos; };
  if (has("FLOOR")) return XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID;
  if (has("CEILING")) return XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID;
  if (has("WALL")) return XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID;
  if (has("TABLE") || has("DESK")) return XR_SCENE_MESH_SEMANTIC_LABEL_TABLE_ANDROID;
  return XR_SCENE_MESH_SEMANTIC_LABEL_OTHER_ANDROID;
}

// Labels a world-space triangle.
struct Labeller {
  const Room& room;
  double low = 0.0, high = 0.0;
  std::vector<std::pair<Rigid, glm::dvec2>> planes;  // each object's plane pose and half size
  std::vector<std::uint8_t> plane_labels;

  explicit Labeller(const Room& r) : room(r) {
    if (!r.mesh.vertices.empty()) {
      low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
      for (const glm::vec3& v : r.mesh.vertices) low = std::min(low, double(v.y)), high = std::max(high, double(v.y));
    }
    for (const RoomObject& o : r.objects) {
      if (o.label.empty() || !is_valid_pose(o.plane_pose)) continue;
      planes.push_back({to_rigid(o.plane_pose).inverse(), glm::dvec2(o.plane_size.width, o.plane_size.height) * 0.5});
      plane_labels.push_back(label_of_name(o.label));
    }
  }

  std::uint8_t operator()(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) const {
    const glm::dvec3 centroid = (a + b + c) / 3.0;
    double best = kObjectReach;
    std::uint8_t label = 0xff;
    for (std::size_t i = 0; i < planes.size(); ++i) {
      const glm::dvec3 p = planes[i].first.apply(centroid);
      const double dx = std::max(std::abs(p.x) - planes[i].second.x, 0.0);
      const double dy = std::max(std::abs(p.y) - planes[i].second.y, 0.0);
      const double d = std::sqrt(dx * dx + dy * dy + p.z * p.z);
      if (d < best) best = d, label = plane_labels[i];
    }
    if (label != 0xff) return label;
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double length = glm::length(cross);
    if (!(length > 0.0)) return XR_SCENE_MESH_SEMANTIC_LABEL_OTHER_ANDROID;
    const double ny = cross.y / length;
    if (ny > kFlat && centroid.y < low + kLevelBand) return XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID;
    if (ny < -kFlat && centroid.y > high - kLevelBand) return XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID;
    if (std::abs(ny) < kVertical) return XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID;
    return XR_SCENE_MESH_SEMANTIC_LABEL_OTHER_ANDROID;
  }
};

XrVector3f to_xr(const glm::dvec3& v) { return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)}; }
glm::dvec3 to_glm(const XrVector3f& v) { return {v.x, v.y, v.z}; }

// A chunk as a submesh (its update time aside).
Submesh build_submesh(const Chunk& chunk, const Labeller& labeller, const std::string& source, double chunk_size) {
  Submesh s;
  // By the chunk's cell, so a submesh keeps its id while others appear (scan_progress.h).
  s.uuid = stable_uuid(source, chunked_salt(0x414e44524f4944ull /* "ANDROID" */, chunk_size), cell_key(chunk.cell));
  // The pose as an XrPosef holds it; the vertices were made in the unrounded frame, so move them over.
  s.pose = to_rigid(to_pose(chunk.pose));
  const Rigid to_local = s.pose.inverse() * chunk.pose;
  s.vertices.reserve(chunk.mesh.vertices.size());
  std::vector<glm::dvec3> world;
  world.reserve(chunk.mesh.vertices.size());
  glm::dvec3 extent(0.0);
  for (const XrVector3f& v : chunk.mesh.vertices) {
    const glm::dvec3 local = to_local.apply(to_glm(v));
    s.vertices.push_back(to_xr(local));
    world.push_back(chunk.pose.apply(to_glm(v)));
    extent = glm::max(extent, glm::abs(local));
  }
  s.bounds = {static_cast<float>(2.0 * extent.x), static_cast<float>(2.0 * extent.y), static_cast<float>(2.0 * extent.z)};
  s.world_centre = s.pose.translation;
  s.world_radius = glm::length(extent);
  s.indices = chunk.mesh.indices;

  // Normals (area-weighted face normals, in the submesh's space) and label votes per vertex.
  std::vector<glm::dvec3> normals(s.vertices.size(), glm::dvec3(0.0));
  std::vector<std::array<std::uint32_t, 5>> votes(s.vertices.size(), std::array<std::uint32_t, 5>{});
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3) {
    const std::uint32_t i0 = s.indices[t], i1 = s.indices[t + 1], i2 = s.indices[t + 2];
    const glm::dvec3 n = glm::cross(to_glm(s.vertices[i1]) - to_glm(s.vertices[i0]), to_glm(s.vertices[i2]) - to_glm(s.vertices[i0]));
    const std::uint8_t label = labeller(world[i0], world[i1], world[i2]);
    for (std::uint32_t i : {i0, i1, i2}) {
      normals[i] += n;
      ++votes[i][label];
    }
  }
  s.normals.reserve(normals.size());
  s.labels.reserve(normals.size());
  for (std::size_t v = 0; v < normals.size(); ++v) {
    const double length = glm::length(normals[v]);
    s.normals.push_back(length > 0.0 ? to_xr(normals[v] / length) : XrVector3f{0.0f, 1.0f, 0.0f});
    const auto& vote = votes[v];
    s.labels.push_back(static_cast<std::uint8_t>(std::max_element(vote.begin(), vote.end()) - vote.begin()));
  }
  return s;
}

// The scene of an instance's room as scanned now, built once per step of the scan (the whole room, where it is not
// being scanned), each chunk's submesh once while the chunk is held: a step of a scan changes a chunk or two.
// Labels come from the whole room, so a chunk's are the same at every step. Call under the lock.
std::shared_ptr<const MeshScene> scene_of(const InstanceState& instance) {
  const std::shared_ptr<const ScanStep> scanned = instance.room_at(now_time());
  if (!scanned) return nullptr;
  return state().built.scene(scanned, [&] {
    MeshScene scene;
    const XrTime built = now_time();
    std::optional<Labeller> labeller;
    for (const SharedChunk& chunk : scanned->chunks) {
      Submesh s = state().built.piece(chunk, [&] {
        if (!labeller) labeller.emplace(*scanned->room);
        return build_submesh(*chunk, *labeller, scanned->room->source, instance.config.chunk_size);
      });
      s.updated = scanned->update_time(chunk->cell, built);
      scene.submeshes.push_back(std::move(s));
    }
    return scene;
  });
}

bool finite(const XrVector3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

const InstanceState* instance_of_session(std::uint64_t session) {
  const SessionState* s = Runtime::find(runtime().sessions, session);
  return s ? Runtime::find(runtime().instances, s->instance) : nullptr;
}

void destroy_snapshots_of_tracker(std::uint64_t tracker) {
  std::erase_if(state().snapshots, [&](const auto& e) { return e.second.tracker == tracker; });
}

XrResult XRAPI_CALL xrEnumerateSupportedSemanticLabelSetsANDROID(XrInstance instance, XrSystemId systemId, uint32_t capacity,
                                                                 uint32_t* countOutput,
                                                                 XrSceneMeshSemanticLabelSetANDROID* labelSets) {
  return guarded("xrEnumerateSupportedSemanticLabelSetsANDROID", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const InstanceState* state = runtime().instance(instance);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!state->has(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME)) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    return two_call(capacity, countOutput, labelSets,
                    std::vector<XrSceneMeshSemanticLabelSetANDROID>{XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID,
                                                                     XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID});
  });
}

XrResult XRAPI_CALL xrCreateSceneMeshingTrackerANDROID(XrSession session, const XrSceneMeshingTrackerCreateInfoANDROID* createInfo,
                                                       XrSceneMeshingTrackerANDROID* tracker) {
  return guarded("xrCreateSceneMeshingTrackerANDROID", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SessionState* owner = runtime().session(session);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    const InstanceState* instance = Runtime::find(runtime().instances, owner->instance);
    if (instance == nullptr || !instance->has(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME)) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!has_type(createInfo, XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID) || tracker == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->semanticLabelSet != XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID &&
        createInfo->semanticLabelSet != XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID)
      return XR_ERROR_VALIDATION_FAILURE;
    const std::uint64_t id = runtime().new_id();
    state().trackers[id] = Tracker{id_of(session), owner->instance, createInfo->semanticLabelSet, createInfo->enableNormals == XR_TRUE};
    *tracker = handle_of<XrSceneMeshingTrackerANDROID>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySceneMeshingTrackerANDROID(XrSceneMeshingTrackerANDROID tracker) {
  return guarded("xrDestroySceneMeshingTrackerANDROID", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (state().trackers.erase(id_of(tracker)) != 1) return XR_ERROR_HANDLE_INVALID;
    destroy_snapshots_of_tracker(id_of(tracker));  // its children go with it
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrCreateSceneMeshSnapshotANDROID(XrSceneMeshingTrackerANDROID tracker,
                                                     const XrSceneMeshSnapshotCreateInfoANDROID* createInfo,
                                                     XrSceneMeshSnapshotCreationResultANDROID* result) {
  return guarded("xrCreateSceneMeshSnapshotANDROID", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().trackers.find(id_of(tracker));
    if (it == state().trackers.end()) return XR_ERROR_HANDLE_INVALID;
    const Tracker& owner = it->second;
    if (!has_type(createInfo, XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID) ||
        !has_type(result, XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID))
      return XR_ERROR_VALIDATION_FAILURE;
    const SpaceState* base = runtime().space(createInfo->baseSpace);
    if (base == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (base->session != owner.session) return XR_ERROR_VALIDATION_FAILURE;
    if (createInfo->time <= 0) return XR_ERROR_TIME_INVALID;
    const XrBoxf& box = createInfo->boundingBox;
    if (!is_valid_pose(box.center)) return XR_ERROR_POSE_INVALID;
    const XrVector3f extents{box.extents.width, box.extents.height, box.extents.depth};
    if (!finite(extents) || extents.x < 0 || extents.y < 0 || extents.z < 0) return XR_ERROR_VALIDATION_FAILURE;
    Rigid base_world;
    if (!space_in_world(*base, base_world)) return XR_ERROR_HANDLE_INVALID;
    const InstanceState* instance = instance_of_session(owner.session);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;

    Snapshot snapshot;
    snapshot.tracker = id_of(tracker);
    snapshot.session = owner.session;
    snapshot.world_to_base = base_world.inverse();
    snapshot.scene = scene_of(*instance);
    result->trackingState = XR_SCENE_MESH_TRACKING_STATE_TRACKING_ANDROID;
    if (!snapshot.scene) {
      log_error("scene mesh snapshot: ROOMSENSE_SIM_SCENE is not set, so there is no room to serve");
      result->trackingState = XR_SCENE_MESH_TRACKING_STATE_ERROR_ANDROID;
      snapshot.scene = std::make_shared<MeshScene>();
    }
    // Submeshes whose bounding sphere meets the box (a superset, as a runtime may return more).
    const Rigid world_to_box = (base_world * to_rigid(box.center)).inverse();
    const glm::dvec3 half = glm::dvec3(extents.x, extents.y, extents.z) * 0.5;
    for (std::size_t i = 0; i < snapshot.scene->submeshes.size(); ++i) {
      const Submesh& s = snapshot.scene->submeshes[i];
      const glm::dvec3 p = glm::abs(world_to_box.apply(s.world_centre));
      if (p.x <= half.x + s.world_radius && p.y <= half.y + s.world_radius && p.z <= half.z + s.world_radius)
        snapshot.submeshes.push_back(i);
    }
    if (faults::pending(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME))  // still initializing: no submeshes, ever
      result->trackingState = XR_SCENE_MESH_TRACKING_STATE_INITIALIZING_ANDROID, snapshot.submeshes.clear();
    const std::uint64_t id = runtime().new_id();
    state().snapshots[id] = std::move(snapshot);
    result->snapshot = handle_of<XrSceneMeshSnapshotANDROID>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySceneMeshSnapshotANDROID(XrSceneMeshSnapshotANDROID snapshot) {
  return guarded("xrDestroySceneMeshSnapshotANDROID", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    return state().snapshots.erase(id_of(snapshot)) == 1 ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
  });
}

XrResult XRAPI_CALL xrGetAllSubmeshStatesANDROID(XrSceneMeshSnapshotANDROID snapshot, uint32_t capacity, uint32_t* countOutput,
                                                 XrSceneSubmeshStateANDROID* states) {
  return guarded("xrGetAllSubmeshStatesANDROID", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().snapshots.find(id_of(snapshot));
    if (it == state().snapshots.end()) return XR_ERROR_HANDLE_INVALID;
    const Snapshot& s = it->second;
    return two_call_typed(capacity, countOutput, states, s.submeshes.size(), XR_TYPE_SCENE_SUBMESH_STATE_ANDROID,
                          [&](XrSceneSubmeshStateANDROID& out, std::size_t i) {
                            const Submesh& m = s.scene->submeshes[s.submeshes[i]];
                            out.submeshId = m.uuid;
                            out.lastUpdatedTime = m.updated;
                            out.submeshPoseInBaseSpace = to_pose(s.world_to_base * m.pose);
                            out.bounds = m.bounds;
                          });
  });
}

XrResult XRAPI_CALL xrGetSubmeshDataANDROID(XrSceneMeshSnapshotANDROID snapshot, uint32_t count, XrSceneSubmeshDataANDROID* data) {
  return guarded("xrGetSubmeshDataANDROID", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const auto it = state().snapshots.find(id_of(snapshot));
    if (it == state().snapshots.end()) return XR_ERROR_HANDLE_INVALID;
    const Snapshot& s = it->second;
    const auto tracker = state().trackers.find(s.tracker);
    if (tracker == state().trackers.end()) return XR_ERROR_HANDLE_INVALID;
    if (count == 0 || data == nullptr || count > s.submeshes.size()) return XR_ERROR_VALIDATION_FAILURE;

    // Everything is checked before anything is written.
    std::vector<const Submesh*> found(count, nullptr);
    for (uint32_t i = 0; i < count; ++i) {
      const XrSceneSubmeshDataANDROID& d = data[i];
      if (d.type != XR_TYPE_SCENE_SUBMESH_DATA_ANDROID) return XR_ERROR_VALIDATION_FAILURE;
      for (std::size_t k : s.submeshes)
        if (same_uuid(s.scene->submeshes[k].uuid, d.submeshId)) found[i] = &s.scene->submeshes[k];
      if (found[i] == nullptr) return XR_ERROR_VALIDATION_FAILURE;  // not a submesh of this snapshot
      for (uint32_t j = 0; j < i; ++j)
        if (found[j] == found[i]) return XR_ERROR_VALIDATION_FAILURE;  // the same id twice
      if (d.vertexCapacityInput > 0 && d.vertexPositions == nullptr) return XR_ERROR_VALIDATION_FAILURE;
      if (d.indexCapacityInput > 0 && d.indices == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    }
    std::vector<Submesh> scratch(count);
    for (uint32_t i = 0; i < count; ++i) found[i] = &faults::faulty_mesh(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME, *found[i], scratch[i]);
    bool short_capacity = false;
    for (uint32_t i = 0; i < count; ++i) {
      XrSceneSubmeshDataANDROID& d = data[i];
      d.vertexCountOutput = faults::vertex_count(XR_ANDROID_SCENE_MESHING_EXTENSION_NAME, found[i]->vertices.size(), d.vertexCapacityInput);
      d.indexCountOutput = static_cast<uint32_t>(found[i]->indices.size());
      short_capacity = short_capacity || (d.vertexCapacityInput > 0 && d.vertexCapacityInput < d.vertexCountOutput) ||
                       (d.indexCapacityInput > 0 && d.indexCapacityInput < d.indexCountOutput);
    }
    if (short_capacity) return XR_ERROR_SIZE_INSUFFICIENT;
    const bool labels = tracker->second.labels == XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID;
    for (uint32_t i = 0; i < count; ++i) {
      XrSceneSubmeshDataANDROID& d = data[i];
      const Submesh& m = *found[i];
      if (d.vertexCapacityInput > 0) {
        std::copy(m.vertices.begin(), m.vertices.end(), d.vertexPositions);
        if (tracker->second.normals && d.vertexNormals != nullptr) std::copy(m.normals.begin(), m.normals.end(), d.vertexNormals);
        if (labels && d.vertexSemantics != nullptr) std::copy(m.labels.begin(), m.labels.end(), d.vertexSemantics);
      }
      if (d.indexCapacityInput > 0) std::copy(m.indices.begin(), m.indices.end(), d.indices);
    }
    return XR_SUCCESS;
  });
}

// A session's trackers and their snapshots go with it; with no tracker left, the built scenes are let go.
void forget_session(std::uint64_t session) {
  std::lock_guard lock(runtime().mutex);
  std::erase_if(state().trackers, [&](const auto& e) { return e.second.session == session; });
  std::erase_if(state().snapshots, [&](const auto& e) { return e.second.session == session; });
}

void forget_instance(std::uint64_t instance) {
  std::lock_guard lock(runtime().mutex);
  std::erase_if(state().trackers, [&](const auto& e) { return e.second.instance == instance; });
  if (state().trackers.empty()) {
    state().snapshots.clear();
    state().built.clear();
  }
}

}  // namespace

const ServedExtension& android_scene_meshing_extension() {
#define SIM_ANDROID_FUNCTIONS(_)                                                                          \
  _(xrEnumerateSupportedSemanticLabelSetsANDROID) _(xrCreateSceneMeshingTrackerANDROID)                   \
  _(xrDestroySceneMeshingTrackerANDROID) _(xrCreateSceneMeshSnapshotANDROID)                              \
  _(xrDestroySceneMeshSnapshotANDROID) _(xrGetAllSubmeshStatesANDROID) _(xrGetSubmeshDataANDROID)
#define SIM_SERVE(name) ServedFunction{#name, reinterpret_cast<PFN_xrVoidFunction>(&name)},
  static const ServedExtension e{XR_ANDROID_SCENE_MESHING_EXTENSION_NAME, XR_ANDROID_scene_meshing_SPEC_VERSION,
                                 true, {SIM_ANDROID_FUNCTIONS(SIM_SERVE)}, &forget_session, &forget_instance};
#undef SIM_SERVE
#undef SIM_ANDROID_FUNCTIONS
  return e;
}

}  // namespace roomsense::sim
