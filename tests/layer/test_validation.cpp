// XR_EXTX_room_understanding's validation: structure types, null pointers, handles, the two-call idiom's
// XR_ERROR_SIZE_INSUFFICIENT, call order, and functions of an extension that is not enabled.
#include "layer_harness.h"
#include "roomsense/synthetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace layertest;

// A 4 x 2.5 x 3 m box room as one mesh (faces into the room), enough for a result.
struct BoxRoom {
  std::vector<XrVector3f> vertices;
  std::vector<uint32_t> indices;
  BoxRoom() {
    const roomsense::Scan s = roomsense::synth::generate_builtin_source("synthetic:default");
    for (const glm::vec3& v : s.vertices) vertices.push_back({v.x, v.y, v.z});
    indices = s.indices;
  }
};

XrRoomAnalyzerEXTX bogus() { return reinterpret_cast<XrRoomAnalyzerEXTX>(uintptr_t{0xbad0bad}); }

TEST(LayerValidation, FunctionsOfTheExtensionAreUnsupportedWhenItIsNotEnabled) {
  App app({XR_MND_HEADLESS_EXTENSION_NAME});
  for (const char* name : {"xrCreateRoomAnalyzerEXTX", "xrDestroyRoomAnalyzerEXTX", "xrSubmitRoomMeshEXTX", "xrComputeRoomEXTX",
                           "xrGetRoomComputeStateEXTX", "xrGetRoomLayoutEXTX", "xrGetRoomAreasEXTX", "xrGetRoomBoundsMeshEXTX"}) {
    PFN_xrVoidFunction f = reinterpret_cast<PFN_xrVoidFunction>(uintptr_t{1});
    EXPECT_EQ(xrGetInstanceProcAddr(app.instance, name, &f), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
    EXPECT_EQ(f, nullptr) << name;
  }
}

TEST(LayerValidation, CreateAnalyzer) {
  App app;
  XrRoomAnalyzerCreateInfoEXTX info{XR_TYPE_ROOM_ANALYZER_CREATE_INFO_EXTX, nullptr};
  info.baseSpace = app.local;
  XrRoomAnalyzerEXTX a = XR_NULL_HANDLE;
  EXPECT_EQ(app.extx.create(app.session, nullptr, &a), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(app.extx.create(app.session, &info, nullptr), XR_ERROR_VALIDATION_FAILURE);
  XrRoomAnalyzerCreateInfoEXTX wrong = info;
  wrong.type = XR_TYPE_ROOM_COMPUTE_INFO_EXTX;
  EXPECT_EQ(app.extx.create(app.session, &wrong, &a), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(app.extx.create(reinterpret_cast<XrSession>(uintptr_t{0xbad}), &info, &a), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(app.extx.create(XR_NULL_HANDLE, &info, &a), XR_ERROR_HANDLE_INVALID);
  XrRoomAnalyzerCreateInfoEXTX no_space = info;
  no_space.baseSpace = XR_NULL_HANDLE;
  EXPECT_EQ(app.extx.create(app.session, &no_space, &a), XR_ERROR_HANDLE_INVALID);
  for (float voxel : {-0.1f, 0.001f, 5.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    XrRoomAnalyzerCreateInfoEXTX bad = info;
    bad.voxelSize = voxel;
    EXPECT_EQ(app.extx.create(app.session, &bad, &a), XR_ERROR_VALIDATION_FAILURE) << voxel;
  }
  XrRoomAnalyzerCreateInfoEXTX bad_backend = info;
  bad_backend.backend = static_cast<XrRoomComputeBackendEXTX>(7);
  EXPECT_EQ(app.extx.create(app.session, &bad_backend, &a), XR_ERROR_VALIDATION_FAILURE);
  // The base space must be gravity-aligned: VIEW is not, nor a LOCAL space tilted by its pose.
  XrRoomAnalyzerCreateInfoEXTX view = info;
  view.baseSpace = app.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  EXPECT_EQ(app.extx.create(app.session, &view, &a), XR_ERROR_VALIDATION_FAILURE);
  XrRoomAnalyzerCreateInfoEXTX tilted = info;
  const float s = std::sqrt(0.5f);
  tilted.baseSpace = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL, {{s, 0, 0, s}, {0, 0, 0}});
  EXPECT_EQ(app.extx.create(app.session, &tilted, &a), XR_ERROR_VALIDATION_FAILURE);
  // Yawed and moved is fine, and so is STAGE.
  XrRoomAnalyzerCreateInfoEXTX yawed = info;
  yawed.baseSpace = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL, {{0, s, 0, s}, {1, 0, 2}});
  ASSERT_EQ(app.extx.create(app.session, &yawed, &a), XR_SUCCESS);
  EXPECT_NE(a, XR_NULL_HANDLE);
  XrRoomAnalyzerCreateInfoEXTX stage = info;
  stage.baseSpace = app.reference_space(XR_REFERENCE_SPACE_TYPE_STAGE);
  XrRoomAnalyzerEXTX b = XR_NULL_HANDLE;
  ASSERT_EQ(app.extx.create(app.session, &stage, &b), XR_SUCCESS);
  EXPECT_NE(a, b);
  EXPECT_EQ(app.extx.destroy(a), XR_SUCCESS);
  EXPECT_EQ(app.extx.destroy(a), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(app.extx.destroy(b), XR_SUCCESS);
  EXPECT_EQ(app.extx.destroy(XR_NULL_HANDLE), XR_ERROR_HANDLE_INVALID);
}

TEST(LayerValidation, SubmitMesh) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  const std::vector<XrVector3f> v = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  const std::vector<uint32_t> i = {0, 2, 1};
  XrRoomMeshEXTX mesh{XR_TYPE_ROOM_MESH_EXTX, nullptr};
  mesh.pose = {{0, 0, 0, 1}, {0, 0, 0}};
  mesh.vertexCount = 3;
  mesh.vertices = v.data();
  mesh.indexCount = 3;
  mesh.indices = i.data();
  EXPECT_EQ(app.extx.submit(a, &mesh), XR_SUCCESS);
  EXPECT_EQ(app.extx.submit(bogus(), &mesh), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(app.extx.submit(a, nullptr), XR_ERROR_VALIDATION_FAILURE);
  auto with = [&](auto change) {
    XrRoomMeshEXTX m = mesh;
    change(m);
    return app.extx.submit(a, &m);
  };
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.type = XR_TYPE_ROOM_AREA_EXTX; }), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.vertices = nullptr; }), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.vertexCount = 0; }), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.indices = nullptr; }), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.indexCount = 2; }), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.vertexCount = 2; }), XR_ERROR_VALIDATION_FAILURE);  // index 2 out of range
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.pose.orientation = {0, 0, 0, 2}; }), XR_ERROR_POSE_INVALID);
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.pose.position.x = NAN; }), XR_ERROR_POSE_INVALID);
  EXPECT_EQ(with([](XrRoomMeshEXTX& m) { m.indexCount = 0, m.indices = nullptr; }), XR_SUCCESS);  // a point cloud
}

TEST(LayerValidation, ComputeAndState) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  XrRoomComputeInfoEXTX info{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
  info.time = now();
  EXPECT_EQ(app.extx.compute(bogus(), &info), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(app.extx.compute(a, nullptr), XR_ERROR_VALIDATION_FAILURE);
  XrRoomComputeInfoEXTX wrong = info;
  wrong.type = XR_TYPE_ROOM_MESH_EXTX;
  EXPECT_EQ(app.extx.compute(a, &wrong), XR_ERROR_VALIDATION_FAILURE);
  XrRoomComputeInfoEXTX no_time = info;
  no_time.time = 0;
  EXPECT_EQ(app.extx.compute(a, &no_time), XR_ERROR_TIME_INVALID);
  XrRoomComputeStateEXTX state = XR_ROOM_COMPUTE_STATE_MAX_ENUM_EXTX;
  EXPECT_EQ(app.extx.state(a, nullptr), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(app.extx.state(bogus(), &state), XR_ERROR_HANDLE_INVALID);
  ASSERT_EQ(app.extx.state(a, &state), XR_SUCCESS);
  EXPECT_EQ(state, XR_ROOM_COMPUTE_STATE_NONE_EXTX);
  // Nothing to analyse: the compute fails, and there is still no result.
  EXPECT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_FAILED_EXTX);
  XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
  EXPECT_EQ(app.extx.layout(a, &layout), XR_ERROR_CALL_ORDER_INVALID);
}

TEST(LayerValidation, ComputingWhileAComputeRunsIsOutOfOrder) {
  ScopedEnv delay("ROOMSENSE_SIM_COMPUTE_DELAY_MS", std::string("500"));  // the runtime's scene takes a while
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  app.start(a, true);
  XrRoomComputeInfoEXTX info{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
  info.time = now();
  info.includeRuntimeMeshes = XR_TRUE;
  EXPECT_EQ(app.extx.compute(a, &info), XR_ERROR_CALL_ORDER_INVALID);
  EXPECT_EQ(app.wait(a), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  EXPECT_EQ(app.extx.compute(a, &info), XR_SUCCESS);  // and again once it is done
  EXPECT_EQ(app.wait(a), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
}

TEST(LayerValidation, GettersBeforeAnyResultAreOutOfOrder) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
  EXPECT_EQ(app.extx.layout(a, &layout), XR_ERROR_CALL_ORDER_INVALID);
  uint32_t count = 0;
  EXPECT_EQ(app.extx.areas(a, 0, &count, nullptr), XR_ERROR_CALL_ORDER_INVALID);
  XrRoomBoundsMeshEXTX bounds{XR_TYPE_ROOM_BOUNDS_MESH_EXTX, nullptr};
  EXPECT_EQ(app.extx.bounds(a, &bounds), XR_ERROR_CALL_ORDER_INVALID);
}

TEST(LayerValidation, Getters) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  const BoxRoom room;
  app.submit(a, room.vertices, room.indices);
  ASSERT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);

  XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
  EXPECT_EQ(app.extx.layout(bogus(), &layout), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(app.extx.layout(a, nullptr), XR_ERROR_VALIDATION_FAILURE);
  XrRoomLayoutEXTX wrong_layout{XR_TYPE_ROOM_AREA_EXTX, nullptr};
  EXPECT_EQ(app.extx.layout(a, &wrong_layout), XR_ERROR_VALIDATION_FAILURE);
  ASSERT_EQ(app.extx.layout(a, &layout), XR_SUCCESS);
  EXPECT_NEAR(layout.floorHeight, 0.0f, 0.05f);
  EXPECT_NEAR(layout.ceilingHeight, 2.6f, 0.05f);
  EXPECT_EQ(layout.storeyCount, 1u);
  EXPECT_EQ(layout.inputVertexCount, room.vertices.size());
  EXPECT_EQ(layout.inputTriangleCount, room.indices.size() / 3);
  EXPECT_GT(layout.computeDuration, 0);
  EXPECT_LT(layout.boundsMin.y, layout.boundsMax.y);

  // The JSON in the layout's next chain: two-call idiom.
  XrRoomAnalysisJsonEXTX json{XR_TYPE_ROOM_ANALYSIS_JSON_EXTX, nullptr};
  layout.next = &json;
  ASSERT_EQ(app.extx.layout(a, &layout), XR_SUCCESS);
  EXPECT_GT(json.jsonCountOutput, 100u);
  std::vector<char> text(json.jsonCountOutput);
  json.jsonCapacityInput = json.jsonCountOutput - 1;
  json.json = text.data();
  EXPECT_EQ(app.extx.layout(a, &layout), XR_ERROR_SIZE_INSUFFICIENT);
  json.jsonCapacityInput = 5;
  json.json = nullptr;
  EXPECT_EQ(app.extx.layout(a, &layout), XR_ERROR_VALIDATION_FAILURE);
  json.jsonCapacityInput = static_cast<uint32_t>(text.size());
  json.json = text.data();
  ASSERT_EQ(app.extx.layout(a, &layout), XR_SUCCESS);
  EXPECT_EQ(text.back(), '\0');
  EXPECT_NE(std::string(text.data()).find("\"schema\": \"roomsense.analysis/1\""), std::string::npos);

  uint32_t count = 0;
  EXPECT_EQ(app.extx.areas(a, 0, nullptr, nullptr), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(app.extx.areas(a, 3, &count, nullptr), XR_ERROR_VALIDATION_FAILURE);
  ASSERT_EQ(app.extx.areas(a, 0, &count, nullptr), XR_SUCCESS);
  ASSERT_GT(count, 1u) << "the default room has areas";
  std::vector<XrRoomAreaEXTX> areas(count, {XR_TYPE_ROOM_AREA_EXTX, nullptr});
  uint32_t written = 0;
  EXPECT_EQ(app.extx.areas(a, count - 1, &written, areas.data()), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(written, count);
  areas[1].type = XR_TYPE_ROOM_LAYOUT_EXTX;
  EXPECT_EQ(app.extx.areas(a, count, &written, areas.data()), XR_ERROR_VALIDATION_FAILURE);
  areas[1].type = XR_TYPE_ROOM_AREA_EXTX;
  ASSERT_EQ(app.extx.areas(a, count, &written, areas.data()), XR_SUCCESS);
  for (const XrRoomAreaEXTX& area : areas) {
    EXPECT_GE(area.areaType, XR_ROOM_AREA_TYPE_WALL_EXTX);
    EXPECT_LE(area.areaType, XR_ROOM_AREA_TYPE_FURNITURE_EXTX);
    EXPECT_GT(area.extents.width, 0.0f);
    const auto& q = area.pose.orientation;
    EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0f, 1e-4f);
  }

  XrRoomBoundsMeshEXTX bounds{XR_TYPE_ROOM_BOUNDS_MESH_EXTX, nullptr};
  EXPECT_EQ(app.extx.bounds(a, nullptr), XR_ERROR_VALIDATION_FAILURE);
  XrRoomBoundsMeshEXTX wrong_bounds{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
  EXPECT_EQ(app.extx.bounds(a, &wrong_bounds), XR_ERROR_VALIDATION_FAILURE);
  ASSERT_EQ(app.extx.bounds(a, &bounds), XR_SUCCESS);
  ASSERT_GT(bounds.vertexCountOutput, 0u);
  ASSERT_GT(bounds.indexCountOutput, 0u);
  std::vector<XrVector3f> v(bounds.vertexCountOutput);
  std::vector<uint32_t> idx(bounds.indexCountOutput);
  bounds.vertexCapacityInput = 4;
  bounds.vertices = nullptr;
  EXPECT_EQ(app.extx.bounds(a, &bounds), XR_ERROR_VALIDATION_FAILURE);
  bounds.vertices = v.data();
  bounds.vertexCapacityInput = static_cast<uint32_t>(v.size()) - 1;
  EXPECT_EQ(app.extx.bounds(a, &bounds), XR_ERROR_SIZE_INSUFFICIENT);
  bounds.vertexCapacityInput = static_cast<uint32_t>(v.size());
  bounds.indices = idx.data();
  bounds.indexCapacityInput = static_cast<uint32_t>(idx.size()) - 3;
  EXPECT_EQ(app.extx.bounds(a, &bounds), XR_ERROR_SIZE_INSUFFICIENT);
  bounds.indexCapacityInput = static_cast<uint32_t>(idx.size());
  ASSERT_EQ(app.extx.bounds(a, &bounds), XR_SUCCESS);
  for (uint32_t i : idx) EXPECT_LT(i, v.size());

  // NaN vertices are skipped (and counted), the room stays.
  const std::vector<XrVector3f> nan_only = {{NAN, NAN, NAN}, {NAN, 0, 0}, {0, NAN, 0}};
  app.submit(a, nan_only, {0, 1, 2});
  EXPECT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
}

TEST(LayerValidation, AFailedComputeKeepsThePreviousResult) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const Result first = read_result(app.extx, a);
  EXPECT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_FAILED_EXTX);  // nothing submitted, runtime left out
  const Result still = read_result(app.extx, a);
  EXPECT_EQ(still.areas.size(), first.areas.size());
  EXPECT_EQ(still.indices, first.indices);
  EXPECT_EQ(still.json, first.json);
}

TEST(LayerValidation, HandlesDieWithTheirSession) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  app.close_session();
  XrRoomComputeStateEXTX state;
  EXPECT_EQ(app.extx.state(a, &state), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(app.extx.destroy(a), XR_ERROR_HANDLE_INVALID);
}

}  // namespace
