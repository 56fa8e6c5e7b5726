// The CLI's JSON, schema roomsense.analysis/1 (DESIGN.md). Extra members beyond the contract: status,
// message, warnings, input.{outlier_vertices, dropped_triangles, mode}, grid.backend, bounds.closed,
// areas[].orientation (the pose quaternion x, y, z, w), areas[].storey (an index into storeys, main first),
// areas[].room (an index into rooms, or null), rooms (issue 15, with rooms[].bounds as bounds),
// storeys[].room_m2 (B, Eq. 3.12) and area_counts (per type: wall, floor, ceiling, furniture).
#include "roomsense/export.h"

#include "roomsense/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace roomsense {
namespace {

nlohmann::json height(float y, bool ok) { return ok && std::isfinite(y) ? nlohmann::json(y) : nlohmann::json(nullptr); }

nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json bounds_json(const BoundsMesh& mesh, bool ok) {
  return {{"vertices", mesh.vertices.size()},
          {"triangles", mesh.indices.size() / 3},
          {"closed", ok && check_closure(mesh).closed()}};
}

nlohmann::json areas_json(const std::vector<Area>& areas) {
  nlohmann::json out = nlohmann::json::array();
  for (const Area& a : areas) {
    const glm::quat q = a.orientation();
    out.push_back({{"type", to_string(a.type)},
                   {"size", to_string(a.size)},
                   {"interaction", to_string(a.reach)},
                   {"center", vec(a.center)},
                   {"normal", vec(a.normal)},
                   {"half_width", a.half_width},
                   {"half_height", a.half_height},
                   {"rotation_deg", a.rotation_deg},
                   {"volume_height", a.volume_height},
                   {"corners", {vec(a.corners[0]), vec(a.corners[1]), vec(a.corners[2]), vec(a.corners[3])}},
                   {"orientation", {q.x, q.y, q.z, q.w}},
                   {"flags", a.flags},
                   {"storey", a.storey},
                   {"room", a.room == kNoRoom ? nlohmann::json(nullptr) : nlohmann::json(a.room)}});
  }
  return out;
}

}  // namespace

std::string analysis_json(const AnalysisResult& r, const JsonSource& source,
                          const std::vector<std::pair<std::string, std::string>>& members) {
  using nlohmann::json;
  const GridSpec& g = r.voxels.grid.spec;
  json storeys = json::array();
  for (std::size_t i = 0; i < r.storeys.size(); ++i) {
    const Storey& s = r.storeys[i];
    const RoomFeatures& f = r.storey_features(i);
    const double cell = double(g.voxel_size) * double(g.voxel_size);
    const auto square_metres = [cell](const std::vector<std::uint8_t>& mask) {
      return double(std::count(mask.begin(), mask.end(), std::uint8_t{1})) * cell;
    };
    storeys.push_back({{"floor_y", s.floor_y},
                       {"ceiling_y", s.ceiling_y},
                       {"room_m2", square_metres(f.room)}});
  }
  if (storeys.empty()) storeys.push_back({{"floor_y", nullptr}, {"ceiling_y", nullptr}});
  json rooms = json::array();
  for (std::size_t k = 0; k < r.rooms.size(); ++k) {
    const Room& room = r.rooms[k];
    json entry = {{"storey", room.storey},
                  {"floor_area_m2", room.floor_area},
                  {"center", vec(room.center)},
                  {"floor_y", room.floor_y},
                  {"ceiling_y", room.ceiling_y}};
    if (k < r.room_bounds.size())
      entry["bounds"] = bounds_json(r.room_bounds[k], r.ok());
    rooms.push_back(std::move(entry));
  }
  const StageTimings& t = r.timings;
  json doc = {
      {"schema", "roomsense.analysis/1"},
      {"status", r.ok() ? "ok" : "no_floor_ceiling"},
      {"message", r.status_message},
      {"warnings", r.warnings},
      {"input",
       {{"file", source.file},
        {"vertices", r.input.vertices},
        {"triangles", r.input.triangles},
        {"skipped_vertices", r.input.skipped_vertices},
        {"outlier_vertices", r.input.outlier_vertices},
        {"dropped_triangles", r.input.dropped_triangles},
        {"mode", r.mode == VoxelMode::Triangles ? "triangles" : "vertices"}}},
      {"grid",
       {{"voxel_size", g.voxel_size},
        {"origin", {g.origin.x, g.origin.y, g.origin.z}},
        {"dims", {g.nx, g.ny, g.nz}},
        {"backend", r.backend},
        {"voxel_tests", r.voxels.voxel_tests}}},
      {"floor_y", height(r.floor_y, r.ok())},
      {"ceiling_y", height(r.ceiling_y, r.ok())},
      {"storeys", storeys},
      {"rooms", rooms},
      {"areas", areas_json(r.areas)},
      {"area_counts",
       {{"found", r.area_counts.found}, {"deduplicated", r.area_counts.deduplicated}, {"reduced", r.area_counts.reduced}}},
      {"bounds", bounds_json(r.bounds, r.ok())},
      {"timings_ms",
       {{"load", source.load_ms},
        {"prepare", t.prepare},
        {"voxelize", t.voxelize},
        {"features", t.features},
        {"areas", t.areas},
        {"reduce", t.reduce},
        {"classify", t.classify},
        {"bounds", t.bounds},
        {"total_compute", t.total}}},
  };
  for (const auto& [name, value] : members) {
    nlohmann::json parsed = json::parse(value, nullptr, false);
    if (parsed.is_discarded()) throw Error(ErrorCode::BadParameter, "the JSON member " + name + " is not JSON");
    doc[name] = std::move(parsed);
  }
  return doc.dump(2);
}

}  // namespace roomsense
