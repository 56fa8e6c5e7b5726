// The layer's results against the CLI's and analyze()'s on the same room file.
//
// Submitted meshes (xrSubmitRoomMeshEXTX with an identity pose) reach the pipeline bit for bit, so there the
// layer must match exactly. The runtime's meshes do not: the simulated runtime serves each chunk of the room
// in its own component space (the chunk's centre, turned by a per-chunk yaw), like a real device, and the
// layer maps the vertices back with the located pose. Each vertex comes back within float rounding of where
// the file has it (a few 1e-7 m). That moves the grid origin (the minimum vertex) and the measured surface
// heights by as much, and could flip a vertex lying within that distance of a voxel boundary into the next
// voxel. So the comparison there allows 1e-4 m on every number and no structural difference (the same areas
// of the same types, sizes and reach, the same bounds counts); ROOMSENSE_SIM_CHUNK_SIZE=1000 serves the room
// as one component (one pose), the default 2 m chunks as many.
#include "compare.h"
#include "passive_capture.h"
#include "rooms.h"
#include "roomsense/analysis.h"
#include "roomsense/export.h"
#include "roomsense/quest_capture.h"
#include "roomsense/scanio.h"
#include "roomsense/synthetic.h"

#include <dlfcn.h>

#include <gtest/gtest.h>

#include <fstream>
#include <set>

namespace {

using namespace layertest;

std::vector<XrVector3f> xr_vertices(const roomsense::Scan& scan) {
  std::vector<XrVector3f> v;
  v.reserve(scan.vertices.size());
  for (const glm::vec3& p : scan.vertices) v.push_back({p.x, p.y, p.z});
  return v;
}

Result analyse_submitted(const roomsense::Scan& scan) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  app.submit(a, xr_vertices(scan), scan.indices);
  EXPECT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  return read_result(app.extx, a);
}

TEST(LayerResults, SubmittedSyntheticRoomMatchesAnalyzeAndTheCliExactly) {
  const roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:default");
  const Result got = analyse_submitted(scan);
  roomsense::AnalysisOptions options;
  const roomsense::AnalysisResult want = roomsense::analyze(scan, options);
  ASSERT_TRUE(want.ok());
  EXPECT_FALSE(want.areas.empty()) << "the pipeline finds no areas in the default room";
  expect_identical(got, want);
  expect_same_room_json(nlohmann::json::parse(got.json), run_cli("synthetic:default"));
}

// Spec version 3 on whole homes: every storey's heights, the rooms and each area's storey and room are
// analyze()'s, and there is more than one of each (the flat's three rooms, the house's two storeys).
TEST(LayerResults, SubmittedWholeHomesSayEachAreasStoreyAndRoom) {
  for (const char* source : {"synthetic:flat", "synthetic:house"}) {
    SCOPED_TRACE(source);
    const roomsense::Scan scan = roomsense::synth::generate_builtin_source(source);
    const Result got = analyse_submitted(scan);
    const roomsense::AnalysisResult want = roomsense::analyze(scan);
    ASSERT_TRUE(want.ok());
    expect_identical(got, want);
    EXPECT_GE(got.rooms.size(), 2u);
    EXPECT_EQ(got.layout.storeyCount, got.storeys.size());
    std::set<std::uint32_t> storeys, rooms;
    for (const XrRoomAreaLocationEXTX& l : got.area_locations) {
      storeys.insert(l.storeyIndex);
      rooms.insert(l.roomIndex);
    }
    EXPECT_EQ(storeys.size(), got.storeys.size());
    EXPECT_GE(rooms.size(), 2u);
    // Each room's own bounds, chained to the bounds getter.
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    app.submit(a, xr_vertices(scan), scan.indices);
    ASSERT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    for (std::uint32_t k = 0; k <= want.rooms.size(); ++k) {
      XrRoomBoundsMeshRoomEXTX room{XR_TYPE_ROOM_BOUNDS_MESH_ROOM_EXTX, nullptr, k};
      if (k == want.rooms.size()) {  // one past the last room
        XrRoomBoundsMeshEXTX mesh{XR_TYPE_ROOM_BOUNDS_MESH_EXTX, &room};
        EXPECT_EQ(app.extx.bounds(a, &mesh), XR_ERROR_VALIDATION_FAILURE);
        break;
      }
      std::vector<XrVector3f> vertices;
      std::vector<uint32_t> indices;
      read_bounds(app.extx, a, &room, vertices, indices);
      EXPECT_EQ(indices, want.room_bounds[k].indices) << "room " << k;
      ASSERT_EQ(vertices.size(), want.room_bounds[k].vertices.size());
      for (std::size_t v = 0; v < vertices.size(); ++v) EXPECT_EQ(vertices[v].y, want.room_bounds[k].vertices[v].y);
    }
  }
}

// Issue 15, ceilings that are not one level, through the extension: the loft's ceiling areas come with
// analyze()'s poses, on both slopes of the roof (their +Z, the normal, tilted along the slope), and the home
// layout's storey reaches the ridge.
TEST(LayerResults, SubmittedLoftServesCeilingAreasOnItsSlopes) {
  const roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:loft");
  const Result got = analyse_submitted(scan);
  const roomsense::AnalysisResult want = roomsense::analyze(scan);
  ASSERT_TRUE(want.ok());
  expect_identical(got, want);
  std::size_t toward_plus_z = 0, toward_minus_z = 0;
  for (const XrRoomAreaEXTX& a : got.areas) {
    if (a.areaType != XR_ROOM_AREA_TYPE_CEILING_EXTX) continue;
    const XrQuaternionf& q = a.pose.orientation;  // +Z rotated: the area's normal
    const float nz = 1.0f - 2.0f * (q.x * q.x + q.y * q.y), ny = 2.0f * (q.y * q.z - q.w * q.x);
    EXPECT_LT(ny, -0.5f) << "a ceiling area faces down";
    if (ny > -0.95f) (nz > 0.0f ? toward_plus_z : toward_minus_z) += 1;
  }
  EXPECT_GE(toward_plus_z, 3u);
  EXPECT_GE(toward_minus_z, 3u);
  ASSERT_EQ(got.storeys.size(), 1u);
  EXPECT_NEAR(got.storeys[0].ceilingHeight, 3.2f, 0.05f);
}

// Issue 19, item 2: a compute over the meshes of the latest result keeps that result (its computeDuration
// is the analysis's, not a new one's); a new mesh gets a new analysis. With the runtime's meshes too.
TEST(LayerResults, ComputingAnUnchangedRoomKeepsTheLatestResult) {
  for (const bool include_runtime : {false, true}) {
    SCOPED_TRACE(include_runtime ? "runtime and submitted meshes" : "submitted meshes");
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    const roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:default");
    app.submit(a, xr_vertices(scan), scan.indices);
    ASSERT_EQ(app.compute(a, include_runtime), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    const Result first = read_result(app.extx, a);
    ASSERT_GT(first.layout.computeDuration, 0);
    for (int again = 0; again < 2; ++again) {
      ASSERT_EQ(app.compute(a, include_runtime), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
      const Result same = read_result(app.extx, a);
      EXPECT_EQ(same.layout.computeDuration, first.layout.computeDuration) << "the room was analysed again";
      EXPECT_EQ(same.json, first.json);
      EXPECT_EQ(same.areas.size(), first.areas.size());
    }
    // A 1 m table top in the middle of the room: new meshes, a new analysis.
    app.submit(a, {{-0.5f, 0.7f, -0.5f}, {0.5f, 0.7f, -0.5f}, {0.5f, 0.7f, 0.5f}, {-0.5f, 0.7f, 0.5f}}, {0, 2, 1, 0, 3, 2});
    ASSERT_EQ(app.compute(a, include_runtime), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    const Result changed = read_result(app.extx, a);
    EXPECT_EQ(changed.layout.inputVertexCount, first.layout.inputVertexCount + 4);
    EXPECT_NE(changed.json, first.json);
  }
}

// The two-call idiom on the home layout: counts alone, a too-small array, a null array with a capacity.
TEST(LayerResults, HomeLayoutFollowsTheTwoCallIdiom) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  const roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:flat");
  app.submit(a, xr_vertices(scan), scan.indices);
  ASSERT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  XrRoomHomeLayoutEXTX home{XR_TYPE_ROOM_HOME_LAYOUT_EXTX, nullptr};
  XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, &home};
  ASSERT_EQ(app.extx.layout(a, &layout), XR_SUCCESS);
  EXPECT_EQ(home.storeyCountOutput, 1u);
  EXPECT_EQ(home.roomCountOutput, 3u);
  std::vector<XrRoomInfoEXTX> rooms(2);
  home.roomCapacityInput = 2;
  home.rooms = rooms.data();
  EXPECT_EQ(app.extx.layout(a, &layout), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(home.roomCountOutput, 3u);
  home.rooms = nullptr;
  EXPECT_EQ(app.extx.layout(a, &layout), XR_ERROR_VALIDATION_FAILURE);
}

// The Vulkan voxel stage through the layer (lavapipe where there is no GPU): the same room as the CPU path,
// by the compute backend's design. ROOMSENSE_BACKEND steers analyzers that ask for AUTO, and only those.
TEST(LayerResults, VulkanBackendMatchesTheCpuBackend) {
  // The Vulkan loader finds its drivers through XDG_DATA_DIRS, which the test environment empties (so that no
  // host OpenXR layer joins in); the system's data dirs hold only explicit OpenXR layers.
  ScopedEnv data_dirs("XDG_DATA_DIRS", std::string("/usr/local/share:/usr/share"));
  // The layer, and with it the Vulkan loader and driver, is unloaded with each instance. Keeping the Vulkan
  // libraries loaded lets LeakSanitizer name them (lsan.supp suppresses the driver stack's own leaks by name).
  for (const char* lib : {"libvulkan.so.1", "libvulkan_lvp.so"}) dlopen(lib, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  const roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:default");
  auto run = [&](XrRoomComputeBackendEXTX backend) {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer(XR_NULL_HANDLE, 0.0f, backend);
    app.submit(a, xr_vertices(scan), scan.indices);
    EXPECT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    return nlohmann::json::parse(read_result(app.extx, a).json);
  };
  const nlohmann::json cpu = run(XR_ROOM_COMPUTE_BACKEND_CPU_EXTX);
  EXPECT_EQ(cpu["grid"]["backend"], "cpu");
  const nlohmann::json vulkan = run(XR_ROOM_COMPUTE_BACKEND_VULKAN_EXTX);
  if (vulkan["grid"]["backend"] != "vulkan") {
    if (roomsense::test::running_in_ci()) FAIL() << "CI must have a Vulkan device (lavapipe)";
    GTEST_SKIP() << "no Vulkan device: the layer fell back to the CPU path";
  }
  expect_same_room_json(vulkan, cpu);
  ScopedEnv env("ROOMSENSE_BACKEND", std::string("vulkan"));
  EXPECT_EQ(run(XR_ROOM_COMPUTE_BACKEND_AUTO_EXTX)["grid"]["backend"], "vulkan");
  EXPECT_EQ(run(XR_ROOM_COMPUTE_BACKEND_CPU_EXTX)["grid"]["backend"], "cpu");
}

// An analyzer keeps the Vulkan stage it started (310-370 ms on an H100, compute/README.md) for its later computes:
// two computes of a changed scan log one stage start, and both run on Vulkan.
TEST(LayerResults, AnalyzerKeepsItsVulkanStage) {
  ScopedEnv data_dirs("XDG_DATA_DIRS", std::string("/usr/local/share:/usr/share"));
  for (const char* lib : {"libvulkan.so.1", "libvulkan_lvp.so"}) dlopen(lib, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  const std::filesystem::path dir = temp_dir("kept_stage");
  std::filesystem::create_directories(dir);
  const std::filesystem::path log = dir / "layer.log";
  ScopedEnv file("ROOMSENSE_LOG_FILE", log.string());
  ScopedEnv level("ROOMSENSE_LOG", std::string("info"));
  const roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:default");
  {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer(XR_NULL_HANDLE, 0.0f, XR_ROOM_COMPUTE_BACKEND_VULKAN_EXTX);
    app.submit(a, xr_vertices(scan), scan.indices);
    ASSERT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    const nlohmann::json first = nlohmann::json::parse(read_result(app.extx, a).json);
    if (first["grid"]["backend"] != "vulkan") {
      if (roomsense::test::running_in_ci()) FAIL() << "CI must have a Vulkan device (lavapipe)";
      GTEST_SKIP() << "no Vulkan device: the layer fell back to the CPU path";
    }
    app.submit(a, xr_vertices(scan), scan.indices);  // a second piece: the input changed
    ASSERT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    EXPECT_EQ(nlohmann::json::parse(read_result(app.extx, a).json)["grid"]["backend"], "vulkan");
  }
  std::ifstream in(log);
  int starts = 0, computes = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.find("backend: vulkan: requested") != std::string::npos) ++starts;
    if (line.find("analysis completed") != std::string::npos) ++computes;
  }
  EXPECT_EQ(computes, 2);
  EXPECT_EQ(starts, 1);
}

class LayerRealRoom : public testing::TestWithParam<const char*> {};

TEST_P(LayerRealRoom, SubmittedScanMatchesAnalyzeAndTheCliExactly) {
  ROOMSENSE_REQUIRE_ROOM(path, GetParam());
  const roomsense::Scan scan = roomsense::scanio::is_quest_capture_path(path.string())
                                   ? roomsense::scanio::load_quest_capture(path.string()).mesh
                                   : roomsense::scanio::load_mesh_file(path.string());
  const Result got = analyse_submitted(scan);
  const roomsense::AnalysisResult want = roomsense::analyze(scan);
  ASSERT_TRUE(want.ok());
  expect_identical(got, want);
  expect_same_room_json(nlohmann::json::parse(got.json), run_cli(path.string()));
}

// The room through the simulated runtime and the layer's own scene query, against the CLI on the same file.
// Every scene extension the runtime serves: the layer takes the best (test_sources_rooms.cpp: one at a time).
const Headset kEverything{"every extension", std::nullopt, "XR_META_spatial_entity_mesh"};

void expect_runtime_matches_cli(const std::string& source, const std::optional<std::string>& chunk) {
  layertest::expect_runtime_matches_cli(source, chunk, kEverything);
}

TEST(LayerResults, RuntimeMeshesOfTheDefaultRoomMatchTheCliAsOneComponent) {
  expect_runtime_matches_cli("synthetic:default", "1000");
}

TEST(LayerResults, RuntimeMeshesOfTheDefaultRoomMatchTheCliInChunks) {
  expect_runtime_matches_cli("synthetic:default", std::nullopt);
}

TEST_P(LayerRealRoom, RuntimeMeshesMatchTheCliAsOneComponent) {
  ROOMSENSE_REQUIRE_ROOM(path, GetParam());
  expect_runtime_matches_cli(path.string(), "1000");
}

TEST_P(LayerRealRoom, RuntimeMeshesMatchTheCliInChunks) {
  ROOMSENSE_REQUIRE_ROOM(path, GetParam());
  expect_runtime_matches_cli(path.string(), std::nullopt);
}

INSTANTIATE_TEST_SUITE_P(Rooms, LayerRealRoom, testing::ValuesIn(kRealRooms));

}  // namespace
