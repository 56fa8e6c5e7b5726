// Each mesh source alone, on every room: the simulated runtime plays one headset at a time
// (ROOMSENSE_SIM_EXTENSIONS), and the layer's room through that headset's scene extension equals
// `roomsense analyze` of the same file (within 1e-4 m, test_results.cpp says why). Android XR's per-vertex labels
// (the simulated runtime derives them from a capture's objects or the triangles' normals) change its areas, so
// there only the rest must match. Prints each capture's time.
#include "compare.h"
#include "rooms.h"

#include <gtest/gtest.h>

#include <cctype>
#include <tuple>

namespace {

using namespace layertest;

const Headset kHeadsets[] = {
    {"HoloLens 2", std::string("XR_MSFT_scene_understanding"), "XR_MSFT_scene_understanding"},
    {"Quest 3", std::string("XR_META_spatial_entity_mesh"), "XR_META_spatial_entity_mesh"},
    {"Android XR", std::string("XR_ANDROID_scene_meshing"), "XR_ANDROID_scene_meshing", true},
    {"Magic Leap 2", std::string("XR_ML_world_mesh_detection"), "XR_ML_world_mesh_detection"},
};

class LayerSourceRoom : public testing::TestWithParam<std::tuple<Headset, const char*>> {};

TEST_P(LayerSourceRoom, MatchesTheCli) {
  const auto& [headset, room] = GetParam();
  ROOMSENSE_REQUIRE_ROOM(path, room);
  EXPECT_GT(expect_runtime_matches_cli(path.string(), std::nullopt, headset), 0u);
}

TEST(LayerSourceDefaultRoom, EveryHeadsetMatchesTheCli) {
  for (const Headset& headset : kHeadsets) {
    EXPECT_GT(expect_runtime_matches_cli("synthetic:default", std::nullopt, headset), 0u) << headset.name;
    expect_runtime_matches_cli("synthetic:default", std::string("1.0"), headset);  // many small chunks
  }
}

std::string name_of(const testing::TestParamInfo<LayerSourceRoom::ParamType>& info) {
  std::string name = std::string(std::get<0>(info.param).mesh_source) + "_" + std::get<1>(info.param);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Rooms, LayerSourceRoom, testing::Combine(testing::ValuesIn(kHeadsets), testing::ValuesIn(kRealRooms)),
                         name_of);

}  // namespace
