// A room being scanned (ROOMSENSE_SIM_SCAN_SECONDS): the simulated runtime shows the room's chunks over time,
// nearest the head first, each first coarse and later whole, as a headset meshing the room while its user looks
// around. Through the layer, on each live-meshing headset: computes follow the scan (the room's triangles only
// grow), the source reads only the chunks that appeared or changed since its last query, and once the scan is done
// the room equals that of an instance served the whole room at once.
#include "compare.h"
#include "layer_log.h"
#include "passive_capture.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>

namespace {

using namespace layertest;

constexpr double kScanSeconds = 1.5;

class LayerScan : public testing::TestWithParam<Headset> {};

TEST_P(LayerScan, ComputesFollowTheScanReadOnlyWhatChangedAndEndWithTheWholeRoom) {
  const Headset& headset = GetParam();
  const LayerLog log(std::string("scan-") + headset.name);
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", headset.extensions);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  std::vector<std::size_t> triangles;  // of each compute that found a room
  std::string scanned_json;
  {
    ScopedEnv scan("ROOMSENSE_SIM_SCAN_SECONDS", std::to_string(kScanSeconds));
    App app;
    // Taken after the instance's creation, where the scan starts once the room is loaded (which under sanitizers on
    // a busy machine takes a while): the loop then ends after the scan does.
    const auto start = std::chrono::steady_clock::now();
    const XrRoomAnalyzerEXTX a = app.analyzer();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    while (elapsed() < kScanSeconds + 0.05) {
      // Early on, too little is scanned for a room: such a compute fails, and the next goes on.
      if (app.compute(a, true) == XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) {
        const nlohmann::json doc = nlohmann::json::parse(read_result(app.extx, a).json);
        if (doc.at("status") == "ok") triangles.push_back(doc.at("input").at("triangles").get<std::size_t>());
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // The scan is done: one compute takes in its last changes, if the loop's last compute began before them; the
    // next finds nothing changed.
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    scanned_json = read_result(app.extx, a).json;
  }
  ASSERT_GE(triangles.size(), 3u);
  for (std::size_t i = 1; i < triangles.size(); ++i) EXPECT_LE(triangles[i - 1], triangles[i]) << "compute " << i;
  EXPECT_GE(std::set<std::size_t>(triangles.begin(), triangles.end()).size(), 3u) << "the computes saw the scan grow";
  const std::size_t whole = nlohmann::json::parse(scanned_json).at("input").at("triangles").get<std::size_t>();
  EXPECT_LT(triangles.front(), whole);

  // While the scan went on, queries found chunks they had served and read only the others.
  const std::vector<QueryCount> counts = log.query_counts();
  ASSERT_GE(counts.size(), triangles.size());
  std::size_t partly_read = 0;
  for (const QueryCount& c : counts) partly_read += c.read > 0 && c.read < c.chunks ? 1 : 0;
  EXPECT_GE(partly_read, 2u) << "no query kept chunks it had served while others changed";
  EXPECT_EQ(counts.back().read, 0u) << "the last query, after the scan, read chunks again";

  // The room scanned piece by piece equals the room served whole.
  std::string whole_json;
  {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    whole_json = read_result(app.extx, a).json;
  }
  expect_same_room_json(nlohmann::json::parse(scanned_json), nlohmann::json::parse(whole_json));
}

// The headsets that mesh the room live; Quest serves the scene captured beforehand, and planes are no meshes.
const Headset kLiveMeshingHeadsets[] = {
    {"HoloLens_2", std::string("XR_MSFT_scene_understanding"), "XR_MSFT_scene_understanding"},
    {"Android_XR", std::string("XR_ANDROID_scene_meshing"), "XR_ANDROID_scene_meshing", true},
    {"Magic_Leap_2", std::string("XR_ML_world_mesh_detection"), "XR_ML_world_mesh_detection"},
};
INSTANTIATE_TEST_SUITE_P(Headsets, LayerScan, testing::ValuesIn(kLiveMeshingHeadsets),
                         [](const testing::TestParamInfo<Headset>& info) { return std::string(info.param.name); });

}  // namespace
