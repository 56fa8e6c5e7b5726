// Comparing what the layer returns with what the core pipeline or the CLI computes on the same room.
#pragma once
#include "layer_harness.h"
#include "roomsense/analysis.h"
#include "test_process.h"

#include <nlohmann/json.hpp>


#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <fstream>
#include <string>

namespace layertest {

// The getters against analyze()'s result, bit for bit.
inline void expect_identical(const Result& got, const roomsense::AnalysisResult& want) {
  EXPECT_EQ(got.layout.floorHeight, want.floor_y);
  EXPECT_EQ(got.layout.ceilingHeight, want.ceiling_y);
  EXPECT_EQ(got.layout.storeyCount, want.storeys.size());
  EXPECT_EQ(got.layout.inputVertexCount, want.input.vertices);
  EXPECT_EQ(got.layout.inputTriangleCount, want.input.triangles);
  ASSERT_EQ(got.areas.size(), want.areas.size());
  for (std::size_t i = 0; i < want.areas.size(); ++i) {
    const roomsense::Area& w = want.areas[i];
    const XrRoomAreaEXTX& g = got.areas[i];
    const glm::quat q = w.orientation();
    SCOPED_TRACE("area " + std::to_string(i));
    EXPECT_EQ(int(g.areaType), int(w.type));
    EXPECT_EQ(int(g.size), int(w.size));
    EXPECT_EQ(int(g.interaction), int(w.reach));
    EXPECT_EQ(g.categoryFlags, w.flags);
    EXPECT_EQ(g.pose.position.x, w.center.x);
    EXPECT_EQ(g.pose.position.y, w.center.y);
    EXPECT_EQ(g.pose.position.z, w.center.z);
    EXPECT_EQ(g.pose.orientation.x, q.x);
    EXPECT_EQ(g.pose.orientation.y, q.y);
    EXPECT_EQ(g.pose.orientation.z, q.z);
    EXPECT_EQ(g.pose.orientation.w, q.w);
    EXPECT_EQ(g.extents.width, 2.0f * w.half_width);
    EXPECT_EQ(g.extents.height, 2.0f * w.half_height);
    EXPECT_EQ(g.volumeHeight, w.volume_height);
    ASSERT_EQ(got.area_locations.size(), want.areas.size());
    EXPECT_EQ(got.area_locations[i].type, XR_TYPE_ROOM_AREA_LOCATION_EXTX);
    EXPECT_EQ(got.area_locations[i].storeyIndex, w.storey);
    EXPECT_EQ(got.area_locations[i].roomIndex,
              w.room == roomsense::kNoRoom ? XR_ROOM_INDEX_NONE_EXTX : std::uint32_t(w.room));
  }
  ASSERT_EQ(got.storeys.size(), want.storeys.size());
  for (std::size_t i = 0; i < want.storeys.size(); ++i) {
    EXPECT_EQ(got.storeys[i].floorHeight, want.storeys[i].floor_y);
    EXPECT_EQ(got.storeys[i].ceilingHeight, want.storeys[i].ceiling_y);
  }
  ASSERT_EQ(got.rooms.size(), want.rooms.size());
  for (std::size_t i = 0; i < want.rooms.size(); ++i) {
    const roomsense::Room& w = want.rooms[i];
    const XrRoomInfoEXTX& g = got.rooms[i];
    EXPECT_EQ(g.storeyIndex, w.storey);
    EXPECT_EQ(g.floorArea, w.floor_area);
    EXPECT_EQ(g.center.x, w.center.x);
    EXPECT_EQ(g.center.y, w.center.y);
    EXPECT_EQ(g.center.z, w.center.z);
    EXPECT_EQ(g.floorHeight, w.floor_y);
    EXPECT_EQ(g.ceilingHeight, w.ceiling_y);
  }
  ASSERT_EQ(got.vertices.size(), want.bounds.vertices.size());
  for (std::size_t i = 0; i < got.vertices.size(); ++i) {
    EXPECT_EQ(got.vertices[i].x, want.bounds.vertices[i].x);
    EXPECT_EQ(got.vertices[i].y, want.bounds.vertices[i].y);
    EXPECT_EQ(got.vertices[i].z, want.bounds.vertices[i].z);
  }
  EXPECT_EQ(got.indices, want.bounds.indices);
}

// Runs `roomsense analyze SOURCE --no-labels --json` and returns the document. Without labels: the layer sees
// a capture through a runtime's mesh extensions, which carry none of the capture's anchors.
inline nlohmann::json run_cli(const std::string& source) {
  const std::filesystem::path out = roomsense::test::scratch_dir() / "layer_cli.json";
  const std::string command = std::string("'") + ROOMSENSE_CLI + "' analyze '" + source + "' --no-labels --backend cpu --json '" +
                              out.string() + "'";
  const int status = std::system(command.c_str());
  if (status != 0) throw std::runtime_error("the CLI failed: " + command);
  std::ifstream in(out);
  nlohmann::json doc = nlohmann::json::parse(in);
  std::filesystem::remove(out);
  return doc;
}

// The members of the analysis JSON that describe the room (not where it came from, nor how long it took).
inline const char* const kRoomMembers[] = {"status", "floor_y", "ceiling_y", "storeys", "rooms", "areas", "bounds", "grid"};

// A member of kRoomMembers without what says how it was computed rather than what was found: the
// backend, and the voxel tests done, which differ with float rounding of the same triangles.
// The members a runtime's semantic labels change: areas (no wall area over a door or window) and rooms (a
// labelled door or window column is no wall, which moves a room's border by a column or two).
inline bool changed_by_labels(const std::string& member) { return member == "areas" || member == "rooms"; }

inline nlohmann::json room_member(const nlohmann::json& analysis, const char* member) {
  nlohmann::json m = analysis.at(member);
  if (std::string(member) == "grid")
    for (const char* how : {"backend", "voxel_tests"}) m.erase(how);
  return m;
}

inline void expect_same_room_json(const nlohmann::json& got, const nlohmann::json& want) {
  for (const char* member : kRoomMembers) {
    const nlohmann::json g = room_member(got, member), w = room_member(want, member);
    EXPECT_EQ(g, w) << "member " << member << " differs";
  }
}

// The same with a tolerance on every number: for meshes that went through the runtime's per-chunk component
// spaces, where each vertex picks up float rounding (about 1e-7 of its distance from the chunk's centre).
struct JsonDiff {
  double max_number_difference = 0.0;
  std::vector<std::string> mismatches;  // structure or non-numeric values
};

inline void diff_json(const nlohmann::json& g, const nlohmann::json& w, const std::string& path, JsonDiff& d) {
  if (g.is_number() && w.is_number()) {
    d.max_number_difference = std::max(d.max_number_difference, std::fabs(g.get<double>() - w.get<double>()));
  } else if (g.is_array() && w.is_array()) {
    if (g.size() != w.size()) {
      d.mismatches.push_back(path + ": " + std::to_string(g.size()) + " entries against " + std::to_string(w.size()));
      return;
    }
    for (std::size_t i = 0; i < g.size(); ++i) diff_json(g[i], w[i], path + "[" + std::to_string(i) + "]", d);
  } else if (g.is_object() && w.is_object()) {
    for (auto it = w.begin(); it != w.end(); ++it) {
      if (!g.contains(it.key())) d.mismatches.push_back(path + "." + it.key() + " missing");
      else diff_json(g.at(it.key()), it.value(), path + "." + it.key(), d);
    }
  } else if (g != w) {
    d.mismatches.push_back(path + ": " + g.dump() + " against " + w.dump());
  }
}

// The room files every runtime-mesh comparison runs on: every scan of ../shared/rooms.
inline const char* const kRealRooms[] = {
    "quest-iwer/living_room_global_mesh.obj",  "quest-iwer/meeting_room_global_mesh.obj",
    "quest-iwer/music_room_global_mesh.obj",   "quest-iwer/office_large_global_mesh.obj",
    "quest-iwer/office_small_global_mesh.obj", "quest-iwer/living_room.json",
    "quest-iwer/meeting_room.json",            "quest-iwer/music_room.json",
    "quest-iwer/office_large.json",            "quest-iwer/office_small.json",
    "hololens1/holotoolkit_fake_spatial_mapping.obj", "hololens1/mrtk_example_spatial_mesh.obj",
    "hololens2-su/SU_Kitchen_world_mesh.obj",  "hololens2-su/SU_Apartment_world_mesh.obj"};

// A headset the simulated runtime plays (ROOMSENSE_SIM_EXTENSIONS) and the mesh source the layer must use on it.
struct Headset {
  const char* name;
  std::optional<std::string> extensions;  // nullopt: everything the runtime serves
  const char* mesh_source;
  bool labels = false;  // the source carries the runtime's labels: its areas differ from the CLI's
};

// The layer's analysis of the runtime's meshes of `source` against `roomsense analyze` of the same file: the
// same structure and every number within 1e-4 m (test_results.cpp says why not bit for bit). Returns the areas.
inline std::size_t expect_runtime_matches_cli(const std::string& source, const std::optional<std::string>& chunk,
                                              const Headset& headset) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", headset.extensions);
  ScopedEnv scene("ROOMSENSE_SIM_SCENE", source);
  ScopedEnv chunk_size("ROOMSENSE_SIM_CHUNK_SIZE", chunk);
  Result got;
  double query_ms = 0.0;
  {
    App app;
    const XrRoomAnalyzerEXTX a = app.analyzer();
    EXPECT_EQ(app.compute(a, true), XR_ROOM_COMPUTE_STATE_COMPLETED_EXTX) << source << " on " << headset.name;
    got = read_result(app.extx, a);
  }
  if (got.json.empty()) return 0;
  const nlohmann::json layer = nlohmann::json::parse(got.json);
  const nlohmann::json& openxr = layer.at("openxr");
  EXPECT_EQ(openxr.at("mesh_source"), headset.mesh_source) << source << " on " << headset.name;
  EXPECT_GE(openxr.at("runtime_meshes").get<int>(), 1);
  query_ms = openxr.at("mesh_query_ms").get<double>();
  const nlohmann::json cli = run_cli(source);
  JsonDiff d;
  for (const char* member : kRoomMembers) {
    if (headset.labels && changed_by_labels(member)) continue;
    nlohmann::json g = room_member(layer, member), w = room_member(cli, member);
    diff_json(g, w, member, d);
  }
  for (const std::string& m : d.mismatches) ADD_FAILURE() << source << " on " << headset.name << ": " << m;
  EXPECT_LE(d.max_number_difference, 1e-4) << source << " on " << headset.name;
  std::printf("[ figures  ] %s on %s (chunks %s): %zu areas, %zu bounds triangles, largest difference to the CLI "
              "%.2g m, capture through %s %.1f ms\n",
              source.c_str(), headset.name, chunk ? chunk->c_str() : "2 m", got.areas.size(), got.indices.size() / 3,
              d.max_number_difference, headset.mesh_source, query_ms);
  return got.areas.size();
}

}  // namespace layertest
