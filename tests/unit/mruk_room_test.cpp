// scanio's MRUK room reader: the Unity -> OpenXR conversion, plane and volume conventions (through
// plane_rect / volume_top_rect), merged rooms, global and built meshes, "Unreal" files, and clear errors (never
// a crash) on malformed input. The rooms in tests/data/mruk are hand-written for these tests.
#include "roomsense/error.h"
#include "roomsense/mruk_room.h"
#include "roomsense/scan.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using roomsense::Error;
using roomsense::ErrorCode;
using roomsense::Scan;
using roomsense::scanio::is_mruk_room_json;
using roomsense::scanio::load_mruk_room;
using roomsense::scanio::OrientedRect;
using roomsense::scanio::parse_mruk_room;
using roomsense::scanio::plane_rect;
using roomsense::scanio::QuestCapture;
using roomsense::scanio::volume_top_rect;

const std::filesystem::path kData = ROOMSENSE_MRUK_TEST_DATA;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

QuestCapture load(const char* name) { return load_mruk_room((kData / name).string()); }

glm::vec3 normal(const OrientedRect& r) { return r.pose.orientation * glm::vec3(0, 0, 1); }
glm::vec3 up_axis(const OrientedRect& r) { return r.pose.orientation * glm::vec3(0, 1, 0); }

void expect_vec_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-4f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
  EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
  EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

const roomsense::scanio::QuestPlane& plane(const QuestCapture& c, const std::string& uuid) {
  const auto it = std::find_if(c.planes.begin(), c.planes.end(), [&](const auto& p) { return p.uuid == uuid; });
  if (it == c.planes.end()) throw std::runtime_error("no plane " + uuid);
  return *it;
}

const roomsense::scanio::QuestVolume& volume(const QuestCapture& c, const std::string& uuid) {
  const auto it = std::find_if(c.volumes.begin(), c.volumes.end(), [&](const auto& v) { return v.uuid == uuid; });
  if (it == c.volumes.end()) throw std::runtime_error("no volume " + uuid);
  return *it;
}

// Six times the signed volume the triangles enclose: positive when they face outwards (counter-clockwise).
double signed_volume(const Scan& s) {
  double v = 0.0;
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3) {
    const glm::dvec3 a = s.vertices[s.indices[t]], b = s.vertices[s.indices[t + 1]], c = s.vertices[s.indices[t + 2]];
    v += glm::dot(a, glm::cross(b, c));
  }
  return v / 6.0;
}

// Closed and consistently oriented: every directed edge once, and its reverse once.
bool closed_and_oriented(const Scan& s) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) ++edges[{s.indices[t + k], s.indices[t + (k + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    if (count != 1) return false;
    const auto reverse = edges.find({edge.second, edge.first});
    if (reverse == edges.end() || reverse->second != 1) return false;
  }
  return !edges.empty();
}

std::string room_json(const std::string& anchors, const std::string& system = R"("CoordinateSystem": "Unity", )") {
  return "{" + system + R"("Rooms": [{"UUID": "R", "RoomLayout": {}, "Anchors": [)" + anchors + "]}]}";
}

std::string anchor(const std::string& label, const std::string& translation, const std::string& rotation,
                   const std::string& extra) {
  return R"({"UUID": ")" + label + R"(", "SemanticClassifications": [")" + label +
         R"("], "Transform": {"Translation": )" + translation + R"(, "Rotation": )" + rotation +
         R"(, "Scale": [1, 1, 1]})" + extra + "}";
}

constexpr float kRoomHeight = 2.6f;
const glm::vec3 kRoomCentre(0.0f, 1.3f, -1.5f);  // Unity x -2..2, z 0..3 is ours x -2..2, z -3..0

TEST(MrukRoom, LabelsAndCounts) {
  const QuestCapture c = load("room_4x3.json");
  std::multiset<std::string> labels;
  for (const auto& p : c.planes) labels.insert(p.label);
  EXPECT_EQ(labels, (std::multiset<std::string>{"FLOOR", "CEILING", "WALL_FACE", "WALL_FACE", "WALL_FACE", "WALL_FACE",
                                                "TABLE", "WINDOW_FRAME", "DOOR_FRAME"}));
  ASSERT_EQ(c.volumes.size(), 1u);
  EXPECT_EQ(c.volumes[0].label, "TABLE");  // the table is both a plane and a volume, as in a Quest capture
  EXPECT_EQ(c.volumes[0].uuid, "T100");
  EXPECT_EQ(c.skipped_entities, 0u);
  // No global mesh: 8 planes as polygons (2 triangles each) and the table as a closed box (12).
  EXPECT_EQ(c.mesh.indices.size(), 3u * (8 * 2 + 12));
}

TEST(MrukRoom, FloorAndCeilingFaceIntoTheRoom) {
  const QuestCapture c = load("room_4x3.json");
  const OrientedRect floor = plane_rect(plane(c, "F100"));
  expect_vec_near(floor.pose.position, {0, 0, -1.5f});
  expect_vec_near(normal(floor), {0, 1, 0});
  EXPECT_NEAR(floor.width * floor.height, 12.0f, 1e-4);
  const OrientedRect ceiling = plane_rect(plane(c, "C100"));
  expect_vec_near(ceiling.pose.position, {0, kRoomHeight, -1.5f});
  expect_vec_near(normal(ceiling), {0, -1, 0});
}

TEST(MrukRoom, WallsFaceIntoTheRoomUpright) {
  const QuestCapture c = load("room_4x3.json");
  const std::map<std::string, float> widths = {{"W100", 4}, {"W200", 4}, {"W300", 3}, {"W400", 3}};
  for (const auto& [uuid, width] : widths) {
    SCOPED_TRACE(uuid);
    const OrientedRect wall = plane_rect(plane(c, uuid));
    const glm::vec3 n = normal(wall);
    EXPECT_NEAR(n.y, 0.0f, 1e-5);
    EXPECT_NEAR(glm::dot(n, glm::normalize(kRoomCentre - wall.pose.position)), 1.0f, 1e-4);  // straight at the centre
    expect_vec_near(up_axis(wall), {0, 1, 0});  // DESIGN.md: for walls +Y is up
    EXPECT_NEAR(wall.pose.position.y, 1.3f, 1e-5);
    EXPECT_NEAR(wall.width, width, 1e-5);
    EXPECT_NEAR(wall.height, kRoomHeight, 1e-5);
  }
  // The wall at Unity z = 0 is ours at z = 0 and faces -Z; the window in it sits on it and faces the same way.
  expect_vec_near(plane_rect(plane(c, "W100")).pose.position, {0, 1.3f, 0});
  const OrientedRect window = plane_rect(plane(c, "N100"));
  expect_vec_near(window.pose.position, {-0.8f, 1.5f, 0});
  expect_vec_near(normal(window), {0, 0, -1});
  EXPECT_NEAR(window.width, 1.0f, 1e-5);
  EXPECT_NEAR(window.height, 1.2f, 1e-5);
  const OrientedRect door = plane_rect(plane(c, "D100"));
  expect_vec_near(door.pose.position, {2, 1, -2});
  expect_vec_near(normal(door), {-1, 0, 0});
  EXPECT_NEAR(door.pose.position.y - door.height / 2, 0.0f, 1e-5);  // the door reaches the floor
}

TEST(MrukRoom, TableTopIsUpAtItsHeight) {
  const QuestCapture c = load("room_4x3.json");
  const OrientedRect top = volume_top_rect(volume(c, "T100"));
  expect_vec_near(top.pose.position, {0.5f, 0.75f, -1.8f});
  expect_vec_near(normal(top), {0, 1, 0});
  EXPECT_NEAR(top.width * top.height, 1.2f * 0.8f, 1e-5);
  const OrientedRect surface = plane_rect(plane(c, "T100"));  // the table's plane is its top too
  expect_vec_near(surface.pose.position, top.pose.position);
  expect_vec_near(normal(surface), {0, 1, 0});
  // Unity yaw 30 degrees turns the table's long side (local X) from +X towards Unity -Z, ours +Z.
  const glm::vec3 long_side = surface.pose.orientation * glm::vec3(surface.width > surface.height ? 1 : 0, 0,
                                                                   surface.width > surface.height ? 0 : 1);
  EXPECT_NEAR(std::fabs(long_side.x), std::cos(glm::radians(30.0f)), 1e-4);
  EXPECT_NEAR(std::fabs(long_side.z), 0.5f, 1e-4);
  EXPECT_GT(long_side.x * long_side.z, 0.0f);  // ours: (cos 30, 0, +sin 30) up to sign
}

TEST(MrukRoom, UnityPointsMirrorZ) {
  // A wall-like plane at Unity (1, 2, 3) with no rotation faces Unity +Z, ours -Z, and sits at ours (1, 2, -3).
  const std::string wall =
      anchor("WALL_FACE", "[1, 2, 3]", "[0, 0, 0]", R"(, "PlaneBounds": {"Min": [-1, -1], "Max": [1, 1]})");
  // Euler (90, 90, 0): Unity applies Z, then X, then Y, so local +Z (the normal) points down and local +X
  // points to Unity -Z, local +Y to Unity +X. Its mesh vertices at local (0, 0, 0), (1, 0, 0) and (0, 1, 0) are
  // Unity (4, 5, 6), (4, 5, 5) and (5, 5, 6).
  const std::string turned = anchor("GLOBAL_MESH", "[4, 5, 6]", "[90, 90, 0]",
                                    R"(, "PlaneBounds": {"Min": [-1, -1], "Max": [1, 1]},
                                       "GlobalMesh": {"Positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "Indices": [0, 1, 2]})");
  const QuestCapture c = parse_mruk_room(room_json(wall + "," + turned), "inline");
  const OrientedRect w = plane_rect(plane(c, "WALL_FACE"));
  expect_vec_near(w.pose.position, {1, 2, -3});
  expect_vec_near(normal(w), {0, 0, -1});
  expect_vec_near(normal(plane_rect(plane(c, "GLOBAL_MESH"))), {0, -1, 0});
  ASSERT_EQ(c.mesh.vertices.size(), 3u);  // the room has a global mesh: the planes are not meshed
  expect_vec_near(c.mesh.vertices[0], {4, 5, -6});
  expect_vec_near(c.mesh.vertices[1], {4, 5, -5});
  expect_vec_near(c.mesh.vertices[2], {5, 5, -6});
  // The same mapping as core's left-handed (Unity) scan conversion.
  Scan unity{{{4, 5, 6}, {4, 5, 5}, {5, 5, 6}}, {0, 1, 2}};
  roomsense::convert_to_roomsense_frame(unity, {roomsense::UpAxis::Y, roomsense::Units::Metres, true});
  for (std::size_t i = 0; i < 3; ++i) expect_vec_near(c.mesh.vertices[i], unity.vertices[i]);
  EXPECT_EQ(c.mesh.indices, unity.indices);
}

TEST(MrukRoom, UnrealFileMatchesTheUnityOne) {
  const QuestCapture unity = load("room_4x3.json");
  const QuestCapture unreal = load("room_4x3_unreal.json");
  ASSERT_EQ(unreal.planes.size(), 4u);
  for (const auto& p : unreal.planes) {
    SCOPED_TRACE(p.uuid);
    const OrientedRect a = plane_rect(p), b = plane_rect(plane(unity, p.uuid));
    expect_vec_near(a.pose.position, b.pose.position);
    expect_vec_near(normal(a), normal(b));
    expect_vec_near(up_axis(a), up_axis(b));
    EXPECT_NEAR(a.width, b.width, 1e-4);
    EXPECT_NEAR(a.height, b.height, 1e-4);
  }
  ASSERT_EQ(unreal.volumes.size(), 1u);
  const OrientedRect a = volume_top_rect(unreal.volumes[0]), b = volume_top_rect(volume(unity, "T100"));
  expect_vec_near(a.pose.position, b.pose.position);
  expect_vec_near(normal(a), normal(b));
  EXPECT_NEAR(a.width * a.height, b.width * b.height, 1e-4);
}

TEST(MrukRoom, RoomsAreMergedAndConcaveFloorsTriangulated) {
  const QuestCapture c = load("two_rooms.json");  // no CoordinateSystem key: Unity
  EXPECT_EQ(c.planes.size(), 3u);
  EXPECT_EQ(c.volumes.size(), 2u);
  EXPECT_EQ(c.skipped_entities, 1u);  // the OTHER anchor with a transform only
  expect_vec_near(volume_top_rect(volume(c, "A-C")).pose.position, {-0.7f, 0.8f, 0.7f});
  const OrientedRect storage = volume_top_rect(volume(c, "B-S"));
  expect_vec_near(storage.pose.position, {10, 1, 0});
  expect_vec_near(normal(storage), {0, 1, 0});
  // Room A's L-shaped floor: 3 x 3 less a 1.5 x 1.5 corner, all facing up (the couch stands 5 cm above it).
  double area = 0.0;
  for (std::size_t t = 0; t < c.mesh.indices.size(); t += 3) {
    const glm::vec3 a = c.mesh.vertices[c.mesh.indices[t]], b = c.mesh.vertices[c.mesh.indices[t + 1]],
                    d = c.mesh.vertices[c.mesh.indices[t + 2]];
    if (std::max({std::fabs(a.y), std::fabs(b.y), std::fabs(d.y)}) > 1e-6f || a.x > 5.0f) continue;
    const glm::vec3 n = glm::cross(b - a, d - a);
    EXPECT_GT(n.y, 0.0f);
    area += 0.5 * glm::length(n);
  }
  EXPECT_NEAR(area, 6.75, 1e-4);
}

TEST(MrukRoom, GlobalMeshIsUsedAndConverted) {
  const QuestCapture c = load("global_mesh.json");
  EXPECT_EQ(c.planes.size(), 2u);  // the floor and the table still come as planes
  EXPECT_EQ(c.volumes.size(), 1u);
  ASSERT_EQ(c.mesh.vertices.size(), 8u);  // only the global mesh, nothing built from the anchors
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& v : c.mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  expect_vec_near(lo, {-2, 0, -3});
  expect_vec_near(hi, {2, kRoomHeight, 0});
  EXPECT_TRUE(closed_and_oriented(c.mesh));
  EXPECT_NEAR(signed_volume(c.mesh), -4.0 * 3.0 * kRoomHeight, 1e-3);  // scanned surfaces face into the room
}

TEST(MrukRoom, BuiltMeshesAreClosedAndFaceTheRightWay) {
  // The floor, ceiling and four walls (the file's first six anchors, two triangles each) close the room and
  // all face into it.
  const QuestCapture room = load("room_4x3.json");
  Scan walls;
  walls.vertices = room.mesh.vertices;
  walls.indices.assign(room.mesh.indices.begin(), room.mesh.indices.begin() + 6 * 2 * 3);
  EXPECT_NEAR(signed_volume(walls), -4.0 * 3.0 * kRoomHeight, 1e-3);

  // A lone volume is a closed box facing out.
  const QuestCapture box =
      parse_mruk_room(room_json(anchor("STORAGE", "[1, 1, 1]", "[270, 20, 0]",
                                       R"(, "VolumeBounds": {"Min": [-0.5, -0.25, -1], "Max": [0.5, 0.25, 0]})")),
                      "box");
  EXPECT_EQ(box.mesh.indices.size(), 36u);
  EXPECT_TRUE(closed_and_oriented(box.mesh));
  EXPECT_NEAR(signed_volume(box.mesh), 0.5, 1e-4);
}

TEST(MrukRoom, DegenerateBoundariesStillEnd) {
  // A bow-tie (self-crossing) boundary and a long zig-zag: the reader finishes and keeps the plane.
  std::string zigzag = "[";
  for (int i = 0; i <= 1000; ++i) {  // appended piece by piece: GCC 12's -Wrestrict misfires on "[" + std::string
    zigzag += '[';
    zigzag += std::to_string(i * 0.001);
    zigzag += i % 2 != 0 ? ", 0.01]," : ", 0],";
  }
  zigzag += "[1, 1], [0, 1]]";
  const QuestCapture c = parse_mruk_room(
      room_json(
          anchor("FLOOR", "[0, 0, 0]", "[270, 0, 0]", R"(, "PlaneBoundary2D": [[0, 0], [1, 1], [1, 0], [0, 1]])") +
          "," + anchor("CEILING", "[0, 2, 0]", "[90, 0, 0]", R"(, "PlaneBoundary2D": )" + zigzag)),
      "degenerate");
  EXPECT_EQ(c.planes.size(), 2u);
  EXPECT_FALSE(c.mesh.indices.empty());
  EXPECT_NEAR(plane_rect(plane(c, "CEILING")).width * plane_rect(plane(c, "CEILING")).height, 1.0f, 1e-4);
}

void expect_error(const std::string& text, const std::string& fragment) {
  SCOPED_TRACE(text.substr(0, 300));
  try {
    parse_mruk_room(text, "bad.json");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("cannot read MRUK room 'bad.json': ", 0), 0u) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(MrukRoom, MalformedFilesThrowClearErrors) {
  const std::string floor_bounds = R"(, "PlaneBounds": {"Min": [-1, -1], "Max": [1, 1]})";
  const auto floor_with = [&](const std::string& translation, const std::string& extra) {
    return room_json(anchor("FLOOR", translation, "[270, 0, 0]", extra));
  };
  const auto mesh = [&](const std::string& positions, const std::string& indices) {
    return room_json(anchor("GLOBAL_MESH", "[0, 0, 0]", "[0, 0, 0]",
                            R"(, "GlobalMesh": {"Positions": )" + positions + R"(, "Indices": )" + indices + "}"));
  };
  expect_error("", "not valid JSON");
  expect_error(R"({"Rooms": [)", "not valid JSON");
  expect_error(R"({"Rooms": [NaN]})", "not valid JSON");
  expect_error("[1, 2]", "top level is not a JSON object");
  expect_error("{}", R"(no "Rooms" array)");
  expect_error(R"({"Rooms": {}})", R"(no "Rooms" array)");
  expect_error(R"({"Rooms": []})", "empty");
  expect_error(R"({"Rooms": [3]})", "Rooms[0] is not an object");
  expect_error(R"({"Rooms": [{}]})", R"(Rooms[0] has no "Anchors" array)");
  expect_error(room_json(anchor("FLOOR", "[0, 0, 0]", "[0, 0, 0]", floor_bounds), R"("CoordinateSystem": "OpenXR", )"),
               R"(CoordinateSystem "OpenXR" is neither "Unity" nor "Unreal")");
  expect_error(room_json(R"({"UUID": "x", "PlaneBounds": {"Min": [0, 0], "Max": [1, 1]}})"),
               R"(Anchors[0] has no object "Transform")");
  expect_error(room_json(R"({"Transform": {"Rotation": [0, 0, 0]}})"), R"(Transform has no "Translation")");
  expect_error(floor_with("[0, 0]", floor_bounds), "Transform.Translation is not an array of 3 numbers");
  expect_error(floor_with(R"([0, "1", 0])", floor_bounds), "Translation[1] is not a number");
  expect_error(floor_with("[0, 1e999, 0]", floor_bounds), "not valid JSON");  // overflows to no number at all
  expect_error(floor_with("[0, 1e300, 0]", floor_bounds), "Translation lies beyond 1 km");
  expect_error(floor_with("[0, 0, 0]", R"(, "PlaneBounds": {"Min": [-1, -1], "Max": [5000, 1]})"),
               "PlaneBounds.Max lies beyond 1 km");
  expect_error(floor_with("[0, 0, 0]", R"(, "PlaneBounds": {"Min": [1, -1], "Max": [-1, 1]})"),
               "PlaneBounds.Min exceeds Max");
  expect_error(floor_with("[0, 0, 0]", R"(, "PlaneBounds": {"Min": [-1, -1]})"), R"(PlaneBounds has no "Max")");
  expect_error(floor_with("[0, 0, 0]", R"(, "VolumeBounds": {"Min": [0, 0, -2000], "Max": [1, 1, 0]})"),
               "VolumeBounds.Min lies beyond 1 km");
  expect_error(floor_with("[0, 0, 0]", R"(, "VolumeBounds": [1, 2])"), "VolumeBounds is not an object");
  expect_error(floor_with("[0, 0, 0]", R"(, "PlaneBoundary2D": [[0, 0], [1, 1]])"), "fewer than 3 points");
  std::string many = "[";
  for (int i = 0; i < 1100; ++i) {
    many += '[';
    many += std::to_string(i);
    many += ", 0],";
  }
  many.back() = ']';
  expect_error(floor_with("[0, 0, 0]", R"(, "PlaneBoundary2D": )" + many), "more than 1024");
  expect_error(
      room_json(
          R"({"SemanticClassifications": "FLOOR", "Transform": {"Translation": [0, 0, 0], "Rotation": [0, 0, 0]}})"),
      "SemanticClassifications is not an array");
  expect_error(room_json(anchor("FLOOR", "[0, 0, 0]", "[0, 0, 0]", R"(, "Transform": 1)")),
               R"(has no object "Transform")");  // a repeated key: the last one counts
  expect_error(
      room_json(
          R"({"Transform": {"Translation": [0, 0, 0], "Rotation": [0, 0, 0], "Scale": [0, 1, 1]}, "PlaneBounds": {"Min": [0, 0], "Max": [1, 1]}})"),
      "Scale is not between");
  expect_error(mesh("[[0, 0, 0], [1, 0, 0], [0, 1, 0]]", "[0, 1, 3]"), "Indices[2] is out of range for 3 positions");
  expect_error(mesh("[[0, 0, 0], [1, 0, 0], [0, 1, 0]]", "[0, -1, 2]"), "Indices[1] is out of range");
  expect_error(mesh("[[0, 0, 0], [1, 0, 0], [0, 1, 0]]", "[0, 1.5, 2]"), "Indices[1] is not an integer");
  expect_error(mesh("[[0, 0, 0], [1, 0, 0], [0, 1, 0]]", "[0, 1]"), "not a whole number of triangles");
  expect_error(mesh("[[0, 0, 0], [1, 0, 0], [0, 1]]", "[0, 1, 2]"), "Positions[2] is not an array of 3 numbers");
  expect_error(mesh("[[0, 0, 0], [1, 0, 0], [0, 1, 9999]]", "[0, 1, 2]"), "Positions[2] lies beyond 1 km");
  expect_error(mesh("{}", "[]"), R"(GlobalMesh has no "Positions" array)");
  expect_error(room_json(anchor("OTHER", "[0, 0, 0]", "[0, 0, 0]", "")), "no usable geometry");
  expect_error(mesh("[[0, 0, 0]]", "[]"), "no usable geometry");
}

TEST(MrukRoom, TruncatedFilesNeverCrash) {
  const std::string text = read_text(kData / "two_rooms.json");
  ASSERT_FALSE(text.empty());
  for (std::size_t n = 0; n < text.size(); n += 7) {
    try {
      parse_mruk_room(std::string_view(text).substr(0, n), "cut");
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::Io);
    }
  }
}

TEST(MrukRoom, MissingFileThrows) { EXPECT_THROW(load_mruk_room((kData / "no_such_room.json").string()), Error); }

TEST(MrukRoom, SniffTellsRoomsFromCaptures) {
  EXPECT_TRUE(is_mruk_room_json(read_text(kData / "room_4x3.json")));
  EXPECT_TRUE(is_mruk_room_json(read_text(kData / "two_rooms.json")));
  EXPECT_TRUE(is_mruk_room_json(R"(  {"CoordinateSystem": "Unity", "Rooms": [{"UUID": )"));  // a prefix is enough
  EXPECT_FALSE(is_mruk_room_json(R"({"spatialEntities": [], "Rooms": []})"));
  EXPECT_FALSE(is_mruk_room_json(R"({"spatialEntities": [{"uuid": "x"}]})"));
  EXPECT_FALSE(is_mruk_room_json(R"({"a": {"Rooms": []}})"));  // only a top-level key counts
  EXPECT_FALSE(is_mruk_room_json(R"([{"Rooms": []}])"));
  EXPECT_FALSE(is_mruk_room_json(""));
  EXPECT_FALSE(is_mruk_room_json("not json"));
}

}  // namespace
