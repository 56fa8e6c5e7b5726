// scanio's Quest capture parser: conventions on a tiny hand-written capture, the real captures against their
// OBJ exports, and clear errors (never a crash) on malformed files.
#include "rooms.h"

#include "roomsense/error.h"
#include "roomsense/quest_capture.h"
#include "roomsense/scanio.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

using roomsense::scanio::parse_quest_capture;

std::string base64(const void* data, std::size_t size) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::string out;
  for (std::size_t i = 0; i < size; i += 3) {
    const unsigned v = bytes[i] << 16 | (i + 1 < size ? bytes[i + 1] << 8 : 0) | (i + 2 < size ? bytes[i + 2] : 0);
    out += alphabet[v >> 18 & 63];
    out += alphabet[v >> 12 & 63];
    out += i + 1 < size ? alphabet[v >> 6 & 63] : '=';
    out += i + 2 < size ? alphabet[v & 63] : '=';
  }
  return out;
}

std::string capture(const std::string& vertices, const std::string& indices, const std::string& extra = "") {
  return R"({"spatialEntities":[)" + extra +
         R"({"semanticLabel_META":"GLOBAL_MESH","locatable_META":{"position":{"x":1,"y":2,"z":3},"orientation":{"w":1}},
             "triangleMesh_META":{"vertices":")" + vertices + R"(","indices":")" + indices + R"("}}]})";
}

const float kVertices[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
const uint32_t kIndices[] = {0, 1, 2};

TEST(QuestCapture, TinyCaptureConventions) {
  const std::string floor = R"({"semanticLabel_META":"FLOOR","locatable_META":{"position":{"y":0.05},
      "orientation":{"x":1}},"bounded2D_META":{"offset":{"x":-1,"y":-2},"extent":{"width":2,"height":4}}},)";
  const std::string table = R"({"semanticLabel_META":"TABLE","locatable_META":{"position":{"y":0.75},
      "orientation":{"x":-0.70710678,"w":0.70710678}},"bounded3D_META":{"offset":{"x":-0.5,"y":-0.25,"z":-0.75},
      "extent":{"width":1,"height":0.5,"depth":0.75}}},)";
  const auto c = parse_quest_capture(capture(base64(kVertices, sizeof kVertices), base64(kIndices, sizeof kIndices), floor + table), "tiny");
  ASSERT_EQ(c.mesh.vertices.size(), 3u);
  EXPECT_EQ(c.mesh.vertices[1], glm::vec3(2, 2, 3));  // the entity pose is applied
  ASSERT_EQ(c.planes.size(), 1u);
  const auto rect = roomsense::scanio::plane_rect(c.planes[0]);
  EXPECT_NEAR(rect.pose.position.y, 0.05f, 1e-6);
  EXPECT_NEAR((rect.pose.orientation * glm::vec3(0, 0, 1)).y, 1.0f, 1e-6);  // floor normal up
  EXPECT_FLOAT_EQ(rect.width, 2.0f);
  EXPECT_FLOAT_EQ(rect.height, 4.0f);
  ASSERT_EQ(c.volumes.size(), 1u);
  const auto top = roomsense::scanio::volume_top_rect(c.volumes[0]);
  EXPECT_NEAR(top.pose.position.y, 0.75f, 1e-6);  // the box's top face
  EXPECT_NEAR((top.pose.orientation * glm::vec3(0, 0, 1)).y, 1.0f, 1e-6);
  EXPECT_FLOAT_EQ(top.width * top.height, 0.5f);
}

TEST(QuestCapture, MalformedFilesThrowClearErrors) {
  const std::string v = base64(kVertices, sizeof kVertices), i = base64(kIndices, sizeof kIndices);
  const uint32_t out_of_range[] = {0, 1, 7};
  const std::vector<std::string> bad = {
      "", "{", "[1,2]", R"({"spatialEntities":{}})", R"({"spatialEntities":[]})", R"({"spatialEntities":[3]})",
      R"({"spatialEntities":[{"locatable_META":"x"}]})",
      R"({"spatialEntities":[{"locatable_META":{"position":{"x":"1"},"orientation":{"w":1}}}]})",
      R"({"spatialEntities":[{"locatable_META":{"position":{},"orientation":{}}}]})",  // zero quaternion
      R"({"spatialEntities":[{"locatable_META":{"position":{"x":1e300},"orientation":{"w":1}}}]})",
      capture(v.substr(0, v.size() - 4), i),  // truncated: not whole vertices
      capture(v.substr(0, v.size() - 1), i),  // not whole base64
      capture("!!!!" + v, i), capture(v, base64(out_of_range, sizeof out_of_range)), capture(v, i.substr(0, 8)),
      R"({"spatialEntities":[{"locatable_META":{"position":{},"orientation":{"w":1}},"triangleMesh_META":{"vertices":5,"indices":""}}]})",
      R"({"spatialEntities":[{"locatable_META":{"position":{},"orientation":{"w":1}},"bounded2D_META":{"offset":{},"extent":{"width":-1}}}]})",
  };
  for (const std::string& text : bad) {
    try {
      parse_quest_capture(text, "bad.json");
      ADD_FAILURE() << "accepted: " << text.substr(0, 120);
    } catch (const roomsense::Error& e) {
      EXPECT_EQ(e.code(), roomsense::ErrorCode::Io);
      EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos);
    }
  }
  EXPECT_THROW(roomsense::scanio::load_quest_capture("/nonexistent.json"), roomsense::Error);
}

TEST(QuestCapture, RealCaptureMatchesItsObjExport) {
  ROOMSENSE_REQUIRE_ROOM(json, "quest-iwer/office_small.json");
  ROOMSENSE_REQUIRE_ROOM(obj, "quest-iwer/office_small_global_mesh.obj");
  const auto c = roomsense::scanio::load_quest_capture(json.string());
  const auto exported = roomsense::scanio::load_mesh_file(obj.string());
  EXPECT_EQ(c.mesh.vertices.size(), 1895u);
  EXPECT_EQ(c.mesh.indices.size(), 3822u * 3);
  EXPECT_EQ(c.planes.size() + c.volumes.size(), 13u);  // every entity but the mesh
  // The export has 5 decimals, and assimp reorders vertices: compare each with its nearest.
  ASSERT_EQ(exported.vertices.size(), c.mesh.vertices.size());
  float worst = 0;
  for (const auto& v : c.mesh.vertices) {
    float best = 1e30f;
    for (const auto& e : exported.vertices) best = std::min(best, glm::length(v - e));
    worst = std::max(worst, best);
  }
  EXPECT_LT(worst, 1e-4f);
}

}  // namespace
