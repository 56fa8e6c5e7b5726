// Lifetimes and threads: getters on several threads while a compute runs, instances destroyed and created
// again, sessions and analyzers destroyed while an analysis runs, and the capture of the meshes an
// application reads (with the extension, and without it through ROOMSENSE_EXPORT_DIR).
#include "compare.h"
#include "passive_capture.h"
#include "layer_harness.h"
#include "synthetic_room.h"
#include "roomsense/synthetic.h"
#include "test_process.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>

namespace {

using namespace layertest;

TEST(LayerLifecycle, GettersOnSeveralThreadsWhileAComputeRuns) {
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  const Room room("synthetic:thesis-room1");  // about 78k vertices: the compute takes a while
  app.submit(a, room.vertices, room.indices);

  std::atomic<bool> done{false};
  std::atomic<int> results{0}, early{0}, failures{0};
  auto reader = [&] {
    while (!done.load()) {
      XrRoomComputeStateEXTX state;
      if (app.extx.state(a, &state) != XR_SUCCESS) ++failures;
      XrRoomLayoutEXTX layout{XR_TYPE_ROOM_LAYOUT_EXTX, nullptr};
      const XrResult r = app.extx.layout(a, &layout);
      if (r == XR_ERROR_CALL_ORDER_INVALID) {
        ++early;
        continue;
      }
      if (r != XR_SUCCESS) {
        ++failures;
        continue;
      }
      uint32_t count = 0;
      if (app.extx.areas(a, 0, &count, nullptr) != XR_SUCCESS) ++failures;
      std::vector<XrRoomAreaEXTX> areas(count, {XR_TYPE_ROOM_AREA_EXTX, nullptr});
      // Every compute here analyses the same meshes, so the count cannot change between the two calls.
      if (app.extx.areas(a, count, &count, areas.data()) != XR_SUCCESS) ++failures;
      XrRoomBoundsMeshEXTX bounds{XR_TYPE_ROOM_BOUNDS_MESH_EXTX, nullptr};
      if (app.extx.bounds(a, &bounds) != XR_SUCCESS) ++failures;
      std::vector<XrVector3f> v(bounds.vertexCountOutput);
      bounds.vertexCapacityInput = static_cast<uint32_t>(v.size());
      bounds.vertices = v.data();
      if (app.extx.bounds(a, &bounds) != XR_SUCCESS) ++failures;
      ++results;
    }
  };
  std::vector<std::thread> readers;
  for (int i = 0; i < 4; ++i) readers.emplace_back(reader);
  EXPECT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  EXPECT_EQ(app.compute(a, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);  // readers see the old result meanwhile
  done = true;
  for (auto& t : readers) t.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_GT(results.load(), 0);
  std::printf("[ figures  ] %d reads before the first result, %d full reads\n", early.load(), results.load());
}

// One worker thread serves every compute of an analyzer, from the first until the analyzer ends: an application
// that computes every few frames starts no thread each time. The process's threads are read right after each
// compute starts (a compute over changed meshes analyses for a millisecond and more, so a thread of its own would
// still be running): after the first, no compute brings a thread the first did not have (it starts the worker,
// and the analysis its own threads, kept too).
TEST(LayerLifecycle, AnAnalyzersComputesShareOneThread) {
  if (!roomsense::test::kThreadsListed) GTEST_SKIP() << "reads the process's threads from /proc/self/task";
  const auto threads = roomsense::test::process_threads;
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  const Room room("synthetic:thesis-room1");
  app.submit(a, room.vertices, room.indices);
  app.start(a, false);
  std::set<std::string> first = threads();
  ASSERT_EQ(app.wait(a), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  first.merge(threads());
  for (int round = 0; round < 5; ++round) {
    const float x = -1.0f + 0.3f * float(round);  // a standing 0.2 m square: the meshes changed, an analysis runs
    app.submit(a, {{x, 1.0f, 0.5f}, {x + 0.2f, 1.0f, 0.5f}, {x + 0.2f, 1.2f, 0.5f}, {x, 1.2f, 0.5f}}, {0, 2, 1, 0, 3, 2});
    app.start(a, false);
    const std::set<std::string> now = threads();
    ASSERT_EQ(app.wait(a), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) << "round " << round;
    for (const std::string& id : now) EXPECT_EQ(first.count(id), 1u) << "round " << round << ": thread " << id << " is new";
  }
}

TEST(LayerLifecycle, InstanceDestroyedAndCreatedAgain) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  std::size_t areas = 0;
  for (int round = 0; round < 3; ++round) {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) << "round " << round;
    const Result r = read_result(app.extx, a);
    if (round > 0) {
      EXPECT_EQ(r.areas.size(), areas);
    }
    areas = r.areas.size();
    if (round == 1) app.start(a, true);  // this instance goes while an analysis runs
  }
  EXPECT_GT(areas, 0u);
}

TEST(LayerLifecycle, SessionDestroyedWhileTheRuntimeIsQueried) {
  ScopedEnv delay("ROOMSENSE_SIM_COMPUTE_DELAY_MS", std::string("2000"));
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  app.start(a, true);
  const auto start = std::chrono::steady_clock::now();
  app.close_session();  // the layer's scene query is still waiting for the runtime
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(1500)) << "the query was not cancelled";
  XrRoomComputeStateEXTX state;
  EXPECT_EQ(app.extx.state(a, &state), XR_ERROR_HANDLE_INVALID);
  // The instance carries on with a new session.
  ScopedEnv quick("ROOMSENSE_SIM_COMPUTE_DELAY_MS", std::string("5"));
  app.open_session();
  const XrRoomAnalyzerEXTX b = app.analyzer();
  const Room room("synthetic:default");
  app.submit(b, room.vertices, room.indices);
  EXPECT_EQ(app.compute(b, false), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
}

TEST(LayerLifecycle, SessionDestroyedWhileThePipelineRuns) {
  App app;
  const Room room("synthetic:thesis-room1");
  for (int round = 0; round < 3; ++round) {
    const XrRoomAnalyzerEXTX a = app.analyzer();
    app.submit(a, room.vertices, room.indices);
    app.start(a, false);
    std::this_thread::sleep_for(std::chrono::milliseconds(5 * round));
    app.close_session();
    XrRoomComputeStateEXTX state;
    EXPECT_EQ(app.extx.state(a, &state), XR_ERROR_HANDLE_INVALID);
    app.open_session();
  }
}

TEST(LayerLifecycle, AnalyzerDestroyedWhileItComputes) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  for (int round = 0; round < 3; ++round) {
    const XrRoomAnalyzerEXTX a = app.analyzer();
    app.start(a, true);
    std::this_thread::sleep_for(std::chrono::milliseconds(10 * round));
    EXPECT_EQ(app.extx.destroy(a), XR_SUCCESS);
  }
  const XrRoomAnalyzerEXTX b = app.analyzer();
  EXPECT_EQ(app.compute(b, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
}

// An application that exits without destroying anything, its analyzer computing from the runtime's meshes and its
// application meshes: exit() ends the layer's statics (the analyzer's worker is stopped and joined) and the
// runtime's, in whatever order, and the process ends cleanly. Each round is a child process (a hang is killed
// after 60 s and fails), with a different delay into the compute.
TEST(LayerLifecycle, AProcessExitingMidComputeEndsCleanly) {
  if constexpr (!roomsense::test::kPosix) GTEST_SKIP() << "fork() is POSIX";
  const Room room("synthetic:thesis-room1");
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  for (int round = 0; round < 6; ++round) {
    const std::string ended = roomsense::test::exit_of_child(
        [&] {
          // Never destroyed: the application exits with everything open (a static keeps it reachable for LSan).
          static const App& app = *new App;
          const XrRoomAnalyzerEXTX a = app.analyzer();
          app.submit(a, room.vertices, room.indices);
          app.start(a, true);
          std::this_thread::sleep_for(std::chrono::milliseconds(4 * round));
        },
        std::chrono::seconds(60));
    EXPECT_EQ(ended, "") << "round " << round;
  }
}

// Whatever the pipeline is doing, destroying the analyzer, the session or the instance gives the app its
// thread back at once (issue 18: 100 ms; the bound here is a hang detector). The default room at 1.25 cm
// voxels keeps the pipeline busy for some 1.5 s here (at 2 cm, which issue 19 made faster, it ended some 0.44 s
// in: too near the 400 ms destroy).
TEST(LayerLifecycle, DestroyDuringASlowPipelineReturnsPromptly) {
  const Room room("synthetic:default");
  for (const int what : {0, 1, 2}) {  // analyzer, session, instance
    for (const int delay_ms : {20, 400}) {
      App app;
      const XrRoomAnalyzerEXTX a = app.analyzer(XR_NULL_HANDLE, 0.0125f);
      app.submit(a, room.vertices, room.indices);
      app.start(a, false);
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
      XrRoomComputeStateEXTX state;
      ASSERT_EQ(app.extx.state(a, &state), XR_SUCCESS);
      EXPECT_EQ(state, XR_ROOM_COMPUTE_STATE_RUNNING_EXTX) << "finished before the destroy: make it slower";
      const auto start = std::chrono::steady_clock::now();
      if (what == 0) {
        EXPECT_EQ(app.extx.destroy(a), XR_SUCCESS);
      } else if (what == 1) {
        app.close_session();
      } else {
        EXPECT_EQ(xrDestroyInstance(app.instance), XR_SUCCESS);
        app.instance = XR_NULL_HANDLE;
      }
      EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(3)) << what << " after " << delay_ms << " ms";
    }
  }
}

// The application reads the scene itself and then computes: the layer adds what it read, but not twice
// when its own query served the same meshes.
TEST(LayerLifecycle, MeshesTheApplicationReadAreNotCountedTwice) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App plain;
  const XrRoomAnalyzerEXTX p = plain.analyzer();
  ASSERT_EQ(plain.compute(p, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const Result want = read_result(plain.extx, p);
  xrDestroyInstance(plain.instance);
  plain.instance = XR_NULL_HANDLE;

  App app({XR_EXTX_ROOM_UNDERSTANDING_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME});
  EXPECT_GT(read_scene_meshes(app), 0u);
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const Result got = read_result(app.extx, a);
  const nlohmann::json doc = nlohmann::json::parse(got.json);
  EXPECT_GT(doc["openxr"]["runtime_meshes"].get<int>(), 0);
  EXPECT_EQ(doc["openxr"]["app_read_meshes"].get<int>(), 0) << "the application's meshes duplicate the layer's";
  EXPECT_EQ(got.layout.inputVertexCount, want.layout.inputVertexCount);
  EXPECT_EQ(got.areas.size(), want.areas.size());
  EXPECT_EQ(got.indices, want.indices);
}

// An application that never enables the extension but reads the scene meshes: with ROOMSENSE_EXPORT_DIR the
// layer analyses what it read (passive capture, placed with the components' poses) and exports the result.
TEST(LayerLifecycle, ExportDirAnalysesWhatAnApplicationWithoutTheExtensionRead) {
  const auto dir = temp_dir("layer_export_only");
  ScopedEnv export_dir("ROOMSENSE_EXPORT_DIR", dir.string());
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  std::size_t read = 0;
  {
    App app({XR_MND_HEADLESS_EXTENSION_NAME, XR_MSFT_SCENE_UNDERSTANDING_EXTENSION_NAME});
    read = read_scene_meshes(app);
    EXPECT_GT(read, 0u);
    // The analysis runs once the application is done with the scene, in the background; the session's end
    // waits for it.
    app.close_session();
    EXPECT_TRUE(std::filesystem::exists(dir / "analysis.json"));
    EXPECT_TRUE(std::filesystem::exists(dir / "bounds.obj"));
  }
  std::ifstream in(dir / "analysis.json");
  const nlohmann::json got = nlohmann::json::parse(in);
  EXPECT_EQ(got.at("schema"), "roomsense.analysis/1");
  EXPECT_EQ(got.at("openxr").at("app_read_meshes").get<std::size_t>(), read);
  EXPECT_EQ(got.at("openxr").at("runtime_meshes").get<int>(), 0);
  // What the application read is the whole room, so the result is the CLI's (within the components' rounding).
  const nlohmann::json cli = run_cli("synthetic:default");
  JsonDiff d;
  for (const char* member : kRoomMembers) {
    nlohmann::json g = room_member(got, member), w = room_member(cli, member);
    diff_json(g, w, member, d);
  }
  for (const std::string& m : d.mismatches) ADD_FAILURE() << m;
  EXPECT_LE(d.max_number_difference, 1e-4);
  std::filesystem::remove_all(dir);
}

TEST(LayerLifecycle, ExportDirAfterEachAnalysisWithTheExtension) {
  const auto dir = temp_dir("layer_export");
  ScopedEnv export_dir("ROOMSENSE_EXPORT_DIR", (dir / "nested").string());
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  const XrRoomAnalyzerEXTX a = app.analyzer();
  ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const Result r = read_result(app.extx, a);
  std::ifstream in(dir / "nested" / "analysis.json");
  ASSERT_TRUE(in.good());
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc.at("areas").size(), r.areas.size());
  EXPECT_EQ(doc, nlohmann::json::parse(r.json));
  std::ifstream obj(dir / "nested" / "bounds.obj");
  std::size_t faces = 0;
  for (std::string line; std::getline(obj, line);) faces += line.rfind("f ", 0) == 0;
  EXPECT_EQ(faces, r.indices.size() / 3);
  std::filesystem::remove_all(dir);
}

TEST(LayerLifecycle, ResultsAreInTheAnalyzersBaseSpace) {
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  App app;
  const XrRoomAnalyzerEXTX in_local = app.analyzer();
  ASSERT_EQ(app.compute(in_local, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const Result l = read_result(app.extx, in_local);
  // A LOCAL space 1 m higher: every height comes out 1 m lower.
  const XrSpace raised = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL, {{0, 0, 0, 1}, {0, 1, 0}});
  const XrRoomAnalyzerEXTX in_raised = app.analyzer(raised);
  ASSERT_EQ(xrDestroySpace(raised), XR_SUCCESS);  // the analyzer keeps its own copy
  ASSERT_EQ(app.compute(in_raised, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  const Result r = read_result(app.extx, in_raised);
  EXPECT_NEAR(r.layout.floorHeight, l.layout.floorHeight - 1.0f, 1e-4f);
  EXPECT_NEAR(r.layout.ceilingHeight, l.layout.ceilingHeight - 1.0f, 1e-4f);
  EXPECT_NEAR(r.layout.boundsMin.y, l.layout.boundsMin.y - 1.0f, 1e-4f);
}

}  // namespace
