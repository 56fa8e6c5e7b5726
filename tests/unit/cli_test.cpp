// `roomsense analyze` as a user runs it: exit codes, one clear stderr line on bad input, the JSON.
#include "roomsense/mruk_room.h"
#include "roomsense/analysis.h"
#include "roomsense/bounds.h"
#include "roomsense/scanio.h"
#include "roomsense/queries.h"
#include "roomsense/synthetic.h"
#include "rooms.h"
#include "sanitizers.h"
#include "test_process.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct CliRun {
  int status = -1;
  std::string err;
  std::string out;
};

using roomsense::test::temp_path;

// `shell_prefix` runs first in the same shell, e.g. a ulimit.
CliRun run_cli(const std::string& args, const std::string& shell_prefix = "") {
  const std::string err_path = temp_path("cli_stderr.txt"), out_path = temp_path("cli_stdout.txt");
  CliRun r;
  r.status = roomsense::test::run_program(ROOMSENSE_CLI, args, err_path, shell_prefix, out_path);
  std::ifstream err(err_path), out(out_path);
  r.err.assign(std::istreambuf_iterator<char>(err), {});
  r.out.assign(std::istreambuf_iterator<char>(out), {});
  return r;
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path) << text;
  return path;
}

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(Cli, AnalyzesTheBuiltInRoomIntoJsonAndBounds) {
  const std::string json = temp_path("default.json"), glb = temp_path("default.glb");
  const CliRun r = run_cli("analyze synthetic:default --json " + json + " --bounds " + glb);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(json);
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["status"], "ok");
  EXPECT_NEAR(doc["ceiling_y"].get<double>() - doc["floor_y"].get<double>(), 2.6, 0.05);
  std::ifstream bounds(glb, std::ios::binary);
  char magic[4] = {};
  bounds.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "glTF");
}

// Issue 15: --room-bounds writes one closed mesh per room of the JSON, each around its own room.
TEST(Cli, WritesEachRoomsBoundsOfTheFlat) {
  const std::string json = temp_path("flat.json"), dir = temp_path("flat_rooms");
  std::filesystem::remove_all(dir);
  const CliRun r = run_cli("analyze synthetic:flat --json " + json + " --room-bounds " + dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(json);
  const auto doc = nlohmann::json::parse(in);
  ASSERT_EQ(doc["rooms"].size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string obj = dir + "/room_" + std::to_string(k) + ".obj";
    const roomsense::Scan mesh = roomsense::scanio::load_mesh_file(obj);
    EXPECT_EQ(mesh.indices.size() / 3, doc["rooms"][k]["bounds"]["triangles"].get<std::size_t>()) << obj;
    EXPECT_TRUE(doc["rooms"][k]["bounds"]["closed"].get<bool>());
    EXPECT_TRUE(roomsense::check_closure(roomsense::BoundsMesh{mesh.vertices, mesh.indices}).closed()) << obj;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/room_3.obj"));
  std::filesystem::remove_all(dir);
}

// Issue 15: the summary has a line per room, numbered as the JSON's rooms, with its areas by type.
TEST(Cli, SummarisesEachRoomOfTheFlat) {
  const CliRun r = run_cli("analyze synthetic:flat");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("rooms     3 (split at passages up to 1.20 m wide"), std::string::npos) << r.out;
  for (const char* room : {"room 0 ", "room 1 ", "room 2 "}) {
    const std::size_t at = r.out.find(room);
    ASSERT_NE(at, std::string::npos) << room << " missing:\n" << r.out;
    const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
    EXPECT_NE(line.find(" wall, "), std::string::npos) << line;
    EXPECT_NE(line.find(" furniture areas"), std::string::npos) << line;
  }
}

TEST(Cli, BadInputGetsOneClearLineAndAnErrorStatus) {
  const std::string nan_obj = write_file("nan.obj", "v nan 0 0\nv 0 nan 0\nv 0 0 nan\nf 1 2 3\n");
  const std::string empty_obj = write_file("empty.obj", "");
  const std::string garbage = write_file("garbage.ply", "this is not a ply file\n");
  const std::string flat = write_file("flat.obj", "v 0 0 0\nv 4 0 0\nv 4 0 4\nv 0 0 4\nf 1 3 2\nf 1 4 3\n");
  // A header that claims a billion vertices in a tiny file: refused before anything is allocated for them.
  const std::string huge = write_file("huge.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\n"
                                                  "property float y\nproperty float z\nend_header\n0 0 0\n");
  const std::string bad_index = write_file("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  for (const std::string& args : std::vector<std::string>{"analyze /no/such/file.obj", "analyze " + nan_obj, "analyze " + empty_obj,
                                  "analyze " + garbage, "analyze " + flat, "analyze " + huge, "analyze " + bad_index, "analyze synthetic:nope"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("roomsense analyze: "), std::string::npos) << r.err;
  }
}

TEST(Cli, BadUsageGetsStatus2) {
  for (const char* args : {"", "frobnicate", "analyze", "analyze a.obj --up w", "analyze a.obj --voxel x",
                           "analyze a.obj --threads -1", "analyze a.obj b.obj", "analyze a.obj --json",
                           "analyze synthetic:default --voxel 0", "analyze synthetic:default --voxel 1e9",
                           "analyze synthetic:default --voxel nan", "analyze synthetic:default --voxel 1e999",
                           "analyze synthetic:default --min-plateau -1"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  }
  EXPECT_EQ(run_cli("--help").status, 0);
  EXPECT_EQ(run_cli("analyze --help").status, 0);
}

// Issue 18: PLY files that crashed assimp (SIGSEGV, SIGABRT) or went unreported exit 1 with one line naming
// the face and the index.
TEST(Cli, MalformedPlyFilesGetOneLineAndStatus1) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string five = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {header + "3 0 1 -1\n", "face 0 refers to vertex -1, but the file has 3 vertices"},
      {header + "3 0 1 100000000\n", "face 0 refers to vertex 100000000, but the file has 3 vertices"},
      {header + "3 0 1 5\n", "face 0 refers to vertex 5, but the file has 3 vertices"},
      {header + "0\n", "no floor and ceiling"},  // a face of no vertices is skipped: three points remain
      {five, "declares more data"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string path = write_file("malformed" + std::to_string(i) + ".ply", cases[i].first);
    const CliRun r = run_cli("analyze " + path);
    EXPECT_EQ(r.status, 1) << path << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(cases[i].second), std::string::npos) << r.err;
    if (i != 3) {
      EXPECT_EQ(r.err.rfind("roomsense analyze: cannot read '" + path + "': ", 0), 0u) << r.err;
    }
  }
}

TEST(Cli, SaysWhatAScanPathIsWhenItIsNoFile) {
  const std::string fifo = temp_path("scan.fifo");
  std::remove(fifo.c_str());
  const std::string dir = roomsense::test::scratch_dir().string();
  std::vector<std::pair<std::string, std::string>> cases{
      {dir, "it is a directory"}, {"/no/such/room.ply", "no such file"}, {dir + "/room.json", "no such file"}};
  if (roomsense::test::kPosix) {
    ASSERT_TRUE(roomsense::test::make_fifo(fifo));
    cases.insert(cases.end(), {{fifo, "it is not a regular file (a FIFO)"},
                               {"/dev/zero", "it is not a regular file (a character device)"}});
  }
  for (const auto& [path, what] : cases) {
    const CliRun r = run_cli("analyze " + path);
    EXPECT_EQ(r.status, 1) << path;
    EXPECT_EQ(r.err, "roomsense analyze: cannot read '" + path + "': " + what + "\n");
  }
  std::remove(fifo.c_str());
}

// --voxel is checked with the options, before the scan is opened: here it would block on a FIFO forever.
TEST(Cli, VoxelOutOfRangeExits2BeforeReadingTheScan) {
  if (!roomsense::test::kPosix) GTEST_SKIP() << "needs a FIFO (POSIX)";
  const std::string fifo = temp_path("voxel.fifo");
  std::remove(fifo.c_str());
  ASSERT_TRUE(roomsense::test::make_fifo(fifo));
  const CliRun r = run_cli("analyze " + fifo + " --voxel 0.0001");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "roomsense analyze: --voxel takes a size from 0.01 to 1 m, not '0.0001' (see roomsense analyze --help)\n");
  std::remove(fifo.c_str());
}

// Huge spans print as %g, not as forty digits.
TEST(Cli, HugeNumbersArePrintedCompactly) {
  const std::string path = write_file("huge_span.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nv 0 0 1e30\nf 1 2 3\nf 1 3 4\n");
  const CliRun r = run_cli("analyze " + path);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(lines(r.err), 1);
  EXPECT_NE(r.err.find("the scan spans 1e+30 x 1e+30 x 1e+30 m, which needs 1e+93 voxels"), std::string::npos) << r.err;
  EXPECT_LT(r.err.size(), 160u) << r.err;
}

// A Quest capture bigger than the address space allows: one line and status 1, never an abort.
TEST(Cli, OutOfMemoryIsOneLineAndStatus1) {
#if ROOMSENSE_TEST_ASAN || ROOMSENSE_TEST_TSAN
  GTEST_SKIP() << "a sanitizer maps terabytes of shadow memory at start: no address-space limit fits it "
                  "(the Release build runs this test)";
#endif
  if (!roomsense::test::kPosix) GTEST_SKIP() << "needs ulimit -v (POSIX)";
  // 64 MiB of base64 vertices under a 150 MB address-space limit (enough to start the process and read small scans).
  const std::string path = temp_path("big_capture.json");
  {
    std::ofstream out(path);
    out << R"({"spatialEntities":[{"locatable_META":{"position":{},"orientation":{"w":1}},"triangleMesh_META":{"vertices":")";
    const std::string chunk(1 << 20, 'A');
    for (int i = 0; i < 64; ++i) out << chunk;
    out << R"(","indices":""}}]})";
  }
  const CliRun r = run_cli("analyze " + path, "ulimit -v 150000; ");
  std::remove(path.c_str());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("out of memory reading '" + path + "'"), std::string::npos) << r.err;
}

}  // namespace

namespace {

// Wall areas of an analysis JSON whose centre lies over the rectangle, within 0.3 m of its plane.
int wall_areas_over(const nlohmann::json& doc, const roomsense::scanio::OrientedRect& r) {
  int n = 0;
  for (const auto& a : doc["areas"]) {
    if (a["type"] != "wall") continue;
    const glm::vec3 c(a["center"][0].get<float>(), a["center"][1].get<float>(), a["center"][2].get<float>());
    const glm::vec3 l = glm::inverse(r.pose.orientation) * (c - r.pose.position);
    n += std::abs(l.x) < 0.5f * r.width && std::abs(l.y) < 0.5f * r.height && std::abs(l.z) < 0.3f ? 1 : 0;
  }
  return n;
}

}  // namespace

TEST(Cli, AnMrukRoomIsReadWithItsLabelsUnlessToldNot) {
  const std::string room = std::string(ROOMSENSE_MRUK_TEST_DATA) + "/room_4x3.json";
  const std::string labelled = temp_path("mruk_labels.json"), bare = temp_path("mruk_bare.json");
  ASSERT_EQ(run_cli("analyze " + room + " --json " + labelled).status, 0);
  ASSERT_EQ(run_cli("analyze " + room + " --no-labels --json " + bare).status, 0);
  const auto with = nlohmann::json::parse(std::ifstream(labelled)), without = nlohmann::json::parse(std::ifstream(bare));
  ASSERT_EQ(with["status"], "ok");
  ASSERT_EQ(without["status"], "ok");
  // The room's window frame is flush with its wall: only its label tells it apart.
  const roomsense::scanio::QuestCapture capture = roomsense::scanio::load_mruk_room(room);
  int windows = 0;
  for (const auto& plane : capture.planes)
    if (plane.label == "WINDOW_FRAME") {
      ++windows;
      EXPECT_EQ(wall_areas_over(with, roomsense::scanio::plane_rect(plane)), 0);
      EXPECT_GT(wall_areas_over(without, roomsense::scanio::plane_rect(plane)), 0);
    }
  EXPECT_EQ(windows, 1);
}

// `roomsense place`: the poses core's RoomQueries finds on the same room, as JSON and in plan.svg; what the room
// cannot hold exits 0 with the reason; bad usage exits 2.
nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(CliPlace, WritesCoresPlacementsAsJsonAndIntoThePlan) {
  const std::string json = temp_path("place.json"), report = temp_path("place_report");
  ASSERT_EQ(run_cli("place synthetic:default --size 0.6x0.4x0.05 --on wall --count 4 --seed 3 --json " + json +
                    " --report " + report).status, 0);
  const nlohmann::json doc = read_json(json);
  EXPECT_EQ(doc["schema"], "roomsense.placements/1");
  EXPECT_EQ(doc["shortfall"], "none");
  const roomsense::AnalysisResult analysis = roomsense::analyze(roomsense::synth::generate_builtin_source("synthetic:default"));
  roomsense::PlacementQuery q;
  q.size = {0.6f, 0.4f, 0.05f};
  q.surfaces = roomsense::kOnWall;
  q.max_count = 4;
  q.seed = 3;
  const roomsense::PlacementResult want = roomsense::RoomQueries(analysis).find_placements(q);
  ASSERT_EQ(doc["placements"].size(), want.placements.size());
  ASSERT_EQ(want.placements.size(), 4u);
  for (std::size_t i = 0; i < want.placements.size(); ++i) {
    EXPECT_EQ(doc["placements"][i]["surface"], "wall");
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(doc["placements"][i]["center"][k].get<float>(), want.placements[i].center[k], 1e-5f);
  }
  std::ifstream plan(report + "/plan.svg");
  const std::string svg((std::istreambuf_iterator<char>(plan)), {});
  std::size_t polygons = 0;
  for (std::size_t at = svg.find("class=\"placement\""); at != std::string::npos; at = svg.find("class=\"placement\"", at + 1))
    ++polygons;
  EXPECT_EQ(polygons, 4u);
}

TEST(CliPlace, ImpossibleQueriesAnswerAndBadUsageFails) {
  const std::string json = temp_path("place_none.json");
  ASSERT_EQ(run_cli("place synthetic:default --size 9x9x1 --on floor --json " + json).status, 0);
  const nlohmann::json doc = read_json(json);
  EXPECT_TRUE(doc["placements"].empty());
  EXPECT_EQ(doc["shortfall"], "no_space");
  EXPECT_FALSE(doc["reason"].get<std::string>().empty());
  for (const char* bad : {"place synthetic:default", "place synthetic:default --size 1x1", "place synthetic:default --size 1x1x1 --on sky",
                          "place synthetic:default --size 1x1x1 --count 0", "place synthetic:default --size 1x1x1 --near 1,2",
                          "place synthetic:default --size -1x1x1", "place synthetic:default --size 1x1x1 --clearance nan"}) {
    const CliRun r = run_cli(bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("roomsense place:"), std::string::npos) << r.err;
  }
  EXPECT_EQ(run_cli("place /nonexistent.obj --size 1x1x1").status, 1);
}

// The issue's acceptance check: three 30 cm cubes on the living room's tables.
TEST(CliPlace, ThreeCubesOnTheLivingRoomsFurniture) {
  ROOMSENSE_REQUIRE_ROOM(room, "quest-iwer/living_room.json");
  const std::string json = temp_path("place_living.json"), report = temp_path("place_living");
  ASSERT_EQ(run_cli("place " + room.string() + " --size 0.3x0.3x0.3 --on furniture --count 3 --json " + json +
                    " --report " + report).status, 0);
  const nlohmann::json doc = read_json(json);
  ASSERT_EQ(doc["placements"].size(), 3u);
  for (const auto& p : doc["placements"]) {
    EXPECT_EQ(p["surface"], "furniture");
    const float y = p["center"][1].get<float>();  // the capture's floor is at about 0
    EXPECT_GT(y, 0.3f);
    EXPECT_LT(y, 1.3f);
  }
  std::ifstream plan(report + "/plan.svg");
  const std::string svg((std::istreambuf_iterator<char>(plan)), {});
  EXPECT_NE(svg.find("data-index=\"2\" data-surface=\"furniture\""), std::string::npos);
}
