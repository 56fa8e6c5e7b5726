// A mesh source serves a chunk it served before, with the same change marker and placement, without reading it
// from the runtime again (layer/src/sources/served_chunks.h). On each headset the simulated runtime plays: a
// second compute reads nothing again, an analyzer in another base space reads everything again, and a result built
// on kept chunks equals that of an instance whose source read every chunk. ServedChunks itself is tested directly.
#include "../../layer/src/sources/served_chunks.h"
#include "compare.h"
#include "layer_log.h"
#include "passive_capture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using namespace layertest;
using roomsense::layer::ServedChunk;
using roomsense::layer::ServedChunks;
using roomsense::layer::SourceChunk;

// A 0.6 m box on the floor of synthetic:default, submitted by the application: the analysis's input changes while
// the runtime's chunks do not.
void submit_box(const App& app, XrRoomAnalyzerEXTX a) {
  const float x0 = 0.5f, x1 = 1.1f, y0 = 0.0f, y1 = 0.6f, z0 = 0.5f, z1 = 1.1f;
  const std::vector<XrVector3f> v = {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1},
                                     {x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1}};
  const std::vector<uint32_t> i = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                   1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
  app.submit(a, v, i);
}

class LayerServedChunks : public testing::TestWithParam<Headset> {};

TEST_P(LayerServedChunks, UnchangedChunksAreNotReadAgainAndGiveTheSameRoom) {
  const Headset& headset = GetParam();
  const LayerLog log(std::string("served-") + headset.name);
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", headset.extensions);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  std::string kept_json;
  {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    submit_box(app, a);
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);  // the runtime's chunks as they were
    kept_json = read_result(app.extx, a).json;
    // Another base space places every chunk elsewhere: each is read again.
    const XrRoomAnalyzerEXTX moved = app.analyzer(app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL, {{0, 0, 0, 1}, {0.25f, 0, 0}}));
    ASSERT_EQ(app.compute(moved, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
  }
  const std::vector<QueryCount> counts = log.query_counts();
  ASSERT_EQ(counts.size(), 3u) << "one log line per query in " << log.path();
  EXPECT_GT(counts[0].chunks, 0u);
  EXPECT_EQ(counts[0].read, counts[0].chunks);
  EXPECT_EQ(counts[1].chunks, counts[0].chunks);
  EXPECT_EQ(counts[1].read, 0u) << "unchanged chunks were read again";
  EXPECT_EQ(counts[2].chunks, counts[0].chunks);
  EXPECT_EQ(counts[2].read, counts[2].chunks) << "chunks placed elsewhere were served as before";

  // A new instance's source has served nothing yet: it reads every chunk, and the room is the same.
  std::string fresh_json;
  {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    submit_box(app, a);
    ASSERT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX);
    fresh_json = read_result(app.extx, a).json;
  }
  expect_same_room_json(nlohmann::json::parse(kept_json), nlohmann::json::parse(fresh_json));
}

const Headset kServingHeadsets[] = {
    {"HoloLens_2", std::string("XR_MSFT_scene_understanding"), "XR_MSFT_scene_understanding"},
    {"Quest_3", std::string("XR_META_spatial_entity_mesh"), "XR_META_spatial_entity_mesh"},
    {"Android_XR", std::string("XR_ANDROID_scene_meshing"), "XR_ANDROID_scene_meshing", true},
    {"Magic_Leap_2", std::string("XR_ML_world_mesh_detection"), "XR_ML_world_mesh_detection"},
    {"planes_only", std::string("XR_EXT_spatial_plane_tracking"), "XR_EXT_spatial_plane_tracking", true},
};
INSTANTIATE_TEST_SUITE_P(Headsets, LayerServedChunks, testing::ValuesIn(kServingHeadsets),
                         [](const testing::TestParamInfo<Headset>& info) { return std::string(info.param.name); });

ServedChunk chunk(const std::string& id, std::uint64_t change, XrPosef placed) {
  SourceChunk c;
  c.id = id;
  c.change = change;
  c.placed = placed;
  return std::make_shared<const SourceChunk>(std::move(c));
}

TEST(ServedChunks, FindsAChunkOnlyWithItsChangeMarkerPlacementAndSession) {
  const XrSession s1 = reinterpret_cast<XrSession>(std::uintptr_t{1}), s2 = reinterpret_cast<XrSession>(std::uintptr_t{2});
  const XrPosef here{{0, 0, 0, 1}, {1, 2, 3}};
  XrPosef turned = here;
  turned.orientation = {0, 0.70710678f, 0, 0.70710678f};
  XrPosef nudged = here;
  nudged.position.x = std::nextafter(1.0f, 2.0f);
  ServedChunks served;
  EXPECT_EQ(served.find(s1, "a", 7, here), nullptr);  // nothing served yet
  const ServedChunk a = chunk("a", 7, here), b = chunk("b", 8, here);
  served.keep(s1, {a, b});
  EXPECT_EQ(served.find(s1, "a", 7, here), a);
  EXPECT_EQ(served.find(s1, "b", 8, here), b);
  EXPECT_EQ(served.find(s1, "a", 8, here), nullptr);     // the runtime changed it
  EXPECT_EQ(served.find(s1, "a", 7, turned), nullptr);   // placed otherwise
  EXPECT_EQ(served.find(s1, "a", 7, nudged), nullptr);   // by one float step
  EXPECT_EQ(served.find(s2, "a", 7, here), nullptr);     // another session
  EXPECT_EQ(served.find(s1, "c", 7, here), nullptr);     // never served

  served.keep(s1, {b});  // a query that served only b: a is forgotten, and no longer held
  EXPECT_EQ(served.find(s1, "a", 7, here), nullptr);
  EXPECT_EQ(served.find(s1, "b", 8, here), b);
  EXPECT_EQ(a.use_count(), 1);

  served.forget(s2);  // another session's end leaves s1's chunks
  EXPECT_EQ(served.find(s1, "b", 8, here), b);
  served.forget(s1);
  EXPECT_EQ(served.find(s1, "b", 8, here), nullptr);
  EXPECT_EQ(b.use_count(), 1);
}

}  // namespace
