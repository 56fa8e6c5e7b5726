// The query, step by step:
// 1. A world mesh detector; the block states in a box about the base space's origin, through a future polled
//    (xrPollFutureEXT) for 10 s at most and cancelled when the query is stopped; the states read with the
//    two-call idiom of their completion.
// 2. A buffer of the runtime's recommended size for all blocks, then every block's mesh through a second future.
// 3. Each block's vertices moved from its space into the base space with the pose of its state. The buffer and
//    the detector are freed on every path.
#include "ml_world_mesh_detection.h"

#include "source_support.h"

#include "../capture.h"
#include "../guard.h"
#include "../log.h"
#include "../state.h"
#include "roomsense/xr/ext/XR_ML_world_mesh_detection.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <unordered_map>

namespace roomsense::layer {
namespace {

using xr::check;

#define ML_FUTURE_FUNCTIONS(_) _(xrPollFutureEXT) _(xrCancelFutureEXT)
#define ML_FUNCTIONS(_)                                                                                     \
  _(xrCreateWorldMeshDetectorML) _(xrDestroyWorldMeshDetectorML) _(xrRequestWorldMeshStateAsyncML)          \
  _(xrRequestWorldMeshStateCompleteML) _(xrGetWorldMeshBufferRecommendSizeML) _(xrAllocateWorldMeshBufferML) \
  _(xrFreeWorldMeshBufferML) _(xrRequestWorldMeshAsyncML) _(xrRequestWorldMeshCompleteML)

constexpr float kQueryExtent = 200.0f;  // metres, a box about the base space's origin: any room
constexpr std::uint32_t kMaxBlocks = 1u << 16;

std::string chunk_id(const XrUuidEXT& id) { return uuid_chunk_id("ml", id.data); }

std::string key(const XrUuidEXT& u) { return std::string(reinterpret_cast<const char*>(u.data), sizeof u.data); }

constexpr std::uint32_t kMaxBlockVertices = 1u << 16;  // what uint16 indices address

// One block as the runtime served it (vertices in the block's space, uint16 indices), moved by `pose`; every index
// kept as served (checked_chunks and keep_capture drop broken triangles). Empty when the block claims more vertices
// than uint16 indices address, or absurdly many indices: counts nobody may read that far. Shared by the active
// query and the passive capture.
std::optional<SourceChunk> block_chunk(const XrWorldMeshBlockML& m, XrTime updated, const Rigid& pose) {
  if (m.vertexCount > kMaxBlockVertices || m.indexCount > kMaxRuntimeBufferElements) return std::nullopt;
  SourceChunk chunk;
  chunk.id = chunk_id(m.uuid);
  chunk.change = static_cast<std::uint64_t>(updated);
  chunk.mesh.vertices = transformed(m.vertexBuffer, m.vertexCount, pose);
  chunk.mesh.indices.assign(m.indexBuffer, m.indexBuffer + m.indexCount);
  return chunk;
}

// Whether `count` elements of `size` bytes at `p` lie inside the runtime-allocated buffer.
bool inside(const XrWorldMeshBufferML& buffer, const void* p, std::size_t count, std::size_t size) {
  if (count == 0) return true;
  const auto base = reinterpret_cast<std::uintptr_t>(buffer.buffer), at = reinterpret_cast<std::uintptr_t>(p);
  return p != nullptr && at >= base && count <= buffer.bufferSize / size && at - base <= buffer.bufferSize - count * size;
}

class MlSource final : public MeshSource {
 public:
#define ML_MEMBER(name) PFN_##name name = nullptr;
  ML_FUTURE_FUNCTIONS(ML_MEMBER)
  ML_FUNCTIONS(ML_MEMBER)
#undef ML_MEMBER

  std::vector<SourceChunk> run_query(const QueryContext& context, std::stop_token stop) override;
  void forget_session(XrSession session) override;

 private:
  // Polls until the future is ready (true), or the query is stopped (false, future cancelled); throws after 10 s.
  bool wait(XrInstance instance, XrFutureEXT future, const char* what, std::stop_token stop) const {
    return wait_for_future(xrPollFutureEXT, xrCancelFutureEXT, instance, future, what, stop);
  }
};

// Frees what the query made, whatever happens.
struct QueryHandles {
  const MlSource& next;
  XrWorldMeshDetectorML detector = XR_NULL_HANDLE;
  XrWorldMeshBufferML buffer = xr_struct<XrWorldMeshBufferML>(XR_TYPE_WORLD_MESH_BUFFER_ML);
  ~QueryHandles() {
    if (detector == XR_NULL_HANDLE) return;
    if (buffer.buffer != nullptr) next.xrFreeWorldMeshBufferML(detector, &buffer);
    next.xrDestroyWorldMeshDetectorML(detector);
  }
};

std::vector<SourceChunk> MlSource::run_query(const QueryContext& context, std::stop_token stop) {
  QueryHandles handles{*this};
  auto create = xr_struct<XrWorldMeshDetectorCreateInfoML>(XR_TYPE_WORLD_MESH_DETECTOR_CREATE_INFO_ML);
  check(xrCreateWorldMeshDetectorML(context.session, &create, &handles.detector), "xrCreateWorldMeshDetectorML");

  // 1. The block states.
  auto request = xr_struct<XrWorldMeshStateRequestInfoML>(XR_TYPE_WORLD_MESH_STATE_REQUEST_INFO_ML);
  request.baseSpace = context.base;
  request.time = context.time;
  request.boundingBoxCenter = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};
  request.boundingBoxExtents = {kQueryExtent, kQueryExtent, kQueryExtent};
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  check(xrRequestWorldMeshStateAsyncML(handles.detector, &request, &future), "xrRequestWorldMeshStateAsyncML");
  if (!wait(context.instance, future, "xrRequestWorldMeshStateAsyncML", stop)) return {};
  auto completion = xr_struct<XrWorldMeshStateRequestCompletionML>(XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML);
  check(xrRequestWorldMeshStateCompleteML(handles.detector, future, &completion), "xrRequestWorldMeshStateCompleteML");
  check(completion.futureResult, "the world mesh state request");
  if (completion.meshBlockStateCountOutput > kMaxBlocks)
    throw std::runtime_error("xrRequestWorldMeshStateCompleteML reported more blocks than the limit");
  std::vector<XrWorldMeshBlockStateML> states(completion.meshBlockStateCountOutput,
                                              xr_struct<XrWorldMeshBlockStateML>(XR_TYPE_WORLD_MESH_BLOCK_STATE_ML));
  if (!states.empty()) {
    completion.meshBlockStateCapacityInput = static_cast<std::uint32_t>(states.size());
    completion.meshBlockStates = states.data();
    check(xrRequestWorldMeshStateCompleteML(handles.detector, future, &completion), "xrRequestWorldMeshStateCompleteML");
    check(completion.futureResult, "the world mesh state request");
    states.resize(std::min<std::size_t>(states.size(), completion.meshBlockStateCountOutput));
  }
  std::erase_if(states, [](const XrWorldMeshBlockStateML& s) { return s.status == XR_WORLD_MESH_BLOCK_STATUS_DELETED_ML; });
  if (states.empty() || stop.stop_requested()) return {};

  // 2. The blocks not served before as they are now (the runtime meshes only those), a buffer, and their meshes.
  std::vector<SourceChunk> out;
  std::vector<XrWorldMeshBlockRequestML> blocks;
  std::map<std::string, const XrWorldMeshBlockStateML*> by_uuid;
  for (const XrWorldMeshBlockStateML& s : states) {
    if (std::optional<SourceChunk> kept =
            served_before(context, chunk_id(s.uuid), static_cast<std::uint64_t>(s.lastUpdateTime), s.meshBoundingBoxCenter)) {
      out.push_back(std::move(*kept));
      continue;
    }
    auto b = xr_struct<XrWorldMeshBlockRequestML>(XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML);
    b.uuid = s.uuid;
    b.lod = XR_WORLD_MESH_DETECTOR_LOD_MAXIMUM_ML;
    blocks.push_back(b);
    by_uuid[key(s.uuid)] = &s;
  }
  if (blocks.empty()) return out;
  auto size_info = xr_struct<XrWorldMeshBufferRecommendedSizeInfoML>(XR_TYPE_WORLD_MESH_BUFFER_RECOMMENDED_SIZE_INFO_ML);
  size_info.maxBlockCount = static_cast<std::uint32_t>(blocks.size());
  auto size = xr_struct<XrWorldMeshBufferSizeML>(XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML);
  check(xrGetWorldMeshBufferRecommendSizeML(handles.detector, &size_info, &size), "xrGetWorldMeshBufferRecommendSizeML");
  auto buffer = xr_struct<XrWorldMeshBufferML>(XR_TYPE_WORLD_MESH_BUFFER_ML);
  check(xrAllocateWorldMeshBufferML(handles.detector, &size, &buffer), "xrAllocateWorldMeshBufferML");
  handles.buffer = buffer;
  auto get = xr_struct<XrWorldMeshGetInfoML>(XR_TYPE_WORLD_MESH_GET_INFO_ML);
  get.flags = 0;  // counter-clockwise triangles, no point cloud, no planarizing
  get.blockCount = static_cast<std::uint32_t>(blocks.size());
  get.blocks = blocks.data();
  check(xrRequestWorldMeshAsyncML(handles.detector, &get, &handles.buffer, &future), "xrRequestWorldMeshAsyncML");
  if (!wait(context.instance, future, "xrRequestWorldMeshAsyncML", stop)) return {};
  std::vector<XrWorldMeshBlockML> meshes(blocks.size(), xr_struct<XrWorldMeshBlockML>(XR_TYPE_WORLD_MESH_BLOCK_ML));
  auto info = xr_struct<XrWorldMeshRequestCompletionInfoML>(XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_INFO_ML);
  info.meshSpace = context.base;
  info.meshSpaceLocateTime = context.time;
  auto done = xr_struct<XrWorldMeshRequestCompletionML>(XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_ML);
  done.blockCount = static_cast<std::uint32_t>(meshes.size());
  done.blocks = meshes.data();
  check(xrRequestWorldMeshCompleteML(handles.detector, &info, future, &done), "xrRequestWorldMeshCompleteML");
  check(done.futureResult, "the world mesh request");
  meshes.resize(std::min<std::size_t>(meshes.size(), done.blockCount));

  // 3. Into the base space.
  out.reserve(out.size() + meshes.size());
  std::size_t undelivered = 0;
  for (const XrWorldMeshBlockML& m : meshes) {
    if (stop.stop_requested()) return {};
    if (m.blockResult != XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML) {
      ++undelivered;  // FAILED or PENDING: the others are still the room's
      continue;
    }
    const auto state = by_uuid.find(key(m.uuid));
    if (state == by_uuid.end()) throw std::runtime_error("the runtime delivered a world mesh block it did not report");
    if (!is_valid_pose(state->second->meshBoundingBoxCenter)) {
      log_warn("a world mesh block had no valid pose and was left out");
      continue;
    }
    if (!inside(handles.buffer, m.vertexBuffer, m.vertexCount, sizeof(XrVector3f)) ||
        !inside(handles.buffer, m.indexBuffer, m.indexCount, sizeof(std::uint16_t)))
      throw std::runtime_error("the runtime delivered a world mesh block whose " + std::to_string(m.vertexCount) + " vertices or " +
                               std::to_string(m.indexCount) + " indices are not inside its " +
                               std::to_string(handles.buffer.bufferSize) + "-byte buffer");
    std::optional<SourceChunk> chunk = block_chunk(m, state->second->lastUpdateTime, to_rigid(state->second->meshBoundingBoxCenter));
    if (!chunk) throw std::runtime_error("the runtime delivered a world mesh block of " + std::to_string(m.vertexCount) + " vertices");
    chunk->placed = state->second->meshBoundingBoxCenter;
    out.push_back(std::move(*chunk));
  }
  if (undelivered > 0) {
    const std::string what = std::to_string(undelivered) + " of " + std::to_string(meshes.size()) + " world mesh blocks not delivered";
    if (out.empty()) throw std::runtime_error("the runtime delivered none of its world mesh blocks (" + what + ")");
    log_warn(what + " by the runtime; the others are used");
  }
  return out;
}

// ---- passive capture: the application's detectors, the block states it asked for, and the blocks it received

constexpr std::size_t kMaxRecords = 4096;  // per detector (block states, pending state requests): bounded

struct DetectorRecord {
  std::shared_ptr<SessionState> session;
  std::uint64_t serial = 0;
  struct Where {
    XrSpace base = XR_NULL_HANDLE;  // the state request's: block poses are in it, at `time`
    XrTime time = 0;
  };
  struct Block {
    XrPosef pose{};
    XrTime updated = 0;
    Where where;
    std::uint64_t order = 0;  // when it was recorded, to drop the oldest
  };
  std::mutex mutex;  // the application may call from several threads
  std::map<XrFutureEXT, std::pair<Where, std::uint64_t>> state_requests;  // pending, with their order
  std::unordered_map<std::string, Block> blocks;                          // uuid bytes -> latest state
  std::deque<std::pair<std::string, std::uint64_t>> order;                // insertion order, for the bound
  std::uint64_t next_order = 0;
};

// The application's detectors. Lock `mutex` only to look up or change them, never while calling down the chain.
struct Records {
  std::mutex mutex;
  std::unordered_map<XrWorldMeshDetectorML, std::shared_ptr<DetectorRecord>> detectors;
  std::uint64_t serial = 0;
};

Records& records() {
  static Records r;
  return r;
}

void MlSource::forget_session(XrSession session) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  std::erase_if(r.detectors, [&](const auto& entry) { return entry.second->session->handle == session; });
}

MlSource& source_of(const SessionState& session) {
  MlSource* s = session.instance->source<MlSource>(ml_world_mesh_detection_source());
  if (s == nullptr) throw std::logic_error("XR_ML_world_mesh_detection hook without its source");
  return *s;
}

std::shared_ptr<DetectorRecord> detector_record(XrWorldMeshDetectorML detector) {
  Records& r = records();
  std::lock_guard lock(r.mutex);
  const auto it = r.detectors.find(detector);
  return it == r.detectors.end() ? nullptr : it->second;
}

// Records a block's state (under the record's mutex), dropping the oldest beyond the bound.
void remember_block(DetectorRecord& record, const XrWorldMeshBlockStateML& state, const DetectorRecord::Where& where) {
  const std::string k = key(state.uuid);
  if (state.status == XR_WORLD_MESH_BLOCK_STATUS_DELETED_ML) {
    record.blocks.erase(k);
    return;
  }
  auto [it, added] = record.blocks.try_emplace(k);
  it->second.pose = state.meshBoundingBoxCenter;
  it->second.updated = state.lastUpdateTime;
  it->second.where = where;
  if (!added) return;
  it->second.order = ++record.next_order;
  record.order.emplace_back(k, it->second.order);
  while (record.blocks.size() > kMaxRecords && !record.order.empty()) {
    const auto [oldest, order] = record.order.front();
    record.order.pop_front();
    const auto o = record.blocks.find(oldest);
    if (o != record.blocks.end() && o->second.order == order) record.blocks.erase(o);
  }
  if (record.order.size() > 2 * kMaxRecords) {  // stale entries of erased blocks: rebuild
    record.order.clear();
    for (const auto& [b, block] : record.blocks) record.order.emplace_back(b, block.order);
    std::sort(record.order.begin(), record.order.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  }
}

XrResult XRAPI_CALL hook_xrCreateWorldMeshDetectorML(XrSession session, const XrWorldMeshDetectorCreateInfoML* createInfo,
                                                     XrWorldMeshDetectorML* detector) {
  return guarded("xrCreateWorldMeshDetectorML", [&]() -> XrResult {
    const std::shared_ptr<SessionState> s = registry().session(session);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*s).xrCreateWorldMeshDetectorML(session, createInfo, detector);
    if (XR_SUCCEEDED(result) && detector != nullptr) {
      auto record = std::make_shared<DetectorRecord>();
      record->session = s;
      Records& r = records();
      std::lock_guard lock(r.mutex);
      record->serial = ++r.serial;
      r.detectors[*detector] = std::move(record);
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrDestroyWorldMeshDetectorML(XrWorldMeshDetectorML detector) {
  return guarded("xrDestroyWorldMeshDetectorML", [&]() -> XrResult {
    const std::shared_ptr<DetectorRecord> record = detector_record(detector);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrDestroyWorldMeshDetectorML(detector);
    if (XR_SUCCEEDED(result)) {
      Records& r = records();
      std::lock_guard lock(r.mutex);
      r.detectors.erase(detector);
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrRequestWorldMeshStateAsyncML(XrWorldMeshDetectorML detector, const XrWorldMeshStateRequestInfoML* stateRequest,
                                                        XrFutureEXT* future) {
  return guarded("xrRequestWorldMeshStateAsyncML", [&]() -> XrResult {
    const std::shared_ptr<DetectorRecord> record = detector_record(detector);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrRequestWorldMeshStateAsyncML(detector, stateRequest, future);
    if (XR_SUCCEEDED(result) && stateRequest != nullptr && future != nullptr) {
      std::lock_guard lock(record->mutex);
      record->state_requests[*future] = {{stateRequest->baseSpace, stateRequest->time}, ++record->next_order};
      if (record->state_requests.size() > kMaxRecords)  // never completed: forget the oldest
        record->state_requests.erase(std::min_element(record->state_requests.begin(), record->state_requests.end(),
                                                      [](const auto& a, const auto& b) { return a.second.second < b.second.second; }));
    }
    return result;
  });
}

XrResult XRAPI_CALL hook_xrRequestWorldMeshStateCompleteML(XrWorldMeshDetectorML detector, XrFutureEXT future,
                                                           XrWorldMeshStateRequestCompletionML* completion) {
  return guarded("xrRequestWorldMeshStateCompleteML", [&]() -> XrResult {
    const std::shared_ptr<DetectorRecord> record = detector_record(detector);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const XrResult result = source_of(*record->session).xrRequestWorldMeshStateCompleteML(detector, future, completion);
    if (result != XR_SUCCESS || completion == nullptr) return result;
    std::lock_guard lock(record->mutex);
    const auto request = record->state_requests.find(future);
    if (request == record->state_requests.end()) return result;
    if (completion->futureResult != XR_SUCCESS) {
      record->state_requests.erase(request);
      return result;
    }
    if (completion->meshBlockStateCapacityInput == 0 || completion->meshBlockStates == nullptr) return result;  // counts only
    const DetectorRecord::Where where = request->second.first;
    record->state_requests.erase(request);  // taken in full: the future is spent
    const std::uint32_t n = std::min(completion->meshBlockStateCountOutput, completion->meshBlockStateCapacityInput);
    for (std::uint32_t i = 0; i < n; ++i) remember_block(*record, completion->meshBlockStates[i], where);
    return result;
  });
}

XrResult XRAPI_CALL hook_xrRequestWorldMeshCompleteML(XrWorldMeshDetectorML detector, const XrWorldMeshRequestCompletionInfoML* completionInfo,
                                                      XrFutureEXT future, XrWorldMeshRequestCompletionML* completion) {
  return guarded("xrRequestWorldMeshCompleteML", [&]() -> XrResult {
    const std::shared_ptr<DetectorRecord> record = detector_record(detector);
    if (!record) return XR_ERROR_HANDLE_INVALID;
    const std::uint32_t capacity = completion != nullptr ? completion->blockCount : 0;  // the application's array
    const XrResult result = source_of(*record->session).xrRequestWorldMeshCompleteML(detector, completionInfo, future, completion);
    if (result != XR_SUCCESS || completion == nullptr || completion->futureResult != XR_SUCCESS || completion->blocks == nullptr)
      return result;
    SessionState& session = *record->session;
    // Each block's state as recorded, looked up first; then located and copied without the record's lock.
    std::vector<std::pair<const XrWorldMeshBlockML*, DetectorRecord::Block>> received;
    {
      std::lock_guard lock(record->mutex);
      for (std::uint32_t i = 0; i < std::min(capacity, completion->blockCount); ++i) {
        const XrWorldMeshBlockML& m = completion->blocks[i];
        if (m.blockResult != XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML || m.vertexCount == 0 || m.indexCount < 3 ||
            m.vertexBuffer == nullptr || m.indexBuffer == nullptr)
          continue;
        const auto state = record->blocks.find(key(m.uuid));
        if (state == record->blocks.end() || !is_valid_pose(state->second.pose)) continue;  // no state read
        received.emplace_back(&m, state->second);
      }
    }
    std::map<std::pair<XrSpace, XrTime>, std::optional<Rigid>> to_capture;  // base space -> capture space, once each
    std::size_t unlocated = 0;
    for (const auto& [m, state] : received) {
      auto [where, added] = to_capture.try_emplace({state.where.base, state.where.time});
      if (added) where->second = locate_in_capture_space(session, state.where.base, state.where.time);
      if (!where->second) {
        ++unlocated;
        continue;
      }
      std::optional<SourceChunk> chunk = block_chunk(*m, state.updated, *where->second * to_rigid(state.pose));
      if (chunk) keep_capture(session, ml_world_mesh_detection_source(), std::move(*chunk), record->serial, 0);
    }
    if (unlocated > 0)
      log_debug([&] { return std::to_string(unlocated) + " world mesh block(s) the application read cannot be located; not captured"; });
    capture_read_done(record->session);  // the application has what it asked for
    return result;
  });
}

std::unique_ptr<MeshSource> create(PFN_xrGetInstanceProcAddr next, XrInstance instance) {
  auto source = std::make_unique<MlSource>();
#define ML_LOAD(name) load_next(next, instance, #name, source->name);
  ML_FUTURE_FUNCTIONS(ML_LOAD)
  ML_FUNCTIONS(ML_LOAD)
#undef ML_LOAD
  return source;
}

}  // namespace

const SourceInfo& ml_world_mesh_detection_source() {
#define ML_NAME(name) #name,
#define ML_HOOK(name) HookEntry{#name, reinterpret_cast<PFN_xrVoidFunction>(&hook_##name)},
  static const SourceInfo source{
      XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME,
      "world mesh blocks around the base space (uint16 indices)",
      {{XR_EXT_FUTURE_EXTENSION_NAME, {ML_FUTURE_FUNCTIONS(ML_NAME)}},
       {XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME, {ML_FUNCTIONS(ML_NAME)}}},
      {ML_HOOK(xrCreateWorldMeshDetectorML) ML_HOOK(xrDestroyWorldMeshDetectorML) ML_HOOK(xrRequestWorldMeshStateAsyncML)
           ML_HOOK(xrRequestWorldMeshStateCompleteML) ML_HOOK(xrRequestWorldMeshCompleteML)},
      &create,
  };
#undef ML_NAME
#undef ML_HOOK
  return source;
}

}  // namespace roomsense::layer
