// The query, step by step:
// 1. A world mesh detector; the block states in a box about the base space's origin, through a future polled
//    (xrPollFutureEXT) for 10 s at most and cancelled when the query is stopped; the states read with the
//    two-call idiom of their completion.
// 2. A buffer of the runtime's recommended size for all blocks, then every block's mesh through a second future.
// 3. Each block's vertices moved from its space into the base space with the pose of its state. The buffer and
//    the detector are freed on every path.
#include "ml_world_mesh_detection.h"

#include "../guard.h"
#include "../log.h"
#include "roomsense/xr/ext/XR_ML_world_mesh_detection.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <thread>

namespace roomsense::layer {
namespace {

using xr::check;

#define ML_FUTURE_FUNCTIONS(_) _(xrPollFutureEXT) _(xrCancelFutureEXT)
#define ML_FUNCTIONS(_)                                                                                     \
  _(xrCreateWorldMeshDetectorML) _(xrDestroyWorldMeshDetectorML) _(xrRequestWorldMeshStateAsyncML)          \
  _(xrRequestWorldMeshStateCompleteML) _(xrGetWorldMeshBufferRecommendSizeML) _(xrAllocateWorldMeshBufferML) \
  _(xrFreeWorldMeshBufferML) _(xrRequestWorldMeshAsyncML) _(xrRequestWorldMeshCompleteML)

constexpr float kQueryExtent = 200.0f;  // metres, a box about the base space's origin: any room
constexpr auto kPollInterval = std::chrono::milliseconds(2);
constexpr auto kTimeout = std::chrono::seconds(10);  // for each future
constexpr std::uint32_t kMaxBlocks = 1u << 16;

std::string chunk_id(const XrUuidEXT& id) {
  std::string s = "ml:";
  char hex[3];
  for (std::uint8_t b : id.data) {
    std::snprintf(hex, sizeof hex, "%02x", b);
    s += hex;
  }
  return s;
}

std::string key(const XrUuidEXT& u) { return std::string(reinterpret_cast<const char*>(u.data), sizeof u.data); }

class MlSource final : public MeshSource {
 public:
#define ML_MEMBER(name) PFN_##name name = nullptr;
  ML_FUTURE_FUNCTIONS(ML_MEMBER)
  ML_FUNCTIONS(ML_MEMBER)
#undef ML_MEMBER

  std::vector<SourceChunk> query(const QueryContext& context, std::stop_token stop) override;

 private:
  // Polls until the future is ready (true), or the query is stopped (false, future cancelled); throws after 10 s.
  bool wait(XrInstance instance, XrFutureEXT future, const char* what, std::stop_token stop) const;
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

bool MlSource::wait(XrInstance instance, XrFutureEXT future, const char* what, std::stop_token stop) const {
  auto cancel = [&] {
    auto info = xr_struct<XrFutureCancelInfoEXT>(XR_TYPE_FUTURE_CANCEL_INFO_EXT);
    info.future = future;
    xrCancelFutureEXT(instance, &info);
  };
  const auto deadline = std::chrono::steady_clock::now() + kTimeout;
  for (;;) {
    auto poll = xr_struct<XrFuturePollInfoEXT>(XR_TYPE_FUTURE_POLL_INFO_EXT);
    poll.future = future;
    auto state = xr_struct<XrFuturePollResultEXT>(XR_TYPE_FUTURE_POLL_RESULT_EXT);
    check(xrPollFutureEXT(instance, &poll, &state), "xrPollFutureEXT");
    if (state.state == XR_FUTURE_STATE_READY_EXT) return true;
    if (stop.stop_requested()) {
      cancel();
      return false;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      cancel();
      throw std::runtime_error(std::string(what) + ": the runtime's future was not ready within 10 s");
    }
    std::this_thread::sleep_for(kPollInterval);
  }
}

std::vector<SourceChunk> MlSource::query(const QueryContext& context, std::stop_token stop) {
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

  // 2. A buffer, and every block's mesh.
  auto size_info = xr_struct<XrWorldMeshBufferRecommendedSizeInfoML>(XR_TYPE_WORLD_MESH_BUFFER_RECOMMENDED_SIZE_INFO_ML);
  size_info.maxBlockCount = static_cast<std::uint32_t>(states.size());
  auto size = xr_struct<XrWorldMeshBufferSizeML>(XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML);
  check(xrGetWorldMeshBufferRecommendSizeML(handles.detector, &size_info, &size), "xrGetWorldMeshBufferRecommendSizeML");
  auto buffer = xr_struct<XrWorldMeshBufferML>(XR_TYPE_WORLD_MESH_BUFFER_ML);
  check(xrAllocateWorldMeshBufferML(handles.detector, &size, &buffer), "xrAllocateWorldMeshBufferML");
  handles.buffer = buffer;

  std::vector<XrWorldMeshBlockRequestML> blocks;
  std::map<std::string, const XrWorldMeshBlockStateML*> by_uuid;
  for (const XrWorldMeshBlockStateML& s : states) {
    auto b = xr_struct<XrWorldMeshBlockRequestML>(XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML);
    b.uuid = s.uuid;
    b.lod = XR_WORLD_MESH_DETECTOR_LOD_MAXIMUM_ML;
    blocks.push_back(b);
    by_uuid[key(s.uuid)] = &s;
  }
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
  std::vector<SourceChunk> out;
  out.reserve(meshes.size());
  for (const XrWorldMeshBlockML& m : meshes) {
    if (stop.stop_requested()) return {};
    if (m.blockResult != XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML)
      throw std::runtime_error("the runtime did not deliver a world mesh block (result " + std::to_string(m.blockResult) + ")");
    const auto state = by_uuid.find(key(m.uuid));
    if (state == by_uuid.end()) throw std::runtime_error("the runtime delivered a world mesh block it did not report");
    if (!is_valid_pose(state->second->meshBoundingBoxCenter)) {
      log_warn("a world mesh block had no valid pose and was left out");
      continue;
    }
    if ((m.vertexCount > 0 && m.vertexBuffer == nullptr) || (m.indexCount > 0 && m.indexBuffer == nullptr))
      throw std::runtime_error("the runtime delivered a world mesh block without its arrays");
    SourceChunk chunk;
    chunk.id = chunk_id(m.uuid);
    chunk.change = static_cast<std::uint64_t>(state->second->lastUpdateTime);
    chunk.mesh.vertices = transformed(m.vertexBuffer, m.vertexCount, to_rigid(state->second->meshBoundingBoxCenter));
    const std::uint32_t triangles = m.indexCount / 3;
    chunk.mesh.indices.assign(m.indexBuffer, m.indexBuffer + std::size_t(triangles) * 3);
    if (std::any_of(chunk.mesh.indices.begin(), chunk.mesh.indices.end(), [&](std::uint32_t v) { return v >= m.vertexCount; }))
      throw std::runtime_error("the runtime served a world mesh block with an index out of range");
    out.push_back(std::move(chunk));
  }
  return out;
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
  static const SourceInfo source{
      XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME,
      "world mesh blocks around the base space (uint16 indices)",
      {{XR_EXT_FUTURE_EXTENSION_NAME, {ML_FUTURE_FUNCTIONS(ML_NAME)}},
       {XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME, {ML_FUNCTIONS(ML_NAME)}}},
      {},  // no passive capture
      &create,
  };
#undef ML_NAME
  return source;
}

}  // namespace roomsense::layer
