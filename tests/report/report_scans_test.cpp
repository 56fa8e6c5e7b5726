// `roomsense analyze SCAN --report DIR` on every real scan in ../shared/rooms: both files exist, the plan is
// well-formed XML with one element per area of the JSON, the scene passes the structural GLB check with a
// node per area. Skips without the scans, fails without them under CI=1 (tests/support/rooms.h).
#include "report_checks.h"
#include "rooms.h"
#include "test_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <sys/wait.h>

namespace roomsense {
namespace {

namespace fs = std::filesystem;

// Every scan of ../shared/rooms: the meshes (OBJ) and the Quest captures (.json).
constexpr const char* kScans[] = {
    "hololens1/holotoolkit_fake_spatial_mapping.obj",
    "hololens1/mrtk_example_spatial_mesh.obj",
    "hololens2-su/SU_Apartment_objects_by_kind.obj",
    "hololens2-su/SU_Apartment_world_mesh.obj",
    "hololens2-su/SU_Kitchen_objects_by_kind.obj",
    "hololens2-su/SU_Kitchen_world_mesh.obj",
    "quest-iwer/living_room.json",
    "quest-iwer/living_room_global_mesh.obj",
    "quest-iwer/meeting_room.json",
    "quest-iwer/meeting_room_global_mesh.obj",
    "quest-iwer/music_room.json",
    "quest-iwer/music_room_global_mesh.obj",
    "quest-iwer/office_large.json",
    "quest-iwer/office_large_global_mesh.obj",
    "quest-iwer/office_small.json",
    "quest-iwer/office_small_global_mesh.obj",
};

std::string temp_path(const std::string& name) {
  return test::temp_path("report_scan_" + name);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class ReportOfScan : public testing::TestWithParam<const char*> {};

TEST_P(ReportOfScan, HasBothFilesWithOneElementAndOneNodePerArea) {
  ROOMSENSE_REQUIRE_ROOM(scan, GetParam());
  const std::string dir = temp_path("out"), json = dir + "/analysis.json";
  fs::remove_all(dir);
  const std::string cmd = std::string(ROOMSENSE_CLI) + " analyze '" + scan.string() + "' --json '" + json +
                          "' --report '" + dir + "' 2>'" + temp_path("stderr.txt") + "'";
  const int raw = std::system(cmd.c_str());
  const std::string err = read_text(temp_path("stderr.txt"));
  fs::remove(temp_path("stderr.txt"));
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << err;
  const nlohmann::json analysis = nlohmann::json::parse(read_text(json));
  const std::size_t areas = analysis["areas"].size();

  ASSERT_TRUE(fs::is_regular_file(dir + "/plan.svg"));
  const test::SvgReading svg = test::read_svg(read_text(dir + "/plan.svg"));
  ASSERT_TRUE(svg.well_formed) << svg.error;
  // One drawing per storey (ids of storey N from 2 end in -storeyN), one element per area, one border per room.
  ASSERT_EQ(svg.areas.size(), areas);
  for (const test::SvgArea& e : svg.areas) {
    const auto& a = analysis["areas"][std::stoul(e.index)];
    EXPECT_EQ(e.type, a["type"].get<std::string>());
    EXPECT_EQ(e.reach, a["interaction"].get<std::string>());
    EXPECT_EQ(test::dominant_channel(e.fill), test::expected_channel(e.reach));
  }
  const std::string plan = read_text(dir + "/plan.svg");
  for (std::size_t i = 0; i < analysis["storeys"].size(); ++i) {
    const std::string suffix = i == 0 ? "" : "-storey" + std::to_string(i + 1);
    EXPECT_TRUE(svg.ids.count("room" + suffix)) << "no drawing of storey " << i + 1;
    EXPECT_TRUE(svg.ids.count("wall-columns" + suffix)) << "storey " << i + 1;
  }
  std::size_t borders = 0;
  for (std::size_t at = plan.find("class=\"room-outline\""); at != std::string::npos;
       at = plan.find("class=\"room-outline\"", at + 1))
    ++borders;
  EXPECT_EQ(borders, analysis["rooms"].size());
  EXPECT_TRUE(svg.ids.count("wall-columns"));

  ASSERT_TRUE(fs::is_regular_file(dir + "/scene.glb"));
  const test::GlbReading glb = test::check_glb(test::read_bytes(dir + "/scene.glb"));
  for (const std::string& p : glb.problems) ADD_FAILURE() << p;
  ASSERT_EQ(glb.node_names.size(), areas + 2 + analysis["rooms"].size());
  EXPECT_EQ(glb.node_names[0], "scan");
  EXPECT_EQ(glb.node_names[1], "bounds");
  std::printf("[ report   ] %s: %zu areas, plan %zu bytes, scene %zu bytes\n", GetParam(), areas,
              std::size_t(fs::file_size(dir + "/plan.svg")), std::size_t(fs::file_size(dir + "/scene.glb")));
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Rooms, ReportOfScan, testing::ValuesIn(kScans), [](const auto& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

TEST(ReportOfScans, TheListHoldsEveryScanInTheFolder) {
  ROOMSENSE_REQUIRE_ROOM(rooms, ".");
  const std::set<std::string> listed(std::begin(kScans), std::end(kScans));
  for (const auto& entry : fs::recursive_directory_iterator(rooms)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".obj" && ext != ".json")) continue;
    const std::string relative = fs::relative(entry.path(), rooms).generic_string();
    EXPECT_TRUE(listed.count(relative)) << relative << " is a scan without a report test";
  }
}

}  // namespace
}  // namespace roomsense
