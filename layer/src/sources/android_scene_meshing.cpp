#include "android_scene_meshing.h"

#include "source_support.h"

#include "../capture.h"
#include "../guard.h"
#include "../log.h"
#include "../state.h"
#include "roomsense/xr/ext/XR_ANDROID_scene_meshing.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <deque>
#include <mutex>
#include <optional>
#include <unordered_map>

namespace roomsense::layer {
namespace {

using xr::check;

#define ANDROID_FUNCTIONS(_)                                                                            \
  _(xrEnumerateSupportedSemanticLabelSetsANDROID) _(xrCreateSceneMeshingTrackerANDROID)                 \
  _(xrDestroySceneMeshingTrackerANDROID) _(xrCreateSceneMeshSnapshotANDROID)                            \
  _(xrDestroySceneMeshSnapshotANDROID) _(xrGetAllSubmeshStatesANDROID) _(xrGetSubmeshDataANDROID)

constexpr float kQueryExtent = 200.0f;              // metres, a box about the base space's origin: any room
constexpr std::size_t kMaxSubmeshes = 1u << 20;
constexpr std::uint32_t kMaxElements = 1u << 26;    // per submesh: far beyond any room

std::string chunk_id(const XrUuid& id) { return uuid_chunk_id("android", id.data); }

SurfaceLabel surface_label(std::uint8_t label) {
  switch (label) {
    case XR_SCENE_MESH_SEMANTIC_LABEL_OTHER_ANDROID: return SurfaceLabel::Other;
    case XR_SCENE_MESH_SEMANTIC_LABEL_FLOOR_ANDROID: return SurfaceLabel::Floor;
    case XR_SCENE_MESH_SEMANTIC_LABEL_CEILING_ANDROID: return SurfaceLabel::Ceiling;
    case XR_SCENE_MESH_SEMANTIC_LABEL_WALL_ANDROID: return SurfaceLabel::Wall;
    case XR_SCENE_MESH_SEMANTIC_LABEL_TABLE_ANDROID: return SurfaceLabel::Table;
    default: return SurfaceLabel::Unknown;  // a label of a newer revision
  }
}

// The label most of a triangle's three vertices have; with three different ones, the first vertex's.
std::uint8_t majority(std::uint8_t a, std::uint8_t b, std::uint8_t c) { return (b == c && a != b) ? b : a; }

// One submesh as the runtime served it (vertices in the submesh's space), moved by `pose`; with per-vertex
// labels, one label per triangle (the majority; none for a triangle with an index out of range). Every index is
// kept as served: broken triangles and a ragged end are for checked_chunks (active query) and keep_capture
// (passive capture) to drop. Shared by the active query and the passive capture.
SourceChunk submesh_chunk(const XrUuid& id, XrTime updated, const Rigid& pose, const XrVector3f* vertices,
                          std::size_t vertex_count, const std::uint8_t* semantics, const std::uint32_t* indices,
                          std::size_t index_count) {
  SourceChunk chunk;
  chunk.id = chunk_id(id);
  chunk.change = static_cast<std::uint64_t>(updated);
  chunk.mesh.vertices = transformed(vertices, vertex_count, pose);
  if (semantics != nullptr && vertex_count > 0) {
    chunk.labels.reserve(index_count / 3);
    const auto label = [&](std::uint32_t i) { return i < vertex_count ? semantics[i] : std::uint8_t{0xff}; };
    for (std::size_t t = 0; t + 3 <= index_count; t += 3)
      chunk.labels.push_back(surface_label(majority(label(indices[t]), label(indices[t + 1]), label(indices[t + 2]))));
  }
  chunk.mesh.indices.assign(indices, indices + index_count);
  return chunk;
}

class AndroidSource final : public MeshSource {
 public:
#define ANDROID_MEMBER(name) PFN_##name name = nullptr;
  ANDROID_FUNCTIONS(ANDROID_MEMBER)
#undef ANDROID_MEMBER

  std::vector<SourceChunk> run_query(const QueryContext& context, std::stop_token stop) override;
  void forget_session(XrSession session) override;
};

// Destroys what the query created, whatever happens.
struct QueryHandles {
  const AndroidSource& next;
  XrSceneMeshingTrackerANDROID tracker = XR_NULL_HANDLE;
  XrSceneMeshSnapshotANDROID snapshot = XR_NULL_HANDLE;
  ~QueryHandles() {
    if (snapshot != XR_NULL_HANDLE) next.xrDestroySceneMeshSnapshotANDROID(snapshot);
    if (tracker != XR_NULL_HANDLE) next.xrDestroySceneMeshingTrackerANDROID(tracker);
  }
};

std::vector<SourceChunk> AndroidSource::run_query(const QueryContext& context, std::stop_token stop) {
  const auto sets = xr::read_two_call<XrSceneMeshSemanticLabelSetANDROID>(
      "xrEnumerateSupportedSemanticLabelSetsANDROID",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSceneMeshSemanticLabelSetANDROID* out) {
        return xrEnumerateSupportedSemanticLabelSetsANDROID(context.instance, context.system, capacity, count, out);
      },
      64);
  const bool labelled = std::find(sets.begin(), sets.end(), XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID) != sets.end();

  QueryHandles handles{*this};
  auto tracker_info = xr_struct<XrSceneMeshingTrackerCreateInfoANDROID>(XR_TYPE_SCENE_MESHING_TRACKER_CREATE_INFO_ANDROID);
  tracker_info.semanticLabelSet = labelled ? XR_SCENE_MESH_SEMANTIC_LABEL_SET_DEFAULT_ANDROID : XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID;
  tracker_info.enableNormals = XR_FALSE;
  check(xrCreateSceneMeshingTrackerANDROID(context.session, &tracker_info, &handles.tracker), "xrCreateSceneMeshingTrackerANDROID");

  auto snapshot_info = xr_struct<XrSceneMeshSnapshotCreateInfoANDROID>(XR_TYPE_SCENE_MESH_SNAPSHOT_CREATE_INFO_ANDROID);
  snapshot_info.baseSpace = context.base;
  snapshot_info.time = context.time;
  snapshot_info.boundingBox.center = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};
  snapshot_info.boundingBox.extents = {kQueryExtent, kQueryExtent, kQueryExtent};
  auto created = xr_struct<XrSceneMeshSnapshotCreationResultANDROID>(XR_TYPE_SCENE_MESH_SNAPSHOT_CREATION_RESULT_ANDROID);
  check(xrCreateSceneMeshSnapshotANDROID(handles.tracker, &snapshot_info, &created), "xrCreateSceneMeshSnapshotANDROID");
  handles.snapshot = created.snapshot;
  if (created.trackingState == XR_SCENE_MESH_TRACKING_STATE_ERROR_ANDROID)
    throw std::runtime_error("the runtime's scene meshing is in its error state");
  const bool tracking = created.trackingState == XR_SCENE_MESH_TRACKING_STATE_TRACKING_ANDROID;

  const auto states = xr::read_two_call<XrSceneSubmeshStateANDROID>(
      "xrGetAllSubmeshStatesANDROID",
      [&](std::uint32_t capacity, std::uint32_t* count, XrSceneSubmeshStateANDROID* out) {
        return xrGetAllSubmeshStatesANDROID(handles.snapshot, capacity, count, out);
      },
      kMaxSubmeshes, xr_struct<XrSceneSubmeshStateANDROID>(XR_TYPE_SCENE_SUBMESH_STATE_ANDROID));

  std::vector<SourceChunk> out;
  out.reserve(states.size());
  std::size_t unposed = 0;
  for (const XrSceneSubmeshStateANDROID& state : states) {
    if (stop.stop_requested()) return {};
    if (!is_valid_pose(state.submeshPoseInBaseSpace)) {
      ++unposed;
      continue;
    }
    if (std::optional<SourceChunk> kept =
            served_before(context, chunk_id(state.submeshId), static_cast<std::uint64_t>(state.lastUpdatedTime),
                          state.submeshPoseInBaseSpace)) {
      out.push_back(std::move(*kept));
      continue;
    }
    // Counts first, then the arrays (two-call idiom, one submesh at a time).
    auto data = xr_struct<XrSceneSubmeshDataANDROID>(XR_TYPE_SCENE_SUBMESH_DATA_ANDROID);
    data.submeshId = state.submeshId;
    check(xrGetSubmeshDataANDROID(handles.snapshot, 1, &data), "xrGetSubmeshDataANDROID");
    if (data.vertexCountOutput > kMaxElements || data.indexCountOutput > kMaxElements)
      throw std::runtime_error("xrGetSubmeshDataANDROID reported " + std::to_string(data.vertexCountOutput) + " vertices and " +
                               std::to_string(data.indexCountOutput) + " indices, over the limit");
    std::vector<XrVector3f> vertices(data.vertexCountOutput);
    std::vector<std::uint8_t> semantics(labelled ? vertices.size() : 0);
    std::vector<std::uint32_t> indices(data.indexCountOutput);
    if (!vertices.empty() || !indices.empty()) {
      data.vertexCapacityInput = static_cast<std::uint32_t>(vertices.size());
      data.vertexPositions = vertices.empty() ? nullptr : vertices.data();
      data.vertexSemantics = semantics.empty() ? nullptr : semantics.data();
      data.indexCapacityInput = static_cast<std::uint32_t>(indices.size());
      data.indices = indices.empty() ? nullptr : indices.data();
      check(xrGetSubmeshDataANDROID(handles.snapshot, 1, &data), "xrGetSubmeshDataANDROID");
      vertices.resize(std::min<std::size_t>(vertices.size(), data.vertexCountOutput));
      semantics.resize(std::min<std::size_t>(semantics.size(), vertices.size()));
      indices.resize(std::min<std::size_t>(indices.size(), data.indexCountOutput));
    }
    SourceChunk chunk = submesh_chunk(state.submeshId, state.lastUpdatedTime, to_rigid(state.submeshPoseInBaseSpace),
                                      vertices.data(), vertices.size(), labelled && !semantics.empty() ? semantics.data() : nullptr,
                                      indices.data(), indices.size());
    chunk.placed = state.submeshPoseInBaseSpace;
    out.push_back(std::move(chunk));
  }
  if (unposed > 0) log_warn(std::to_string(unposed) + " runtime submesh(es) had no valid pose and were left out");
  if (out.empty() && !tracking)  // initializing or waiting: say so rather than "served nothing"
    throw std::runtime_error("the runtime's scene meshing is not tracking yet (state " + std::to_string(created.trackingState) +
                             ") and has no submeshes");
  return out;
}

// ---- passive capture: the application's trackers and snapshots, and the submeshes it reads of them

constexpr std::size_t kMaxRecords = 4096;  // per snapshot (submesh states) and per session (snapshots): bounded

struct TrackerRecord {
  std::shared_ptr<SessionState> session;
  std::uint64_t serial = 0;
  bool labelled = false;  // made with a semantic label set: the runtime writes per-vertex labels
};

struct SnapshotRecord {
  std::shared_ptr<SessionState> session;
  XrSceneMeshingTrackerANDROID tracker = XR_NULL_HANDLE;
  std::uint64_t tracker_serial = 0, serial = 0;
  bool labelled = false;
  XrSpace base = XR_NULL_HANDLE;  // the create info's: submesh poses are in it, at `time`
  XrTime time = 0;
  struct Submesh {
    XrPosef pose{};
    XrTime updated = 0;
    std::uint64_t order = 0;  // when it was recorded, to drop the oldest
    bool kept = false;        // read in full and captured already
  };
  std::mutex mutex;  // the application may read submeshes from several threads
  std::unordered_map<std::string, Submesh> submeshes;  // uuid bytes -> state
  std::deque<std::pair<std::string, std::uint64_t>> order;  // insertion order, for the bound
  std::uint64_t next_order = 0;
};

// The application's handles. Lock `mutex` only to look up or change them, never while calling down the chain.
struct Records {
  std::mutex mutex;
  std::unordered_map<XrSceneMeshingTrackerANDROID, TrackerRecord> trackers;
  std::unordered_map<XrSceneMeshSnapshotANDROID, std::shared_ptr<SnapshotRecord>> snapshots;
  std::uint64_t serial = 0;
};

Records& records() {
  static Records r;
  return r;
}

void AndroidSource::forget_session(XrSession session) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  std::erase_if(r.trackers, [&](const auto& entry) { return entry.second.session->handle == session; });
  std::erase_if(r.snapshots, [&](const auto& entry) { return entry.second->session->handle == session; });
}

std::string uuid_key(const XrUuid& u) { return std::string(reinterpret_cast<const char*>(u.data), sizeof u.data); }

AndroidSource& source_of(const SessionState& session) {
  AndroidSource* s = session.instance->source<AndroidSource>(android_scene_meshing_source());
  if (s == nullptr) throw std::logic_error("XR_ANDROID_scene_meshing hook without its source");
  return *s;
}

std::shared_ptr<SnapshotRecord> snapshot_record(XrSceneMeshSnapshotANDROID snapshot) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  const auto it = r.snapshots.find(snapshot);
  return it == r.snapshots.end() ? nullptr : it->second;
}

// Records a submesh's state (under the record's mutex), dropping the oldest beyond the bound.
void remember_submesh(SnapshotRecord& record, const XrSceneSubmeshStateANDROID& state) {
  const std::string key = uuid_key(state.submeshId);
  auto [it, added] = record.submeshes.try_emplace(key);
  if (!added && std::memcmp(&it->second.pose, &state.submeshPoseInBaseSpace, sizeof(XrPosef)) == 0 &&
      it->second.updated == state.lastUpdatedTime)
    return;  // read again, unchanged
  it->second.pose = state.submeshPoseInBaseSpace;
  it->second.updated = state.lastUpdatedTime;
  it->second.kept = false;
  if (!added) return;
  it->second.order = ++record.next_order;
  record.order.emplace_back(key, it->second.order);
  while (record.submeshes.size() > kMaxRecords && !record.order.empty()) {
    const auto [oldest, order] = record.order.front();
    record.order.pop_front();
    const auto o = record.submeshes.find(oldest);
    if (o != record.submeshes.end() && o->second.order == order) record.submeshes.erase(o);
  }
}

// A submesh the application read in full: placed in the capture space (its pose in the snapshot's base space,
// then the base space located in the capture space at the snapshot's time) and kept.
void keep_submesh(const SnapshotRecord& record, const SnapshotRecord::Submesh& state, const XrSceneSubmeshDataANDROID& data) {
  SessionState& session = *record.session;
  if (!is_valid_pose(state.pose)) return;
  const std::optional<Rigid> base_in_capture = locate_in_capture_space(session, record.base, record.time);
  if (!base_in_capture) {
    log_debug([] { return std::string("a submesh the application read cannot be located; not captured"); });
    return;
  }
  const std::uint8_t* semantics = record.labelled ? data.vertexSemantics : nullptr;
  // Never past the application's arrays, whatever counts the runtime wrote.
  SourceChunk chunk = submesh_chunk(data.submeshId, state.updated, *base_in_capture * to_rigid(state.pose), data.vertexPositions,
                                    std::min(data.vertexCountOutput, data.vertexCapacityInput), semantics, data.indices,
                                    std::min(data.indexCountOutput, data.indexCapacityInput));
  keep_capture(session, android_scene_meshing_source(), std::move(chunk), record.tracker_serial, record.serial);
}

XrResult XRAPI_CALL hook_xrCreateSceneMeshingTrackerANDROID(XrSession session, const XrSceneMeshingTrackerCreateInfoANDROID* createInfo,
                                                            XrSceneMeshingTrackerANDROID* tracker) {
  return guarded("xrCreateSceneMeshingTrackerANDROID", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*s).xrCreateSceneMeshingTrackerANDROID(session, createInfo, tracker);
    if (XR_SUCCEEDED(result) && createInfo != nullptr && tracker != nullptr) {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      r.trackers[*tracker] = {s, ++r.serial, createInfo->semanticLabelSet != XR_SCENE_MESH_SEMANTIC_LABEL_SET_NONE_ANDROID};
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrDestroySceneMeshingTrackerANDROID(XrSceneMeshingTrackerANDROID tracker) {
  return guarded("xrDestroySceneMeshingTrackerANDROID", [&]() -> XrResult {
    std::shared_ptr<SessionState> s;
    {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      const auto it = r.trackers.find(tracker);
      if (it == r.trackers.end()) return XR_ERROR_HANDLE_INVALID;
      s = it->second.session;
    }
    const XrResult result = source_of(*s).xrDestroySceneMeshingTrackerANDROID(tracker);
    if (XR_SUCCEEDED(result)) {
      bool had_snapshots = false;
      {
        Records& r = records();
        std::lock_guard lock(r.mutex);
        r.trackers.erase(tracker);
        // Its snapshots go with it.
        had_snapshots = std::erase_if(r.snapshots, [&](const auto& entry) { return entry.second->tracker == tracker; }) > 0;
      }
      if (had_snapshots) capture_read_done(s);
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrCreateSceneMeshSnapshotANDROID(XrSceneMeshingTrackerANDROID tracker,
                                                          const XrSceneMeshSnapshotCreateInfoANDROID* createInfo,
                                                          XrSceneMeshSnapshotCreationResultANDROID* outSnapshotCreationResult) {
  return guarded("xrCreateSceneMeshSnapshotANDROID", [&]() -> XrResult {
    TrackerRecord tracker_record;
    {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      const auto it = r.trackers.find(tracker);
      if (it == r.trackers.end()) return XR_ERROR_HANDLE_INVALID;
      tracker_record = it->second;
    }
    const XrResult result =
        source_of(*tracker_record.session).xrCreateSceneMeshSnapshotANDROID(tracker, createInfo, outSnapshotCreationResult);
    if (!XR_SUCCEEDED(result) || createInfo == nullptr || outSnapshotCreationResult == nullptr ||
        outSnapshotCreationResult->snapshot == XR_NULL_HANDLE)
      return result;
    auto record = std::make_shared<SnapshotRecord>();
    record->session = tracker_record.session;
    record->tracker = tracker;
    record->tracker_serial = tracker_record.serial;
    record->labelled = tracker_record.labelled;
    record->base = createInfo->baseSpace;
    record->time = createInfo->time;
    Records& r = records();
    std::lock_guard lock(r.mutex);
    record->serial = ++r.serial;
    r.snapshots[outSnapshotCreationResult->snapshot] = std::move(record);
    // An application that never destroys its snapshots: forget the session's oldest beyond the bound.
    std::size_t of_session = 0;
    auto oldest = r.snapshots.end();
    for (auto it = r.snapshots.begin(); it != r.snapshots.end(); ++it) {
      if (it->second->session != tracker_record.session) continue;
      ++of_session;
      if (oldest == r.snapshots.end() || it->second->serial < oldest->second->serial) oldest = it;
    }
    if (of_session > kMaxRecords) r.snapshots.erase(oldest);
    return result;
  });
}

XrResult XRAPI_CALL hook_xrDestroySceneMeshSnapshotANDROID(XrSceneMeshSnapshotANDROID snapshot) {
  return guarded("xrDestroySceneMeshSnapshotANDROID", [&]() -> XrResult {
    const std::shared_ptr<SnapshotRecord> record = snapshot_record(snapshot);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrDestroySceneMeshSnapshotANDROID(snapshot);
    if (XR_SUCCEEDED(result)) {
      {
        Records& r = records();
        std::lock_guard lock(r.mutex);
        r.snapshots.erase(snapshot);
      }
      capture_read_done(record->session);  // the application is done with this snapshot
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrGetAllSubmeshStatesANDROID(XrSceneMeshSnapshotANDROID snapshot, uint32_t submeshStateCapacityInput,
                                                      uint32_t* submeshStateCountOutput, XrSceneSubmeshStateANDROID* submeshStates) {
  return guarded("xrGetAllSubmeshStatesANDROID", [&]() -> XrResult {
    const std::shared_ptr<SnapshotRecord> record = snapshot_record(snapshot);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session)
                                .xrGetAllSubmeshStatesANDROID(snapshot, submeshStateCapacityInput, submeshStateCountOutput, submeshStates);
    if (result != XR_SUCCESS || submeshStateCapacityInput == 0 || submeshStates == nullptr || submeshStateCountOutput == nullptr)
      return result;
    const std::uint32_t n = std::min(*submeshStateCountOutput, submeshStateCapacityInput);
    std::lock_guard lock(record->mutex);
    for (std::uint32_t i = 0; i < n; ++i) remember_submesh(*record, submeshStates[i]);
    return result;
  });
}

XrResult XRAPI_CALL hook_xrGetSubmeshDataANDROID(XrSceneMeshSnapshotANDROID snapshot, uint32_t submeshDataCount,
                                                 XrSceneSubmeshDataANDROID* inoutSubmeshData) {
  return guarded("xrGetSubmeshDataANDROID", [&]() -> XrResult {
    const std::shared_ptr<SnapshotRecord> record = snapshot_record(snapshot);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrGetSubmeshDataANDROID(snapshot, submeshDataCount, inoutSubmeshData);
    if (result != XR_SUCCESS || inoutSubmeshData == nullptr) return result;
    for (std::uint32_t i = 0; i < submeshDataCount; ++i) {
      const XrSceneSubmeshDataANDROID& d = inoutSubmeshData[i];
      // Read in full: both arrays given and large enough (counts-only calls and partial reads are left alone).
      if (d.vertexPositions == nullptr || d.indices == nullptr || d.vertexCountOutput == 0 || d.indexCountOutput == 0 ||
          d.vertexCapacityInput < d.vertexCountOutput || d.indexCapacityInput < d.indexCountOutput)
        continue;
      SnapshotRecord::Submesh state;
      {
        std::lock_guard lock(record->mutex);
        const auto known = record->submeshes.find(uuid_key(d.submeshId));
        if (known == record->submeshes.end() || known->second.kept) continue;  // no state read, or captured already
        known->second.kept = true;
        state = known->second;
      }
      keep_submesh(*record, state, d);
    }
    return result;
  });
}

std::unique_ptr<MeshSource> create(PFN_xrGetInstanceProcAddr next, XrInstance instance) {
  auto source = std::make_unique<AndroidSource>();
#define ANDROID_LOAD(name) load_next(next, instance, #name, source->name);
  ANDROID_FUNCTIONS(ANDROID_LOAD)
#undef ANDROID_LOAD
  return source;
}

}  // namespace

const SourceInfo& android_scene_meshing_source() {
#define ANDROID_NAME(name) #name,
#define ANDROID_HOOK(name) HookEntry{#name, reinterpret_cast<PFN_xrVoidFunction>(&hook_##name)},
  static const SourceInfo source{
      XR_ANDROID_SCENE_MESHING_EXTENSION_NAME,
      "submeshes of a scene mesh snapshot, with per-vertex labels",
      {{XR_ANDROID_SCENE_MESHING_EXTENSION_NAME, {ANDROID_FUNCTIONS(ANDROID_NAME)}}},
      {ANDROID_HOOK(xrCreateSceneMeshingTrackerANDROID) ANDROID_HOOK(xrDestroySceneMeshingTrackerANDROID)
           ANDROID_HOOK(xrCreateSceneMeshSnapshotANDROID) ANDROID_HOOK(xrDestroySceneMeshSnapshotANDROID)
               ANDROID_HOOK(xrGetAllSubmeshStatesANDROID) ANDROID_HOOK(xrGetSubmeshDataANDROID)},
      &create,
  };
#undef ANDROID_NAME
#undef ANDROID_HOOK
  return source;
}

}  // namespace roomsense::layer
