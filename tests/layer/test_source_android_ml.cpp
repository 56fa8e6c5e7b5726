// The XR_ANDROID_scene_meshing and XR_ML_world_mesh_detection sources, each on a simulated headset that serves
// only that scene extension (ROOMSENSE_SIM_EXTENSIONS): the layer's room on the built-in room and on every
// room of ../shared/rooms equals `roomsense analyze` of the same file (within 1e-4 m, test_results.cpp says
// why), and analysis.json names the source.
#include "compare.h"
#include "rooms.h"

#include <gtest/gtest.h>

#include <cctype>
#include <tuple>

namespace {

using namespace layertest;

const Headset kHeadsets[] = {
    {"Android XR", std::string("XR_ANDROID_scene_meshing"), "XR_ANDROID_scene_meshing"},
};

class LayerSourceAndroidMl : public testing::TestWithParam<std::tuple<Headset, const char*>> {};

TEST_P(LayerSourceAndroidMl, MatchesTheCli) {
  const auto& [headset, room] = GetParam();
  ROOMSENSE_REQUIRE_ROOM(path, room);
  EXPECT_GT(expect_runtime_matches_cli(path.string(), std::nullopt, headset), 0u);
}

TEST(LayerSourceAndroidMlDefaultRoom, MatchesTheCli) {
  for (const Headset& headset : kHeadsets) {
    EXPECT_GT(expect_runtime_matches_cli("synthetic:default", std::nullopt, headset), 0u) << headset.name;
    expect_runtime_matches_cli("synthetic:default", std::string("1.0"), headset);  // many small chunks
  }
}

// The layer enabled the headset's extension below itself: an application that did not must not see its functions.
TEST(LayerSourceAndroidMlDefaultRoom, LayerEnabledFunctionsStayHidden) {
  const std::pair<const char*, std::vector<const char*>> hidden[] = {
      {"XR_ANDROID_scene_meshing", {"xrCreateSceneMeshingTrackerANDROID", "xrGetSubmeshDataANDROID"}},
  };
  for (const auto& [extension, functions] : hidden) {
    ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", std::string(extension));
    ScopedEnv scene("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
    App app;
    for (const char* name : functions) {
      PFN_xrVoidFunction f = nullptr;
      EXPECT_EQ(xrGetInstanceProcAddr(app.instance, name, &f), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
      EXPECT_EQ(f, nullptr) << name;
    }
  }
}

std::string name_of(const testing::TestParamInfo<LayerSourceAndroidMl::ParamType>& info) {
  std::string name = std::string(std::get<0>(info.param).mesh_source) + "_" + std::get<1>(info.param);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Rooms, LayerSourceAndroidMl, testing::Combine(testing::ValuesIn(kHeadsets), testing::ValuesIn(kRealRooms)),
                         name_of);

}  // namespace
