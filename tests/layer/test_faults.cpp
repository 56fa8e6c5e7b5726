// A hostile runtime (ROOMSENSE_SIM_FAULTS, simruntime/README.md "Faults") against the layer, for each mesh source
// it applies to: the app's calls return, the compute ends COMPLETED (with the next source, or with the broken
// triangles dropped) or FAILED, the layer's log names the fault in exactly one line, nothing crashes. Bounds on
// time are hang detectors only.
#include "layer_harness.h"
#include "passive_capture.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace {

using namespace layertest;

struct Source {
  const char* extension;  // ROOMSENSE_SIM_EXTENSIONS, the fault's target and the source's name in the log
  const char* mesh_call;  // the call that delivers its meshes
};

const Source kSources[] = {
    {"XR_META_spatial_entity_mesh", "xrGetSpaceTriangleMeshMETA"},
    {"XR_MSFT_scene_understanding", "xrGetSceneMeshBuffersMSFT"},
    {"XR_ANDROID_scene_meshing", "xrGetSubmeshDataANDROID"},
    {"XR_ML_world_mesh_detection", "xrRequestWorldMeshCompleteML"},
    {"XR_EXT_spatial_plane_tracking", "xrQuerySpatialComponentDataEXT"},
};
constexpr const char* kPlanes = "XR_EXT_spatial_plane_tracking";  // the last source: the fallback of the others

constexpr auto kHang = std::chrono::seconds(30);  // far beyond any run here: only a hang gets there

struct Outcome {
  XrRoomComputeStateEXTX state = XR_ROOM_COMPUTE_STATE_NONE_EXTX;
  std::string source;  // analysis.json's openxr.mesh_source when COMPLETED
  std::vector<std::string> log;

  std::size_t lines_with(const std::string& text) const {
    return static_cast<std::size_t>(std::count_if(log.begin(), log.end(), [&](const std::string& l) { return l.find(text) != std::string::npos; }));
  }
  std::string all() const {
    std::string s;
    for (const std::string& l : log) s += l + "\n";
    return s;
  }
};

// One app: a session, an analyzer, one compute with the runtime's meshes, on the default room with `faults`.
// `after` runs with the app still open (the session lost test looks at events).
template <typename After>
Outcome run(const std::string& extensions, const std::string& faults, After&& after) {
  static int serial = 0;
  const std::filesystem::path dir = temp_dir("faults" + std::to_string(++serial));
  std::filesystem::create_directories(dir);
  const std::filesystem::path log = dir / "layer.log";
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", extensions);
  ScopedEnv fault("ROOMSENSE_SIM_FAULTS", faults);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv file("ROOMSENSE_LOG_FILE", log.string());
  ScopedEnv level("ROOMSENSE_LOG", std::string("warn"));
  ScopedEnv timeout("ROOMSENSE_RUNTIME_TIMEOUT_MS", std::string("300"));
  Outcome r;
  {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    const auto start = std::chrono::steady_clock::now();
    app.start(a, true);
    r.state = app.wait(a, kHang);
    EXPECT_LT(std::chrono::steady_clock::now() - start, kHang) << "the compute never ended";
    if (r.state == XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX)
      r.source = nlohmann::json::parse(read_result(app.extx, a).json).at("openxr").at("mesh_source").get<std::string>();
    after(app, a);
  }
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) r.log.push_back(line);
  return r;
}

Outcome run(const std::string& extensions, const std::string& faults) {
  return run(extensions, faults, [](App&, XrRoomAnalyzerEXTX) {});
}

// A fault of the source alone: FAILED, one line naming `what`; with the planes behind it: COMPLETED from them,
// the same one line.
void expect_fails_over(const Source& s, const std::string& faults, const std::string& what) {
  SCOPED_TRACE(std::string(s.extension) + " with ROOMSENSE_SIM_FAULTS=" + faults);
  const Outcome alone = run(s.extension, faults);
  EXPECT_EQ(alone.state, XR_ROOM_COMPUTE_STATE_FAILED_EXTX);
  EXPECT_EQ(alone.lines_with(what), 1u) << alone.all();
  EXPECT_EQ(alone.lines_with(std::string(s.extension) + " left out"), 1u) << alone.all();
  if (std::string(s.extension) == kPlanes) return;
  const Outcome fallback = run(std::string(s.extension) + "," + kPlanes, faults);
  EXPECT_EQ(fallback.state, XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) << fallback.all();
  EXPECT_EQ(fallback.source, kPlanes);
  EXPECT_EQ(fallback.lines_with(what), 1u) << fallback.all();
}

TEST(LayerFaults, AnErrorFromTheMeshCallFailsOverToTheNextSource) {
  for (const Source& s : kSources)
    expect_fails_over(s, std::string("error:") + s.mesh_call + "=XR_ERROR_RUNTIME_FAILURE",
                      std::string(s.mesh_call) + " failed (XR_ERROR_RUNTIME_FAILURE)");
}

TEST(LayerFaults, WorkThatNeverCompletesGivesUpAfterTheTimeout) {
  for (const Source& s : kSources) {
    SCOPED_TRACE(s.extension);
    const auto start = std::chrono::steady_clock::now();
    const Outcome r = run(s.extension, std::string("pending:") + s.extension);
    EXPECT_LT(std::chrono::steady_clock::now() - start, kHang);
    EXPECT_EQ(r.state, XR_ROOM_COMPUTE_STATE_FAILED_EXTX);
    EXPECT_EQ(r.lines_with(std::string(s.extension) + " left out"), 1u) << r.all();
    // Futures, the scene compute and the space query wait for the timeout; Android XR says it is not tracking.
    const bool android = std::string(s.extension) == "XR_ANDROID_scene_meshing";
    EXPECT_EQ(r.lines_with(android ? "not tracking yet" : "within 300 ms"), 1u) << r.all();
  }
  // With the planes behind it, the best source that never completes costs one timeout, then the planes deliver.
  const Outcome r = run(std::string("XR_ML_world_mesh_detection,") + kPlanes, "pending:XR_ML_world_mesh_detection");
  EXPECT_EQ(r.state, XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) << r.all();
  EXPECT_EQ(r.source, kPlanes);
}

TEST(LayerFaults, NanVerticesDropTheirTrianglesAndTheRestIsUsed) {
  for (const Source& s : kSources) {
    SCOPED_TRACE(s.extension);
    const Outcome r = run(s.extension, std::string("mesh:") + s.extension + "=nan");
    if (std::string(s.extension) != kPlanes) {  // planes lose whole quads; what is left may hold no room
      EXPECT_EQ(r.state, XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) << r.all();
    }
    EXPECT_NE(r.state, XR_ROOM_COMPUTE_STATE_RUNNING_EXTX);
    EXPECT_EQ(r.lines_with("with non-finite vertices"), 1u) << r.all();
  }
}

TEST(LayerFaults, EmptyMeshesFailOverToTheNextSource) {
  for (const Source& s : kSources) expect_fails_over(s, std::string("mesh:") + s.extension + "=empty", "no usable triangles");
}

TEST(LayerFaults, HugeCountsAreRefusedWithoutAllocatingThem) {
  for (const Source& s : kSources) expect_fails_over(s, std::string("mesh:") + s.extension + "=huge", "2147483648");
}

TEST(LayerFaults, RaggedIndexCountsAndIndicesOutOfRangeDropTheirTriangles) {
  for (const Source& s : kSources)
    for (const auto& [fault, line] : {std::pair{"ragged", "not a multiple of 3"}, std::pair{"range", "indices out of range"}}) {
      SCOPED_TRACE(std::string(s.extension) + " " + fault);
      const Outcome r = run(s.extension, std::string("mesh:") + s.extension + "=" + fault);
      EXPECT_EQ(r.state, XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) << r.all();
      EXPECT_EQ(r.source, s.extension);
      EXPECT_EQ(r.lines_with(line), 1u) << r.all();
    }
}

TEST(LayerFaults, ASessionLostMidQueryIsReportedOnceAndTheAppCanEndIt) {
  for (const Source& s : kSources) {
    SCOPED_TRACE(s.extension);
    // The planes behind it are not asked: the session is gone.
    const std::string extensions = std::string(s.extension) == kPlanes ? std::string(kPlanes) : std::string(s.extension) + "," + kPlanes;
    const Outcome r = run(extensions, std::string("lost:") + s.mesh_call, [](App& app, XrRoomAnalyzerEXTX a) {
      bool loss_pending = false;
      XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER, nullptr};
      for (int i = 0; i < 100 && !loss_pending && xrPollEvent(app.instance, &event) == XR_SUCCESS; ++i) {
        if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED)
          loss_pending = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state == XR_SESSION_STATE_LOSS_PENDING;
        event = {XR_TYPE_EVENT_DATA_BUFFER, nullptr};
      }
      EXPECT_TRUE(loss_pending);
      XrRoomComputeInfoEXTX info{XR_TYPE_ROOM_COMPUTE_INFO_EXTX, nullptr};
      info.time = now();
      info.includeRuntimeMeshes = XR_TRUE;
      EXPECT_EQ(app.extx.compute(a, &info), XR_ERROR_SESSION_LOST);
      EXPECT_EQ(xrDestroySession(app.session), XR_SUCCESS);  // what an app does on LOSS_PENDING
      app.session = XR_NULL_HANDLE;
    });
    EXPECT_EQ(r.state, XR_ROOM_COMPUTE_STATE_FAILED_EXTX);
    EXPECT_EQ(r.lines_with("XR_ERROR_SESSION_LOST"), 1u) << r.all();
  }
}

}  // namespace
