// XR_ML_world_mesh_detection (see the header). Blocks are built once per room and chunk size, so their uuids
// and lastUpdateTime stay the same across requests and detectors; a block's status is NEW the first time a
// detector reports it and UNCHANGED afterwards, or UPDATED where its update time changed since (a room being
// scanned, scan_progress.h: a chunk's time is when it last changed). Futures are ready after ROOMSENSE_SIM_COMPUTE_DELAY_MS.
// xrRequestWorldMeshStateCompleteML follows the two-call idiom: a call with no capacity (or too little) leaves
// the result with the future's detector until a call takes every state.
#include "ml_world_mesh_detection.h"
#include "../process_state.h"

#include "stable_uuid.h"

#include "../faults.h"
#include "../functions.h"
#include "../log.h"
#include "../runtime.h"
#include "../spaces.h"
#include "../validate.h"
#include "ext_future.h"
#include "roomsense/xr/ext/XR_ML_world_mesh_detection.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

namespace roomsense::sim {
namespace {

constexpr const char* kStateFuture = "xrRequestWorldMeshStateAsyncML";
constexpr const char* kMeshFuture = "xrRequestWorldMeshAsyncML";
constexpr std::size_t kMaxBlockVertices = 65535;           // what uint16 indices reach (0xFFFF kept free)
constexpr std::size_t kAlign = 16;
constexpr std::uint64_t kMaxBufferSize = 1ull << 31;      // bytes one buffer may have

struct Block {
  XrUuidEXT uuid{};
  XrTime updated = 0;                 // its lastUpdateTime
  Rigid pose;                         // in world space, as an XrPosef holds it
  std::vector<XrVector3f> vertices;   // in the block's space
  std::vector<std::uint16_t> indices;
  XrExtent3DfEXT extents{};           // a box about the pose holding every vertex
  glm::dvec3 centre{0.0};
  double radius = 0.0;
  std::size_t bytes() const {
    const auto round = [](std::size_t n) { return (n + kAlign - 1) / kAlign * kAlign; };
    return round(vertices.size() * sizeof(XrVector3f)) + round(indices.size() * sizeof(std::uint16_t));
  }
};

struct BlockScene {
  std::vector<Block> blocks;
  std::size_t largest = 0, total = 0;  // bytes
};

struct StateResult {
  XrTime time = 0;
  std::vector<XrWorldMeshBlockStateML> states;
};

struct MeshRequest {
  std::uint64_t detector = 0;
  void* buffer = nullptr;
  std::vector<std::pair<std::size_t, XrWorldMeshDetectorLodML>> blocks;  // scene index, or SIZE_MAX: unknown uuid
  std::vector<XrUuidEXT> uuids;
  std::shared_ptr<const BlockScene> scene;
};

struct Detector {
  std::uint64_t session = 0, instance = 0;
  std::map<std::string, XrTime> reported;  // each uuid reported, with its update time then (later: UNCHANGED or UPDATED)
  std::map<XrFutureEXT, std::shared_ptr<const StateResult>> held;  // state results not yet taken in full
  std::map<void*, std::unique_ptr<std::uint8_t[]>> buffers;
  std::map<void*, std::uint32_t> sizes;
};

// Guarded by runtime().mutex.
struct State {
  std::unordered_map<std::uint64_t, Detector> detectors;
  BuiltPerStep<BlockScene, std::vector<Block>> built;  // from the room as scanned (scan_progress.h)
};

State& state() {
  return process_wide<State>();
}



std::string key(const XrUuidEXT& u) { return std::string(reinterpret_cast<const char*>(u.data), sizeof u.data); }
glm::dvec3 to_glm(const XrVector3f& v) { return {v.x, v.y, v.z}; }

// One block of a chunk's triangles [first, last) (and, for the first block, its lone vertices).
Block make_block(const Chunk& chunk, const Rigid& pose, const std::vector<std::uint32_t>& triangles, const std::vector<std::uint32_t>& lone) {
  Block b;
  b.pose = pose;
  const Rigid to_local = pose.inverse() * chunk.pose;
  std::unordered_map<std::uint32_t, std::uint16_t> local;
  auto add = [&](std::uint32_t v) {
    const auto [it, fresh] = local.try_emplace(v, static_cast<std::uint16_t>(b.vertices.size()));
    if (fresh) {
      const glm::dvec3 p = to_local.apply(to_glm(chunk.mesh.vertices[v]));
      b.vertices.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    }
    return it->second;
  };
  for (std::uint32_t t : triangles)
    for (int k = 0; k < 3; ++k) b.indices.push_back(add(chunk.mesh.indices[t + k]));
  for (std::uint32_t v : lone) add(v);
  glm::dvec3 extent(0.0);
  for (const XrVector3f& v : b.vertices) extent = glm::max(extent, glm::abs(to_glm(v)));
  b.extents = {static_cast<float>(2.0 * extent.x), static_cast<float>(2.0 * extent.y), static_cast<float>(2.0 * extent.z)};
  b.centre = pose.translation;
  b.radius = glm::length(extent);
  return b;
}

// A chunk's blocks (their update time aside): its triangles in order, at most kMaxBlockVertices distinct vertices a
// block. Ids by the chunk's cell and the block's place in it, so a block keeps its id while others appear
// (scan_progress.h).
std::vector<Block> build_blocks(const Chunk& chunk, const std::string& source, double chunk_size) {
  std::vector<Block> blocks;
  const Rigid pose = to_rigid(to_pose(chunk.pose));
  std::vector<bool> used(chunk.mesh.vertices.size(), false);
  std::vector<std::uint32_t> triangles;
  std::set<std::uint32_t> in_block;
  auto flush = [&](const std::vector<std::uint32_t>& lone) {
    Block b = make_block(chunk, pose, triangles, lone);
    b.uuid = stable_uuid(source, chunked_salt(0x4d4c32ull /* "ML2" */, chunk_size),
                         cell_key(chunk.cell) ^ (std::uint64_t(blocks.size()) * 0x9E3779B97F4A7C15ull));
    blocks.push_back(std::move(b));
    triangles.clear();
    in_block.clear();
  };
  for (std::uint32_t t = 0; t + 2 < chunk.mesh.indices.size(); t += 3) {
    std::size_t fresh = 0;
    for (int k = 0; k < 3; ++k) fresh += in_block.count(chunk.mesh.indices[t + k]) == 0 ? 1 : 0;
    if (in_block.size() + fresh > kMaxBlockVertices) flush({});
    for (int k = 0; k < 3; ++k) in_block.insert(chunk.mesh.indices[t + k]), used[chunk.mesh.indices[t + k]] = true;
    triangles.push_back(t);
  }
  std::vector<std::uint32_t> lone;
  for (std::uint32_t v = 0; v < used.size(); ++v)
    if (!used[v]) lone.push_back(v);
  while (!triangles.empty() || !lone.empty()) {
    const std::size_t room_left = kMaxBlockVertices - in_block.size();
    std::vector<std::uint32_t> part(lone.begin(), lone.begin() + static_cast<std::ptrdiff_t>(std::min(room_left, lone.size())));
    lone.erase(lone.begin(), lone.begin() + static_cast<std::ptrdiff_t>(part.size()));
    flush(part);
  }
  return blocks;
}

// The blocks of an instance's room as scanned now, built once per step of the scan (the whole room, where it is
// not being scanned), each chunk's blocks once while the chunk is held: a step of a scan changes a chunk or two.
// Call under the lock.
std::shared_ptr<const BlockScene> scene_of(const InstanceState& instance) {
  const std::shared_ptr<const ScanStep> scanned = instance.room_at(now_time());
  if (!scanned) return nullptr;
  return state().built.scene(scanned, [&] {
    BlockScene scene;
    const XrTime built = now_time();
    for (const SharedChunk& chunk : scanned->chunks) {
      const std::vector<Block>& blocks = state().built.piece(
          chunk, [&] { return build_blocks(*chunk, scanned->room->source, instance.config.chunk_size); });
      for (Block b : blocks) {
        b.updated = scanned->update_time(chunk->cell, built);
        scene.largest = std::max(scene.largest, b.bytes()), scene.total += b.bytes();
        scene.blocks.push_back(std::move(b));
      }
    }
    return scene;
  });
}

bool finite(float x) { return std::isfinite(x); }

InstanceState* instance_of(const Detector& d) { return Runtime::find(runtime().instances, d.instance); }

Detector* detector_of(XrWorldMeshDetectorML h) {
  const auto it = state().detectors.find(id_of(h));
  return it == state().detectors.end() ? nullptr : &it->second;
}

// Checks a space for a call of `session` at `time`, and finds where it is in the world.
XrResult resolve_space(XrSpace space, XrTime time, std::uint64_t session, Rigid& world) {
  const SpaceState* s = runtime().space(space);
  if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
  if (s->session != session) return XR_ERROR_VALIDATION_FAILURE;
  if (time <= 0) return XR_ERROR_TIME_INVALID;
  return space_in_world(*s, world) ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
}

XrResult XRAPI_CALL xrCreateWorldMeshDetectorML(XrSession session, const XrWorldMeshDetectorCreateInfoML* createInfo,
                                                XrWorldMeshDetectorML* detector) {
  return guarded("xrCreateWorldMeshDetectorML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SessionState* owner = runtime().session(session);
    if (owner == nullptr) return XR_ERROR_HANDLE_INVALID;
    const InstanceState* instance = Runtime::find(runtime().instances, owner->instance);
    if (instance == nullptr || !instance->has(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME)) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!has_type(createInfo, XR_TYPE_WORLD_MESH_DETECTOR_CREATE_INFO_ML) || detector == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const std::uint64_t id = runtime().new_id();
    Detector& d = state().detectors[id];
    d.session = id_of(session);
    d.instance = owner->instance;
    *detector = handle_of<XrWorldMeshDetectorML>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroyWorldMeshDetectorML(XrWorldMeshDetectorML detector) {
  return guarded("xrDestroyWorldMeshDetectorML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    return state().detectors.erase(id_of(detector)) == 1 ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;  // its buffers with it
  });
}

XrResult XRAPI_CALL xrRequestWorldMeshStateAsyncML(XrWorldMeshDetectorML detector, const XrWorldMeshStateRequestInfoML* info,
                                                   XrFutureEXT* future) {
  return guarded("xrRequestWorldMeshStateAsyncML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Detector* d = detector_of(detector);
    if (d == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_WORLD_MESH_STATE_REQUEST_INFO_ML) || future == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    Rigid base_world;
    if (XrResult r = resolve_space(info->baseSpace, info->time, d->session, base_world); r != XR_SUCCESS) return r;
    if (!is_valid_pose(info->boundingBoxCenter)) return XR_ERROR_POSE_INVALID;
    const XrExtent3DfEXT& e = info->boundingBoxExtents;
    if (!finite(e.width) || !finite(e.height) || !finite(e.depth) || e.width < 0 || e.height < 0 || e.depth < 0)
      return XR_ERROR_VALIDATION_FAILURE;
    InstanceState* instance = instance_of(*d);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    auto result = std::make_shared<StateResult>();
    result->time = info->time;
    const std::shared_ptr<const BlockScene> scene = scene_of(*instance);
    if (!scene) log_error("world mesh state: ROOMSENSE_SIM_SCENE is not set, so there is no room to serve");
    if (scene) {
      const Rigid world_to_base = base_world.inverse();
      const Rigid world_to_box = (base_world * to_rigid(info->boundingBoxCenter)).inverse();
      const glm::dvec3 half = glm::dvec3(e.width, e.height, e.depth) * 0.5;
      for (const Block& b : scene->blocks) {
        const glm::dvec3 p = glm::abs(world_to_box.apply(b.centre));
        if (p.x > half.x + b.radius || p.y > half.y + b.radius || p.z > half.z + b.radius) continue;
        XrWorldMeshBlockStateML s{};
        s.type = XR_TYPE_WORLD_MESH_BLOCK_STATE_ML;
        s.uuid = b.uuid;
        s.meshBoundingBoxCenter = to_pose(world_to_base * b.pose);
        s.meshBoundingBoxExtents = b.extents;
        s.lastUpdateTime = b.updated;
        const auto [seen, is_new] = d->reported.try_emplace(key(b.uuid), b.updated);
        s.status = is_new ? XR_WORLD_MESH_BLOCK_STATUS_NEW_ML
                   : seen->second != b.updated ? XR_WORLD_MESH_BLOCK_STATUS_UPDATED_ML
                                               : XR_WORLD_MESH_BLOCK_STATUS_UNCHANGED_ML;
        seen->second = b.updated;
        result->states.push_back(s);
      }
    }
    *future = make_future(d->instance, d->session, kStateFuture,
                          faults::future_delay(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME, std::chrono::milliseconds(instance->config.compute_delay_ms)),
                          std::shared_ptr<const void>(result, result.get()));
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrRequestWorldMeshStateCompleteML(XrWorldMeshDetectorML detector, XrFutureEXT future,
                                                      XrWorldMeshStateRequestCompletionML* completion) {
  return guarded("xrRequestWorldMeshStateCompleteML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Detector* d = detector_of(detector);
    if (d == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(completion, XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML)) return XR_ERROR_VALIDATION_FAILURE;
    if (completion->meshBlockStateCapacityInput > 0 && completion->meshBlockStates == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    std::shared_ptr<const StateResult> result;
    if (const auto held = d->held.find(future); held != d->held.end()) {
      result = held->second;
    } else {
      std::shared_ptr<const void> taken;
      if (XrResult r = take_future(future, d->session, kStateFuture, taken); r != XR_SUCCESS) return r;
      result = std::static_pointer_cast<const StateResult>(taken);
    }
    const std::uint32_t capacity = completion->meshBlockStateCapacityInput;
    for (std::uint32_t i = 0; i < capacity; ++i)
      if (completion->meshBlockStates[i].type != XR_TYPE_WORLD_MESH_BLOCK_STATE_ML) return XR_ERROR_VALIDATION_FAILURE;
    completion->futureResult = XR_SUCCESS;
    completion->timestamp = result->time;
    completion->meshBlockStateCountOutput = static_cast<std::uint32_t>(result->states.size());
    if (capacity < result->states.size()) {
      d->held[future] = result;  // asked for the count (or too few): the states wait for the next call
      return capacity == 0 ? XR_SUCCESS : XR_ERROR_SIZE_INSUFFICIENT;
    }
    for (std::size_t i = 0; i < result->states.size(); ++i) {
      void* next = completion->meshBlockStates[i].next;
      completion->meshBlockStates[i] = result->states[i];
      completion->meshBlockStates[i].next = next;
    }
    d->held.erase(future);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetWorldMeshBufferRecommendSizeML(XrWorldMeshDetectorML detector, const XrWorldMeshBufferRecommendedSizeInfoML* sizeInfo,
                                                        XrWorldMeshBufferSizeML* size) {
  return guarded("xrGetWorldMeshBufferRecommendSizeML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Detector* d = detector_of(detector);
    if (d == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(sizeInfo, XR_TYPE_WORLD_MESH_BUFFER_RECOMMENDED_SIZE_INFO_ML) || !has_type(size, XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML))
      return XR_ERROR_VALIDATION_FAILURE;
    InstanceState* instance = instance_of(*d);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    const std::shared_ptr<const BlockScene> scene = scene_of(*instance);
    std::uint64_t bytes = scene ? std::min<std::uint64_t>(std::uint64_t(sizeInfo->maxBlockCount) * scene->largest, scene->total) : 0;
    // A ragged block (ROOMSENSE_SIM_FAULTS) has one index more: room for it in every block.
    if (faults::mesh_fault(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME) != faults::MeshFault::None) bytes += std::uint64_t(sizeInfo->maxBlockCount) * kAlign;
    size->size = static_cast<std::uint32_t>(std::clamp<std::uint64_t>(bytes, kAlign, kMaxBufferSize));
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrAllocateWorldMeshBufferML(XrWorldMeshDetectorML detector, const XrWorldMeshBufferSizeML* size,
                                                XrWorldMeshBufferML* buffer) {
  return guarded("xrAllocateWorldMeshBufferML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Detector* d = detector_of(detector);
    if (d == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(size, XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML) || !has_type(buffer, XR_TYPE_WORLD_MESH_BUFFER_ML))
      return XR_ERROR_VALIDATION_FAILURE;
    if (size->size == 0 || size->size > kMaxBufferSize) return XR_ERROR_VALIDATION_FAILURE;
    auto memory = std::make_unique<std::uint8_t[]>(size->size);
    void* p = memory.get();
    d->buffers[p] = std::move(memory);
    d->sizes[p] = size->size;
    buffer->bufferSize = size->size;
    buffer->buffer = p;
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrFreeWorldMeshBufferML(XrWorldMeshDetectorML detector, const XrWorldMeshBufferML* buffer) {
  return guarded("xrFreeWorldMeshBufferML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Detector* d = detector_of(detector);
    if (d == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(buffer, XR_TYPE_WORLD_MESH_BUFFER_ML) || d->buffers.erase(buffer->buffer) != 1) return XR_ERROR_VALIDATION_FAILURE;
    d->sizes.erase(buffer->buffer);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrRequestWorldMeshAsyncML(XrWorldMeshDetectorML detector, const XrWorldMeshGetInfoML* getInfo,
                                              XrWorldMeshBufferML* buffer, XrFutureEXT* future) {
  return guarded("xrRequestWorldMeshAsyncML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Detector* d = detector_of(detector);
    if (d == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(getInfo, XR_TYPE_WORLD_MESH_GET_INFO_ML) || !has_type(buffer, XR_TYPE_WORLD_MESH_BUFFER_ML) || future == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    if (getInfo->blockCount == 0 || getInfo->blocks == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const auto sized = d->sizes.find(buffer->buffer);
    if (sized == d->sizes.end() || sized->second != buffer->bufferSize) return XR_ERROR_VALIDATION_FAILURE;  // not ours
    InstanceState* instance = instance_of(*d);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    auto request = std::make_shared<MeshRequest>();
    request->detector = id_of(detector);
    request->buffer = buffer->buffer;
    request->scene = scene_of(*instance);
    std::map<std::string, std::size_t> index;
    if (request->scene)
      for (std::size_t i = 0; i < request->scene->blocks.size(); ++i) index[key(request->scene->blocks[i].uuid)] = i;
    for (std::uint32_t i = 0; i < getInfo->blockCount; ++i) {
      const XrWorldMeshBlockRequestML& b = getInfo->blocks[i];
      if (b.type != XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML) return XR_ERROR_VALIDATION_FAILURE;
      if (b.lod < XR_WORLD_MESH_DETECTOR_LOD_MINIMUM_ML || b.lod > XR_WORLD_MESH_DETECTOR_LOD_MAXIMUM_ML) return XR_ERROR_VALIDATION_FAILURE;
      const auto found = index.find(key(b.uuid));
      request->blocks.push_back({found == index.end() ? std::numeric_limits<std::size_t>::max() : found->second, b.lod});
      request->uuids.push_back(b.uuid);
    }
    *future = make_future(d->instance, d->session, kMeshFuture,
                          faults::future_delay(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME, std::chrono::milliseconds(instance->config.compute_delay_ms)),
                          std::shared_ptr<const void>(request, request.get()));
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrRequestWorldMeshCompleteML(XrWorldMeshDetectorML detector, const XrWorldMeshRequestCompletionInfoML* completionInfo,
                                                 XrFutureEXT future, XrWorldMeshRequestCompletionML* completion) {
  return guarded("xrRequestWorldMeshCompleteML", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Detector* d = detector_of(detector);
    if (d == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(completionInfo, XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_INFO_ML) ||
        !has_type(completion, XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_ML))
      return XR_ERROR_VALIDATION_FAILURE;
    Rigid unused;
    if (XrResult r = resolve_space(completionInfo->meshSpace, completionInfo->meshSpaceLocateTime, d->session, unused); r != XR_SUCCESS)
      return r;
    if (completion->blockCount > 0 && completion->blocks == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::uint32_t i = 0; i < completion->blockCount; ++i)
      if (completion->blocks[i].type != XR_TYPE_WORLD_MESH_BLOCK_ML) return XR_ERROR_VALIDATION_FAILURE;
    std::shared_ptr<const void> taken;
    if (XrResult r = take_future(future, d->session, kMeshFuture, taken); r != XR_SUCCESS) return r;
    const auto request = std::static_pointer_cast<const MeshRequest>(taken);
    if (request->detector != id_of(detector)) return XR_ERROR_FUTURE_INVALID_EXT;
    const auto sized = d->sizes.find(request->buffer);
    if (sized == d->sizes.end()) {  // the buffer was freed while the request ran
      completion->futureResult = XR_ERROR_VALIDATION_FAILURE;
      return XR_SUCCESS;
    }
    if (completion->blockCount < request->blocks.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    std::uint8_t* memory = static_cast<std::uint8_t*>(request->buffer);
    std::size_t used = 0;
    for (std::size_t i = 0; i < request->blocks.size(); ++i) {
      XrWorldMeshBlockML& out = completion->blocks[i];
      void* next = out.next;
      out = XrWorldMeshBlockML{};
      out.type = XR_TYPE_WORLD_MESH_BLOCK_ML;
      out.next = next;
      out.uuid = request->uuids[i];
      out.lod = request->blocks[i].second;
      const std::size_t at = request->blocks[i].first;
      Block scratch;
      const Block* faulty = !request->scene || at >= request->scene->blocks.size()
                                ? nullptr
                                : &faults::faulty_mesh(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME, request->scene->blocks[at], scratch);
      if (faulty == nullptr || used + faulty->bytes() > sized->second) {
        out.blockResult = XR_WORLD_MESH_BLOCK_RESULT_FAILED_ML;  // an unknown block, or no room left in the buffer
        continue;
      }
      const Block& b = *faulty;
      auto* vertices = reinterpret_cast<XrVector3f*>(memory + used);
      std::copy(b.vertices.begin(), b.vertices.end(), vertices);
      used += (b.vertices.size() * sizeof(XrVector3f) + kAlign - 1) / kAlign * kAlign;
      auto* indices = reinterpret_cast<std::uint16_t*>(memory + used);
      std::copy(b.indices.begin(), b.indices.end(), indices);
      used += (b.indices.size() * sizeof(std::uint16_t) + kAlign - 1) / kAlign * kAlign;
      out.blockResult = XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML;
      out.vertexCount = faults::vertex_count(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME, b.vertices.size(), 0);
      out.vertexBuffer = b.vertices.empty() ? nullptr : vertices;
      out.indexCount = static_cast<std::uint32_t>(b.indices.size());
      out.indexBuffer = b.indices.empty() ? nullptr : indices;
    }
    completion->blockCount = static_cast<std::uint32_t>(request->blocks.size());
    completion->futureResult = XR_SUCCESS;
    return XR_SUCCESS;
  });
}

// A session's detectors (with their buffers) go with it; with none left, the built scenes are let go.
void forget_session(std::uint64_t session) {
  std::lock_guard lock(runtime().mutex);
  std::erase_if(state().detectors, [&](const auto& e) { return e.second.session == session; });
}

void forget_instance(std::uint64_t instance) {
  std::lock_guard lock(runtime().mutex);
  std::erase_if(state().detectors, [&](const auto& e) { return e.second.instance == instance; });
  if (state().detectors.empty()) {
    state().built.clear();
  }
}

}  // namespace

const ServedExtension& ml_world_mesh_detection_extension() {
#define SIM_ML_FUNCTIONS(_)                                                                               \
  _(xrCreateWorldMeshDetectorML) _(xrDestroyWorldMeshDetectorML) _(xrRequestWorldMeshStateAsyncML)        \
  _(xrRequestWorldMeshStateCompleteML) _(xrGetWorldMeshBufferRecommendSizeML) _(xrAllocateWorldMeshBufferML) \
  _(xrFreeWorldMeshBufferML) _(xrRequestWorldMeshAsyncML) _(xrRequestWorldMeshCompleteML)
#define SIM_SERVE(name) ServedFunction{#name, reinterpret_cast<PFN_xrVoidFunction>(&name)},
  static const ServedExtension e{XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME, XR_ML_world_mesh_detection_SPEC_VERSION,
                                 true, {SIM_ML_FUNCTIONS(SIM_SERVE)}, &forget_session, &forget_instance};
#undef SIM_SERVE
#undef SIM_ML_FUNCTIONS
  return e;
}

}  // namespace roomsense::sim
