// XR_ML_world_mesh_detection through the loader: block states and block meshes through futures
// (XR_EXT_future), blocks posed in LOCAL are the room file, uint16 indices (a chunk past 65535 vertices is
// split into several blocks), stable uuids, validation, and a runtime that plays a Magic Leap 2.
#include "mesh_compare.h"
#include "roomsense/scanio.h"
#include "sim_env.h"
#include "xr_harness.h"

#include "roomsense/xr/ext/XR_ML_world_mesh_detection.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace {

using simtest::proc;
using simtest::ScopedEnv;

struct MagicLeap : simtest::App {
  PFN_xrPollFutureEXT poll = nullptr;
  PFN_xrCancelFutureEXT cancel = nullptr;
  PFN_xrCreateWorldMeshDetectorML createDetector = nullptr;
  PFN_xrDestroyWorldMeshDetectorML destroyDetector = nullptr;
  PFN_xrRequestWorldMeshStateAsyncML stateAsync = nullptr;
  PFN_xrRequestWorldMeshStateCompleteML stateComplete = nullptr;
  PFN_xrGetWorldMeshBufferRecommendSizeML recommendSize = nullptr;
  PFN_xrAllocateWorldMeshBufferML allocate = nullptr;
  PFN_xrFreeWorldMeshBufferML free = nullptr;
  PFN_xrRequestWorldMeshAsyncML meshAsync = nullptr;
  PFN_xrRequestWorldMeshCompleteML meshComplete = nullptr;

  MagicLeap()
      : simtest::App({XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_FUTURE_EXTENSION_NAME, XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME}) {
    poll = proc<PFN_xrPollFutureEXT>(instance, "xrPollFutureEXT");
    cancel = proc<PFN_xrCancelFutureEXT>(instance, "xrCancelFutureEXT");
    createDetector = proc<PFN_xrCreateWorldMeshDetectorML>(instance, "xrCreateWorldMeshDetectorML");
    destroyDetector = proc<PFN_xrDestroyWorldMeshDetectorML>(instance, "xrDestroyWorldMeshDetectorML");
    stateAsync = proc<PFN_xrRequestWorldMeshStateAsyncML>(instance, "xrRequestWorldMeshStateAsyncML");
    stateComplete = proc<PFN_xrRequestWorldMeshStateCompleteML>(instance, "xrRequestWorldMeshStateCompleteML");
    recommendSize = proc<PFN_xrGetWorldMeshBufferRecommendSizeML>(instance, "xrGetWorldMeshBufferRecommendSizeML");
    allocate = proc<PFN_xrAllocateWorldMeshBufferML>(instance, "xrAllocateWorldMeshBufferML");
    free = proc<PFN_xrFreeWorldMeshBufferML>(instance, "xrFreeWorldMeshBufferML");
    meshAsync = proc<PFN_xrRequestWorldMeshAsyncML>(instance, "xrRequestWorldMeshAsyncML");
    meshComplete = proc<PFN_xrRequestWorldMeshCompleteML>(instance, "xrRequestWorldMeshCompleteML");
  }

  XrWorldMeshDetectorML detector() const {
    XrWorldMeshDetectorCreateInfoML info{XR_TYPE_WORLD_MESH_DETECTOR_CREATE_INFO_ML};
    XrWorldMeshDetectorML d = XR_NULL_HANDLE;
    SIM_CHECK(createDetector(session, &info, &d));
    return d;
  }

  void wait(XrFutureEXT future) const {
    for (int i = 0; i < 2000; ++i) {
      XrFuturePollInfoEXT info{XR_TYPE_FUTURE_POLL_INFO_EXT};
      info.future = future;
      XrFuturePollResultEXT result{XR_TYPE_FUTURE_POLL_RESULT_EXT};
      SIM_CHECK(poll(instance, &info, &result));
      if (result.state == XR_FUTURE_STATE_READY_EXT) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    throw std::runtime_error("future never ready");
  }

  XrWorldMeshStateRequestInfoML state_info() const {
    XrWorldMeshStateRequestInfoML info{XR_TYPE_WORLD_MESH_STATE_REQUEST_INFO_ML};
    info.baseSpace = local;
    info.time = 1;
    info.boundingBoxCenter.orientation.w = 1;
    info.boundingBoxExtents = {1000.0f, 1000.0f, 1000.0f};
    return info;
  }

  std::vector<XrWorldMeshBlockStateML> states(XrWorldMeshDetectorML d) const {
    const auto info = state_info();
    XrFutureEXT future = XR_NULL_FUTURE_EXT;
    SIM_CHECK(stateAsync(d, &info, &future));
    wait(future);
    XrWorldMeshStateRequestCompletionML completion{XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML};
    SIM_CHECK(stateComplete(d, future, &completion));
    EXPECT_EQ(completion.futureResult, XR_SUCCESS);
    XrWorldMeshBlockStateML proto{};
    proto.type = XR_TYPE_WORLD_MESH_BLOCK_STATE_ML;
    std::vector<XrWorldMeshBlockStateML> out(completion.meshBlockStateCountOutput, proto);
    completion.meshBlockStateCapacityInput = static_cast<uint32_t>(out.size());
    completion.meshBlockStates = out.data();
    SIM_CHECK(stateComplete(d, future, &completion));
    // Taken in full: the future is spent.
    EXPECT_EQ(stateComplete(d, future, &completion), XR_ERROR_FUTURE_INVALID_EXT);
    return out;
  }

  // Every block's mesh, posed with its state, as component meshes in LOCAL.
  std::vector<simtest::ComponentMesh> meshes(XrWorldMeshDetectorML d, const std::vector<XrWorldMeshBlockStateML>& s) const {
    XrWorldMeshBufferRecommendedSizeInfoML size_info{XR_TYPE_WORLD_MESH_BUFFER_RECOMMENDED_SIZE_INFO_ML};
    size_info.maxBlockCount = static_cast<uint32_t>(s.size());
    XrWorldMeshBufferSizeML size{XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML};
    SIM_CHECK(recommendSize(d, &size_info, &size));
    XrWorldMeshBufferML buffer{XR_TYPE_WORLD_MESH_BUFFER_ML};
    SIM_CHECK(allocate(d, &size, &buffer));
    std::vector<XrWorldMeshBlockRequestML> requests;
    for (const auto& state : s) {
      XrWorldMeshBlockRequestML r{XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML};
      r.uuid = state.uuid;
      r.lod = XR_WORLD_MESH_DETECTOR_LOD_MAXIMUM_ML;
      requests.push_back(r);
    }
    XrWorldMeshGetInfoML get{XR_TYPE_WORLD_MESH_GET_INFO_ML};
    get.blockCount = static_cast<uint32_t>(requests.size());
    get.blocks = requests.data();
    XrFutureEXT future = XR_NULL_FUTURE_EXT;
    SIM_CHECK(meshAsync(d, &get, &buffer, &future));
    wait(future);
    XrWorldMeshRequestCompletionInfoML info{XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_INFO_ML};
    info.meshSpace = local;
    info.meshSpaceLocateTime = 1;
    XrWorldMeshBlockML proto{};
    proto.type = XR_TYPE_WORLD_MESH_BLOCK_ML;
    std::vector<XrWorldMeshBlockML> blocks(requests.size(), proto);
    XrWorldMeshRequestCompletionML done{XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_ML};
    done.blockCount = static_cast<uint32_t>(blocks.size());
    done.blocks = blocks.data();
    SIM_CHECK(meshComplete(d, &info, future, &done));
    EXPECT_EQ(done.futureResult, XR_SUCCESS);
    std::vector<simtest::ComponentMesh> out;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      const XrWorldMeshBlockML& b = blocks[i];
      EXPECT_EQ(b.blockResult, XR_WORLD_MESH_BLOCK_RESULT_SUCCESS_ML);
      EXPECT_EQ(std::memcmp(b.uuid.data, s[i].uuid.data, sizeof b.uuid.data), 0);
      EXPECT_LE(b.vertexCount, 65536u);
      simtest::ComponentMesh m;
      m.pose = s[i].meshBoundingBoxCenter;
      m.vertices.assign(b.vertexBuffer, b.vertexBuffer + b.vertexCount);
      m.indices.assign(b.indexBuffer, b.indexBuffer + b.indexCount);
      out.push_back(std::move(m));
    }
    SIM_CHECK(free(d, &buffer));
    return out;
  }
};

std::string key(const XrUuidEXT& u) { return std::string(reinterpret_cast<const char*>(u.data), sizeof u.data); }

void expect_room(const roomsense::Scan& file, const std::vector<simtest::ComponentMesh>& meshes) {
  const simtest::MeshComparison c = simtest::compare_with_file(file, meshes);
  EXPECT_EQ(c.matched_file_vertices, file.vertices.size());
  EXPECT_EQ(c.served_triangles, file.indices.size() / 3);
  EXPECT_TRUE(c.same_triangles);
  EXPECT_LT(c.max_error, 1e-5);
  EXPECT_GT(c.max_error_without_pose, 0.1) << "vertices must be in the block's space";
}

TEST(MlWorldMeshDetection, BlocksPosedInLocalAreTheRoom) {
  const auto path = simtest::write_box_room("ml_box.obj");
  const roomsense::Scan file = simtest::join_identical_vertices(roomsense::scanio::load_mesh_file(path.string()));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  ScopedEnv chunk("ROOMSENSE_SIM_CHUNK_SIZE", std::string("1.0"));
  MagicLeap ml;
  const auto d = ml.detector();
  const auto states = ml.states(d);
  ASSERT_GT(states.size(), 1u);
  for (const auto& s : states) EXPECT_EQ(s.status, XR_WORLD_MESH_BLOCK_STATUS_NEW_ML);
  expect_room(file, ml.meshes(d, states));
  // Asked again: the same blocks, unchanged, at the same update time.
  const auto again = ml.states(d);
  ASSERT_EQ(again.size(), states.size());
  std::map<std::string, XrTime> times;
  for (const auto& s : states) times[key(s.uuid)] = s.lastUpdateTime;
  for (const auto& s : again) {
    EXPECT_EQ(s.status, XR_WORLD_MESH_BLOCK_STATUS_UNCHANGED_ML);
    ASSERT_EQ(times.count(key(s.uuid)), 1u);
    EXPECT_EQ(times[key(s.uuid)], s.lastUpdateTime);
  }
  EXPECT_EQ(ml.destroyDetector(d), XR_SUCCESS);
  EXPECT_EQ(ml.destroyDetector(d), XR_ERROR_HANDLE_INVALID);
}

// A room being scanned (ROOMSENSE_SIM_SCAN_SECONDS): blocks appear over the scan, each NEW when first reported
// and UPDATED when refined (a later update time), each keeping its uuid; after the scan they are the room.
TEST(MlWorldMeshDetection, ARoomBeingScannedGivesNewThenUpdatedBlocksAndEndsAsTheRoom) {
  const auto path = simtest::write_box_room("ml_scanned_box.obj");
  const roomsense::Scan file = simtest::join_identical_vertices(roomsense::scanio::load_mesh_file(path.string()));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  ScopedEnv chunk("ROOMSENSE_SIM_CHUNK_SIZE", std::string("1.0"));
  ScopedEnv scan("ROOMSENSE_SIM_SCAN_SECONDS", std::string("0.6"));
  MagicLeap ml;
  const auto start = std::chrono::steady_clock::now();  // after the instance's creation, where the scan starts
  const auto d = ml.detector();
  std::map<std::string, XrTime> times;  // per uuid, its update time when last reported
  std::set<std::size_t> counts;
  std::size_t updated = 0;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(700)) {
    const auto states = ml.states(d);
    counts.insert(states.size());
    for (const auto& s : states) {
      const auto seen = times.find(key(s.uuid));
      if (seen == times.end()) {
        EXPECT_EQ(s.status, XR_WORLD_MESH_BLOCK_STATUS_NEW_ML);
      } else if (s.lastUpdateTime != seen->second) {
        EXPECT_GT(s.lastUpdateTime, seen->second);
        EXPECT_EQ(s.status, XR_WORLD_MESH_BLOCK_STATUS_UPDATED_ML);
        ++updated;
      } else {
        EXPECT_EQ(s.status, XR_WORLD_MESH_BLOCK_STATUS_UNCHANGED_ML);
      }
      times[key(s.uuid)] = s.lastUpdateTime;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_GE(counts.size(), 3u) << "blocks appeared over the scan";
  EXPECT_GT(updated, 0u) << "no block was refined";
  const auto states = ml.states(d);
  EXPECT_EQ(states.size(), times.size());
  expect_room(file, ml.meshes(d, states));
}

TEST(MlWorldMeshDetection, AChunkPastUint16IsSplitIntoBlocks) {
  const auto path = simtest::write_box_room("ml_big_box.obj", 200);  // 2 x 201^2 grid vertices
  const roomsense::Scan file = simtest::join_identical_vertices(roomsense::scanio::load_mesh_file(path.string()));
  ASSERT_GT(file.vertices.size(), 65536u);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", path.string());
  ScopedEnv chunk("ROOMSENSE_SIM_CHUNK_SIZE", std::string("1000"));  // one chunk
  MagicLeap ml;
  const auto d = ml.detector();
  const auto states = ml.states(d);
  EXPECT_GE(states.size(), 2u);
  expect_room(file, ml.meshes(d, states));
}

TEST(MlWorldMeshDetection, Validation) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  MagicLeap ml;
  XrWorldMeshDetectorML d = XR_NULL_HANDLE;
  EXPECT_EQ(ml.createDetector(ml.session, nullptr, &d), XR_ERROR_VALIDATION_FAILURE);
  d = ml.detector();
  XrFutureEXT future = XR_NULL_FUTURE_EXT;
  auto info = ml.state_info();
  info.time = 0;
  EXPECT_EQ(ml.stateAsync(d, &info, &future), XR_ERROR_TIME_INVALID);
  info = ml.state_info();
  info.boundingBoxCenter.orientation.w = 0;
  EXPECT_EQ(ml.stateAsync(d, &info, &future), XR_ERROR_POSE_INVALID);
  info = ml.state_info();
  info.baseSpace = XR_NULL_HANDLE;
  EXPECT_EQ(ml.stateAsync(d, &info, &future), XR_ERROR_HANDLE_INVALID);
  info = ml.state_info();
  info.boundingBoxExtents.depth = -1;
  EXPECT_EQ(ml.stateAsync(d, &info, &future), XR_ERROR_VALIDATION_FAILURE);

  // Too small a capacity: SIZE_INSUFFICIENT with the count, and the states wait for the next call.
  info = ml.state_info();
  SIM_CHECK(ml.stateAsync(d, &info, &future));
  ml.wait(future);
  XrWorldMeshBlockStateML one{};
  one.type = XR_TYPE_WORLD_MESH_BLOCK_STATE_ML;
  XrWorldMeshStateRequestCompletionML completion{XR_TYPE_WORLD_MESH_STATE_REQUEST_COMPLETION_ML};
  completion.meshBlockStateCapacityInput = 1;
  completion.meshBlockStates = &one;
  EXPECT_EQ(ml.stateComplete(d, future, &completion), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_GT(completion.meshBlockStateCountOutput, 1u);
  EXPECT_EQ(ml.stateComplete(d, XR_NULL_FUTURE_EXT, &completion), XR_ERROR_FUTURE_INVALID_EXT);
  const auto states = ml.states(d);

  XrWorldMeshBufferSizeML size{XR_TYPE_WORLD_MESH_BUFFER_SIZE_ML};
  XrWorldMeshBufferML buffer{XR_TYPE_WORLD_MESH_BUFFER_ML};
  EXPECT_EQ(ml.allocate(d, &size, &buffer), XR_ERROR_VALIDATION_FAILURE) << "size 0";
  size.size = 64;
  SIM_CHECK(ml.allocate(d, &size, &buffer));
  XrWorldMeshBlockRequestML r{XR_TYPE_WORLD_MESH_BLOCK_REQUEST_ML};
  r.uuid = states[0].uuid;
  r.lod = static_cast<XrWorldMeshDetectorLodML>(9);
  XrWorldMeshGetInfoML get{XR_TYPE_WORLD_MESH_GET_INFO_ML};
  get.blockCount = 1;
  get.blocks = &r;
  EXPECT_EQ(ml.meshAsync(d, &get, &buffer, &future), XR_ERROR_VALIDATION_FAILURE) << "a LOD of no kind";
  r.lod = XR_WORLD_MESH_DETECTOR_LOD_MINIMUM_ML;
  XrWorldMeshBufferML foreign{XR_TYPE_WORLD_MESH_BUFFER_ML};
  std::vector<std::uint8_t> mine(64);
  foreign.bufferSize = 64;
  foreign.buffer = mine.data();
  EXPECT_EQ(ml.meshAsync(d, &get, &foreign, &future), XR_ERROR_VALIDATION_FAILURE) << "a buffer the runtime did not allocate";
  // A buffer too small for the block: the block FAILED, the request itself fine.
  SIM_CHECK(ml.meshAsync(d, &get, &buffer, &future));
  XrWorldMeshRequestCompletionInfoML done_info{XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_INFO_ML};
  done_info.meshSpace = ml.local;
  done_info.meshSpaceLocateTime = 1;
  XrWorldMeshBlockML block{};
  block.type = XR_TYPE_WORLD_MESH_BLOCK_ML;
  XrWorldMeshRequestCompletionML done{XR_TYPE_WORLD_MESH_REQUEST_COMPLETION_ML};
  done.blockCount = 1;
  done.blocks = &block;
  ml.wait(future);
  done_info.meshSpaceLocateTime = 0;
  EXPECT_EQ(ml.meshComplete(d, &done_info, future, &done), XR_ERROR_TIME_INVALID);
  done_info.meshSpaceLocateTime = 1;
  SIM_CHECK(ml.meshComplete(d, &done_info, future, &done));
  EXPECT_EQ(block.blockResult, XR_WORLD_MESH_BLOCK_RESULT_FAILED_ML);
  EXPECT_EQ(ml.meshComplete(d, &done_info, future, &done), XR_ERROR_FUTURE_INVALID_EXT) << "completed twice";
  // A cancelled future is gone.
  SIM_CHECK(ml.meshAsync(d, &get, &buffer, &future));
  XrFutureCancelInfoEXT cancel{XR_TYPE_FUTURE_CANCEL_INFO_EXT};
  cancel.future = future;
  SIM_CHECK(ml.cancel(ml.instance, &cancel));
  EXPECT_EQ(ml.meshComplete(d, &done_info, future, &done), XR_ERROR_FUTURE_INVALID_EXT);
  SIM_CHECK(ml.free(d, &buffer));
  EXPECT_EQ(ml.free(d, &buffer), XR_ERROR_VALIDATION_FAILURE) << "freed twice";
}

TEST(MlWorldMeshDetection, ASessionsDetectorsGoWithIt) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  MagicLeap ml;
  const auto d = ml.detector();
  SIM_CHECK(xrDestroySession(ml.session));
  EXPECT_EQ(ml.destroyDetector(d), XR_ERROR_HANDLE_INVALID);
}

TEST(MlWorldMeshDetection, PlayingAMagicLeapHidesTheOtherSceneExtensions) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME));
  uint32_t count = 0;
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr));
  std::vector<XrExtensionProperties> props(count, XrExtensionProperties{XR_TYPE_EXTENSION_PROPERTIES});
  SIM_CHECK(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()));
  std::set<std::string> names;
  for (const auto& p : props) names.insert(p.extensionName);
  EXPECT_EQ(names.count(XR_ML_WORLD_MESH_DETECTION_EXTENSION_NAME), 1u);
  EXPECT_EQ(names.count(XR_EXT_FUTURE_EXTENSION_NAME), 1u);
  EXPECT_EQ(names.count(XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME), 0u);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  MagicLeap ml;
  EXPECT_GT(ml.states(ml.detector()).size(), 1u);
}

}  // namespace
