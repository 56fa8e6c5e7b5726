// The report (report.h): plan.svg is well-formed XML with one element per area in its reach colour, with and
// without voxel features; scene.glb passes a structural check, reads back through assimp and, where the
// Khronos glTF-Validator is installed, passes it; `roomsense analyze --report` writes both or fails clearly.
#include "report_checks.h"
#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "roomsense/queries.h"
#include "roomsense/report.h"
#include "roomsense/synthetic.h"
#include "test_process.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <sys/wait.h>

namespace roomsense {
namespace {

namespace fs = std::filesystem;

struct Room {
  Scan scan;
  AnalysisResult result;
};

const Room& default_room() {
  static const Room room = [] {
    Room r;
    r.scan = synth::generate(synth::default_room());
    r.result = analyze(r.scan);
    return r;
  }();
  return room;
}

// Per-process paths: ctest runs the tests of this binary in parallel processes.
std::string temp_path(const std::string& name) {
  return test::temp_path("report_" + name);
}

std::string expected_node_name(std::size_t i, const Area& a) {
  return "area " + std::to_string(i) + " " + std::string(to_string(a.type)) + " " + std::string(to_string(a.size)) +
         " " + std::string(to_string(a.reach));
}

// Every area exactly once, in the right reach colour, with the right data attributes and a title.
void expect_one_element_per_area(const test::SvgReading& svg, std::span<const Area> areas) {
  ASSERT_EQ(svg.areas.size(), areas.size());
  std::set<std::string> seen;
  for (const test::SvgArea& e : svg.areas) {
    ASSERT_TRUE(seen.insert(e.index).second) << "area " << e.index << " twice";
    const std::size_t i = std::stoul(e.index);
    ASSERT_LT(i, areas.size());
    const Area& a = areas[i];
    EXPECT_EQ(e.type, to_string(a.type));
    EXPECT_EQ(e.size, to_string(a.size));
    EXPECT_EQ(e.reach, to_string(a.reach));
    EXPECT_EQ(test::dominant_channel(e.fill), test::expected_channel(e.reach)) << e.fill << " for " << e.reach;
    EXPECT_NE(e.title.find("area " + e.index + ":"), std::string::npos) << e.title;
    // Four finite points.
    int points = 0;
    std::size_t at = 0;
    while (at < e.points.size()) {
      const std::size_t end = e.points.find(' ', at);
      const std::string pt = e.points.substr(at, end == std::string::npos ? std::string::npos : end - at);
      const std::size_t comma = pt.find(',');
      ASSERT_NE(comma, std::string::npos) << e.points;
      EXPECT_TRUE(std::isfinite(std::stod(pt.substr(0, comma))) && std::isfinite(std::stod(pt.substr(comma + 1))));
      ++points;
      if (end == std::string::npos) break;
      at = end + 1;
    }
    EXPECT_EQ(points, 4) << e.points;
  }
}

// One area of each type and reach, made as an app would from the layer's poses.
std::vector<Area> handmade_areas() {
  const glm::quat floor_pose = glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0));  // +Z to +Y
  const glm::quat ceiling_pose = glm::angleAxis(glm::radians(90.0f), glm::vec3(1, 0, 0));  // +Z to -Y
  const glm::quat wall_pose = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));     // +Z to +X
  return {
      area_from_pose(AreaType::Floor, AreaSize::Large, Reach::Close, {0, 0, 0}, floor_pose, 2, 2),
      area_from_pose(AreaType::Ceiling, AreaSize::Medium, Reach::Distance, {0, 2.6f, 0}, ceiling_pose, 1, 1),
      area_from_pose(AreaType::Wall, AreaSize::Small, Reach::None, {-2.4f, 1.5f, 0.5f}, wall_pose, 0.5f, 0.3f),
      area_from_pose(AreaType::Furniture, AreaSize::Small, Reach::Close, {1, 0.75f, 1}, floor_pose, 0.5f, 0.5f),
  };
}

TEST(Report, PlanIsWellFormedWithOneElementPerAreaInItsReachColour) {
  const Room& room = default_room();
  ASSERT_TRUE(room.result.ok());
  ASSERT_FALSE(room.result.areas.empty()) << "the area search returned nothing";
  const std::string text = plan_svg(report_input(room.result, room.scan, "synthetic:default"));
  const test::SvgReading svg = test::read_svg(text);
  ASSERT_TRUE(svg.well_formed) << svg.error;
  EXPECT_EQ(svg.root, "svg");
  expect_one_element_per_area(svg, room.result.areas);
  for (const char* id : {"footprint", "furniture-tops", "wall-columns", "wall-normals", "bounds-outline", "legend",
                         "scale-bar", "axes"})
    EXPECT_TRUE(svg.ids.count(id)) << id;
  EXPECT_FALSE(svg.path_data.at("wall-columns").empty());
  EXPECT_FALSE(svg.path_data.at("wall-normals").empty());
  EXPECT_FALSE(svg.path_data.at("bounds-outline").empty());
  // Every reach appears among the legend's labels, and the heights are printed.
  for (const char* s : {"close", "distance", "none", "floor y = 0.00 m", "ceiling y = 2.60 m"})
    EXPECT_NE(text.find(s), std::string::npos) << s;
}

TEST(Report, PlanFromWhatTheLayerGivesDrawsTheFootprintFromTheBounds) {
  const Room& room = default_room();
  // An app has the areas, the bounds, the heights and the meshes it submitted, but no voxel features.
  const std::vector<Area> areas = handmade_areas();
  ReportInput in;
  in.title = "app";
  in.floor_y = room.result.floor_y;
  in.ceiling_y = room.result.ceiling_y;
  in.areas = areas;
  in.bounds = &room.result.bounds;
  in.scan = std::span<const Scan>(&room.scan, 1);
  const std::string text = plan_svg(in);
  const test::SvgReading svg = test::read_svg(text);
  ASSERT_TRUE(svg.well_formed) << svg.error;
  expect_one_element_per_area(svg, areas);
  ASSERT_TRUE(svg.path_data.count("footprint"));
  EXPECT_FALSE(svg.path_data.at("footprint").empty());
  EXPECT_FALSE(svg.path_data.at("bounds-outline").empty());
  EXPECT_FALSE(svg.ids.count("wall-columns"));
  EXPECT_FALSE(svg.ids.count("wall-normals"));
}

TEST(Report, PlanSurvivesEmptyInputAndMarkupInTheTitle) {
  ReportInput in;
  in.title = "a<b>&\"c\"'d'\x01";
  const test::SvgReading empty = test::read_svg(plan_svg(in));
  ASSERT_TRUE(empty.well_formed) << empty.error;
  EXPECT_TRUE(empty.areas.empty());
  // Bad features (sizes that do not match the grid) are ignored rather than read out of bounds.
  GridSpec spec;
  spec.nx = spec.nz = 4;
  spec.ny = 3;
  RoomFeatures wrong;
  in.voxels = {&spec, &wrong, {}};
  const std::vector<Area> areas = handmade_areas();
  in.areas = areas;
  const test::SvgReading svg = test::read_svg(plan_svg(in));
  ASSERT_TRUE(svg.well_formed) << svg.error;
  expect_one_element_per_area(svg, areas);
  // An area with a reach outside the enum (an app can build any Area) is left out of both pictures.
  std::vector<Area> odd = areas;
  odd.push_back(areas[0]);
  odd.back().reach = static_cast<Reach>(0);
  in.areas = odd;
  EXPECT_EQ(test::read_svg(plan_svg(in)).areas.size(), areas.size());
  EXPECT_EQ(test::check_glb(scene_glb(in).encode()).node_names.size(), areas.size());  // no scan, no bounds
}

TEST(Report, AreasFromPosesGoCounterClockwiseFromTheFront) {
  for (const Area& a : handmade_areas()) {
    const glm::vec3 turn = glm::cross(a.corners[1] - a.corners[0], a.corners[2] - a.corners[1]);
    EXPECT_GT(glm::dot(turn, a.normal), 0.0f) << to_string(a.type);
    EXPECT_NEAR(glm::length(a.corners[1] - a.corners[0]), 2.0f * a.half_width, 1e-5f);
    EXPECT_NEAR(glm::length(a.corners[2] - a.corners[1]), 2.0f * a.half_height, 1e-5f);
    EXPECT_EQ(a.flags, category_flags(a.type, a.size, a.reach));
  }
  EXPECT_NEAR(handmade_areas()[0].normal.y, 1.0f, 1e-6f);   // floor: up
  EXPECT_NEAR(handmade_areas()[1].normal.y, -1.0f, 1e-6f);  // ceiling: down
  EXPECT_NEAR(handmade_areas()[2].normal.x, 1.0f, 1e-6f);   // wall at x = -2.4: into the room
}

TEST(Report, SceneGlbPassesTheStructuralCheckWithANodePerArea) {
  const Room& room = default_room();
  const ReportInput in = report_input(room.result, room.scan, "synthetic:default");
  const test::GlbReading glb = test::check_glb(scene_glb(in).encode());
  for (const std::string& p : glb.problems) ADD_FAILURE() << p;
  // scan, bounds, the areas, then the one room.
  ASSERT_EQ(room.result.rooms.size(), 1u);
  ASSERT_EQ(glb.node_names.size(), room.result.areas.size() + 3);
  EXPECT_EQ(glb.node_names.back(), "room 0");
  EXPECT_EQ(glb.node_names[0], "scan");
  EXPECT_EQ(glb.node_names[1], "bounds");
  for (std::size_t i = 0; i < room.result.areas.size(); ++i)
    EXPECT_EQ(glb.node_names[i + 2], expected_node_name(i, room.result.areas[i]));
  // The scan is grey and opaque; areas carry their reach in the dominant channel of their colour.
  const auto& materials = glb.doc["materials"];
  const auto& meshes = glb.doc["meshes"];
  const auto colour = [&](std::size_t node) {
    const std::size_t mesh = glb.doc["nodes"][node]["mesh"].get<std::size_t>();
    return materials[meshes[mesh]["primitives"][0]["material"].get<std::size_t>()]["pbrMetallicRoughness"]["baseColorFactor"];
  };
  const auto grey = colour(0);
  EXPECT_EQ(grey[0], grey[1]);
  EXPECT_EQ(grey[1], grey[2]);
  EXPECT_EQ(grey[3].get<float>(), 1.0f);
  for (std::size_t i = 0; i < room.result.areas.size(); ++i) {
    const auto c = colour(i + 2);
    const float r = c[0].get<float>(), g = c[1].get<float>(), b = c[2].get<float>();
    const char dominant = r > g && r > b ? 'r' : g > r && g > b ? 'g' : b > r && b > g ? 'b' : '?';
    EXPECT_EQ(dominant, test::expected_channel(std::string(to_string(room.result.areas[i].reach))));
  }
}

// Issue 15: the flat's three rooms are outlined in the plan and coloured in the scene, each where it is.
TEST(Report, RoomsAreOutlinedInThePlanAndColouredInTheScene) {
  Room flat;
  flat.scan = synth::generate(*synth::builtin("flat"));
  flat.result = analyze(flat.scan);
  ASSERT_TRUE(flat.result.ok());
  ASSERT_EQ(flat.result.rooms.size(), 3u);
  const ReportInput in = report_input(flat.result, flat.scan, "synthetic:flat");
  const std::string text = plan_svg(in);
  const test::SvgReading svg = test::read_svg(text);
  ASSERT_TRUE(svg.well_formed) << svg.error;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NE(text.find("class=\"room-outline\" data-room=\"" + std::to_string(k) + "\""), std::string::npos) << k;
    EXPECT_NE(text.find("room " + std::to_string(k) + ", "), std::string::npos) << "the label of room " << k;
  }
  const test::GlbReading glb = test::check_glb(scene_glb(in).encode());
  for (const std::string& p : glb.problems) ADD_FAILURE() << p;
  ASSERT_EQ(glb.node_names.size(), flat.result.areas.size() + 2 + 3);
  std::set<std::string> colours;
  const std::vector<synth::Rect> truth = synth::three_room_flat_rooms();
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t node = flat.result.areas.size() + 2 + k;
    EXPECT_EQ(glb.node_names[node], "room " + std::to_string(k));
    const std::size_t mesh = glb.doc["nodes"][node]["mesh"].get<std::size_t>();
    const auto& primitive = glb.doc["meshes"][mesh]["primitives"][0];
    colours.insert(glb.doc["materials"][primitive["material"].get<std::size_t>()]["pbrMetallicRoughness"]
                       ["baseColorFactor"].dump());
    // The accessor's bounds lie within the room's true rectangle (walls included: a voxel of slack).
    const auto& position = glb.doc["accessors"][primitive["attributes"]["POSITION"].get<std::size_t>()];
    const glm::vec2 lo(position["min"][0].get<float>(), position["min"][2].get<float>());
    const glm::vec2 hi(position["max"][0].get<float>(), position["max"][2].get<float>());
    const glm::vec2 centre = 0.5f * (lo + hi);
    bool inside = false;
    for (const synth::Rect& r : truth)
      if (lo.x > r.lo.x - 0.15f && lo.y > r.lo.y - 0.15f && hi.x < r.hi.x + 0.15f && hi.y < r.hi.y + 0.15f &&
          centre.x > r.lo.x && centre.x < r.hi.x)
        inside = true;
    EXPECT_TRUE(inside) << "room " << k << " spans (" << lo.x << ", " << lo.y << ") to (" << hi.x << ", " << hi.y << ")";
  }
  EXPECT_EQ(colours.size(), 3u) << "three rooms, three colours";
}

TEST(Report, SceneGlbMergesSeveralSubmittedMeshesAndDropsNonFiniteVertices) {
  Scan a{{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {NAN, 0, 0}}, {0, 2, 1, 0, 3, 1}};  // the second face touches NaN
  Scan b{{{0, 2, 0}, {1, 2, 0}, {0, 2, 1}}, {0, 1, 2, 0, 1, 7}};                // the second face is out of range
  const std::vector<Scan> meshes = {a, b};
  const std::vector<Area> areas = handmade_areas();
  ReportInput in;
  in.scan = meshes;
  in.areas = areas;
  const test::GlbReading glb = test::check_glb(scene_glb(in).encode());
  for (const std::string& p : glb.problems) ADD_FAILURE() << p;
  ASSERT_EQ(glb.node_names.size(), 1 + areas.size());  // no bounds given: no bounds node
  EXPECT_EQ(glb.node_names[0], "scan");
  EXPECT_EQ(glb.doc["accessors"][0]["count"].get<int>(), 6);  // finite vertices of both meshes
  EXPECT_EQ(glb.doc["accessors"][1]["count"].get<int>(), 6);  // two faces kept
}

TEST(Report, SceneGlbReadsBackThroughAssimp) {
  const Room& room = default_room();
  const std::string dir = temp_path("assimp");
  ReportInput in = report_input(room.result, room.scan, "synthetic:default");
  in.rooms = {};  // no room nodes: the face count below is the scan's, the bounds' and the areas'
  write_report(in, dir);
  const std::string path = dir + "/scene.glb";
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_NE(scene->mRootNode, nullptr);
  const std::size_t nodes = room.result.areas.size() + 2;
  EXPECT_EQ(scene->mNumMeshes, nodes);
  std::set<std::string> names;
  const auto collect = [&](const aiNode* n, auto&& self) -> void {
    if (n->mNumMeshes > 0) names.insert(n->mName.C_Str());
    for (unsigned i = 0; i < n->mNumChildren; ++i) self(n->mChildren[i], self);
  };
  collect(scene->mRootNode, collect);
  EXPECT_EQ(names.size(), nodes);
  EXPECT_TRUE(names.count("scan"));
  EXPECT_TRUE(names.count("bounds"));
  for (std::size_t i = 0; i < room.result.areas.size(); ++i)
    EXPECT_TRUE(names.count(expected_node_name(i, room.result.areas[i]))) << i;
  // Geometry survives: the scan's triangles and the bounds' vertices, and two triangles per area.
  std::size_t faces = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) faces += scene->mMeshes[m]->mNumFaces;
  EXPECT_EQ(faces, room.scan.indices.size() / 3 + room.result.bounds.indices.size() / 3 + 2 * room.result.areas.size());
  fs::remove_all(dir);
}

// Placements (a query's answers) are the object's box, closed, outward-facing, standing on the footprint.
TEST(Report, SceneGlbDrawsPlacementsAsTheObjectsBox) {
  const Room& room = default_room();
  PlacementQuery q;
  q.size = {0.6f, 0.4f, 0.5f};
  q.surfaces = kOnFloor | kOnWall;
  q.max_count = 3;
  const PlacementResult found = RoomQueries(room.result).find_placements(q);
  ASSERT_EQ(found.placements.size(), 3u) << found.reason;
  ReportInput in = report_input(room.result, room.scan, "synthetic:default");
  in.placements = found.placements;
  const std::string dir = temp_path("placements");
  write_report(in, dir);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(dir + "/scene.glb", aiProcess_ValidateDataStructure);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  std::size_t boxes = 0;
  const auto visit = [&](const aiNode* n, auto&& self) -> void {
    const std::string name = n->mName.C_Str();
    if (name.rfind("placement ", 0) == 0 && n->mNumMeshes == 1) {
      const std::size_t i = std::stoul(name.substr(10));
      ASSERT_LT(i, found.placements.size());
      const Placement& p = found.placements[i];
      EXPECT_EQ(name, "placement " + std::to_string(i) + " " + std::string(to_string(p.surface)));
      const aiMesh* m = scene->mMeshes[n->mMeshes[0]];
      ASSERT_EQ(m->mNumVertices, 8u);
      ASSERT_EQ(m->mNumFaces, 12u);
      // Signed volume (divergence theorem): the box's, positive when every face points out.
      double volume = 0.0;
      for (unsigned f = 0; f < m->mNumFaces; ++f) {
        const aiVector3D a = m->mVertices[m->mFaces[f].mIndices[0]], b = m->mVertices[m->mFaces[f].mIndices[1]],
                         c = m->mVertices[m->mFaces[f].mIndices[2]];
        volume += glm::dot(glm::dvec3(a.x, a.y, a.z), glm::cross(glm::dvec3(b.x, b.y, b.z), glm::dvec3(c.x, c.y, c.z))) / 6.0;
      }
      EXPECT_NEAR(volume, 0.6 * 0.4 * 0.5, 1e-4) << name;
      // It stands on the footprint, along the normal.
      for (unsigned v = 0; v < 8; ++v) {
        const glm::vec3 x(m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z);
        const float along = glm::dot(x - p.center, p.normal);
        EXPECT_TRUE(std::abs(along) < 1e-4f || std::abs(along - 0.5f) < 1e-4f) << name << " vertex " << v;
      }
      ++boxes;
    }
    for (unsigned i = 0; i < n->mNumChildren; ++i) self(n->mChildren[i], self);
  };
  visit(scene->mRootNode, visit);
  EXPECT_EQ(boxes, 3u);
  const test::GlbReading glb = test::check_glb(scene_glb(in).encode());
  for (const std::string& p : glb.problems) ADD_FAILURE() << p;
  // One the pictures cannot name is left out, not drawn with an undefined name.
  std::vector<Placement> odd = found.placements;
  odd[1].surface = static_cast<AreaType>(9);
  in.placements = odd;
  EXPECT_EQ(test::check_glb(scene_glb(in).encode()).node_names.size(), glb.node_names.size() - 1);
  EXPECT_NO_THROW(plan_svg(in));
  fs::remove_all(dir);
}

TEST(Report, WriteReportCreatesTheFolderOrSaysWhyNot) {
  const Room& room = default_room();
  const ReportInput in = report_input(room.result, room.scan, "synthetic:default");
  const std::string dir = temp_path("nested") + "/a/b";
  fs::remove_all(temp_path("nested"));
  write_report(in, dir);
  EXPECT_TRUE(fs::is_regular_file(dir + "/plan.svg"));
  EXPECT_TRUE(fs::is_regular_file(dir + "/scene.glb"));
  EXPECT_TRUE(test::read_svg(std::string(std::istreambuf_iterator<char>(std::ifstream(dir + "/plan.svg").rdbuf()), {}))
                  .well_formed);
  // A folder below a regular file cannot be made.
  const std::string file = temp_path("a_file");
  std::ofstream(file) << "x";
  try {
    write_report(in, file + "/report");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
  }
  fs::remove_all(temp_path("nested"));
  fs::remove(file);
}

// The Khronos glTF-Validator (npm package gltf-validator), where installed: ROOMSENSE_GLTF_VALIDATOR names
// the folder that holds node_modules/gltf-validator (CI installs it there when npm can reach its registry).
TEST(Report, SceneGlbPassesTheKhronosValidatorWhereInstalled) {
  const char* dir = std::getenv("ROOMSENSE_GLTF_VALIDATOR");
  if (dir == nullptr || *dir == '\0' || !fs::exists(fs::path(dir) / "node_modules" / "gltf-validator"))
    GTEST_SKIP() << "set ROOMSENSE_GLTF_VALIDATOR to a folder with node_modules/gltf-validator (npm install --prefix DIR gltf-validator)";
  const Room& room = default_room();
  const std::string out = temp_path("validator");
  write_report(report_input(room.result, room.scan, "synthetic:default"), out);
  const std::string cmd = "NODE_PATH='" + std::string(dir) + "/node_modules' node '" ROOMSENSE_GLTF_VALIDATE_SCRIPT "' '" +
                          out + "/scene.glb' 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buf[512];
  while (std::fgets(buf, sizeof buf, pipe) != nullptr) output += buf;
  const int status = pclose(pipe);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;
  std::printf("%s", output.c_str());
  fs::remove_all(out);
}

// ---- the CLI ----

struct CliRun {
  int status = -1;
  std::string err;
};

CliRun run_cli(const std::string& args) {
  const std::string err_path = temp_path("cli_stderr.txt");
  CliRun r;
  r.status = test::run_program(ROOMSENSE_CLI, args, err_path);
  {
    std::ifstream in(err_path);
    r.err.assign(std::istreambuf_iterator<char>(in), {});
  }
  fs::remove(err_path);
  return r;
}

TEST(ReportCli, AnalyzeWritesBothFilesIntoANewFolder) {
  const std::string dir = temp_path("cli") + "/report";
  fs::remove_all(temp_path("cli"));
  const CliRun r = run_cli("analyze synthetic:default --report " + dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const test::SvgReading svg = test::read_svg(
      std::string(std::istreambuf_iterator<char>(std::ifstream(dir + "/plan.svg").rdbuf()), {}));
  ASSERT_TRUE(svg.well_formed) << svg.error;
  EXPECT_EQ(svg.areas.size(), default_room().result.areas.size());
  const test::GlbReading glb = test::check_glb(test::read_bytes(dir + "/scene.glb"));
  EXPECT_TRUE(glb.problems.empty());
  EXPECT_EQ(glb.node_names.size(), default_room().result.areas.size() + 2 + default_room().result.rooms.size());
  fs::remove_all(temp_path("cli"));
}

TEST(ReportCli, AnUnwritableFolderGetsOneLineAndExitStatus1) {
  const std::string file = temp_path("cli_file");
  std::ofstream(file) << "x";
  const CliRun r = run_cli("analyze synthetic:default --json /dev/null --report " + file + "/report");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("roomsense analyze: cannot create report folder"), std::string::npos) << r.err;
  const CliRun missing = run_cli("analyze synthetic:default --report");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--report needs a value"), std::string::npos) << missing.err;
  fs::remove(file);
}

TEST(ReportCli, HelpNamesTheReportOption) {
  const std::string out = temp_path("help.txt");
  ASSERT_EQ(std::system((std::string(ROOMSENSE_CLI) + " analyze --help >" + out).c_str()), 0);
  const std::string help(std::istreambuf_iterator<char>(std::ifstream(out).rdbuf()), {});
  EXPECT_NE(help.find("--report DIR"), std::string::npos) << help;
  fs::remove(out);
}

}  // namespace
}  // namespace roomsense
