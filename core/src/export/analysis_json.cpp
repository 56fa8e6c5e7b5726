// The CLI's JSON, schema roomsense.analysis/1 (DESIGN.md). Extra members beyond the contract: status,
// message, warnings, input.{outlier_vertices, dropped_triangles, mode}, grid.backend, bounds.closed.
#include "roomsense/export.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace roomsense {
namespace {

nlohmann::json height(float y, bool ok) { return ok && std::isfinite(y) ? nlohmann::json(y) : nlohmann::json(nullptr); }

}  // namespace

std::string analysis_json(const AnalysisResult& r, const JsonSource& source) {
  using nlohmann::json;
  const GridSpec& g = r.voxels.grid.spec;
  json storeys = json::array();
  for (const Storey& s : r.storeys) storeys.push_back({{"floor_y", s.floor_y}, {"ceiling_y", s.ceiling_y}});
  if (storeys.empty()) storeys.push_back({{"floor_y", nullptr}, {"ceiling_y", nullptr}});
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
        {"backend", r.backend}}},
      {"floor_y", height(r.floor_y, r.ok())},
      {"ceiling_y", height(r.ceiling_y, r.ok())},
      {"storeys", storeys},
      {"areas", json::array()},
      {"bounds",
       {{"vertices", r.bounds.vertices.size()},
        {"triangles", r.bounds.indices.size() / 3},
        {"closed", r.ok() && check_closure(r.bounds).closed()}}},
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
  return doc.dump(2);
}

}  // namespace roomsense
