#include "results.h"

#include "log.h"
#include "roomsense/export.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>

namespace roomsense::layer {
namespace {

std::uint32_t clamp32(std::size_t n) {
  return static_cast<std::uint32_t>(std::min<std::size_t>(n, std::numeric_limits<std::uint32_t>::max()));
}

XrRoomAreaEXTX to_xr(const Area& a) {
  XrRoomAreaEXTX out{};
  out.type = XR_TYPE_ROOM_AREA_EXTX;
  out.next = nullptr;
  const glm::quat q = a.orientation();
  out.pose.orientation = {q.x, q.y, q.z, q.w};
  out.pose.position = {a.center.x, a.center.y, a.center.z};
  out.extents = {2.0f * a.half_width, 2.0f * a.half_height};
  out.volumeHeight = a.volume_height;
  // The core's enums carry the extension's values (areas.h).
  out.areaType = static_cast<XrRoomAreaTypeEXTX>(a.type);
  out.size = static_cast<XrRoomAreaSizeEXTX>(a.size);
  out.interaction = static_cast<XrRoomInteractionEXTX>(a.reach);
  out.categoryFlags = a.flags;
  return out;
}

}  // namespace

const char* space_name(XrReferenceSpaceType type) {
  switch (type) {
    case XR_REFERENCE_SPACE_TYPE_LOCAL: return "LOCAL";
    case XR_REFERENCE_SPACE_TYPE_STAGE: return "STAGE";
    case XR_REFERENCE_SPACE_TYPE_UNBOUNDED_MSFT: return "UNBOUNDED_MSFT";
    default: return static_cast<int>(type) == 1000426000 ? "LOCAL_FLOOR_EXT" : "other";
  }
}

const std::vector<Surface>& LazyResultParts::surfaces() const {
  std::call_once(surfaces_once_, [&] { surfaces_ = extract_surfaces(*analysis_); });
  return surfaces_;
}

const RoomQueries& LazyResultParts::queries() const {
  std::call_once(queries_once_, [&] {
    queries_ = analysis_->ok() ? RoomQueries(*analysis_, surfaces()) : RoomQueries(*analysis_);
  });
  return queries_;
}

const std::string& LazyResultParts::json() const {
  std::call_once(json_once_, [&] {
    const nlohmann::json openxr = {{"base_space", sources_.base_space},
                                   {"mesh_source", sources_.source},
                                   {"mesh_source_reason", sources_.source_reason},
                                   {"mesh_query_ms", sources_.query_ms},
                                   {"runtime_meshes", sources_.runtime_meshes},
                                   {"app_read_meshes", sources_.app_read_meshes},
                                   {"submitted_meshes", sources_.submitted_meshes},
                                   {"compute_ms", double(duration_) / 1e6}};
    json_ = analysis_json(*analysis_, {kJsonSourceName, 0.0}, {{"openxr", openxr.dump()}});
  });
  return json_;
}

RoomResult make_room_result(std::shared_ptr<const AnalysisResult> analysis, const MeshSources& sources,
                            XrDuration duration) {
  const AnalysisResult& r = *analysis;
  RoomResult out;
  out.floor_y = r.floor_y;
  out.ceiling_y = r.ceiling_y;
  for (const Storey& s : r.storeys) out.storeys.push_back({s.floor_y, s.ceiling_y});
  for (const Room& room : r.rooms)
    out.rooms.push_back({room.storey, room.floor_area, {room.center.x, room.center.y, room.center.z}, room.floor_y,
                         room.ceiling_y});
  out.areas.reserve(r.areas.size());
  for (const Area& a : r.areas) {
    out.areas.push_back(to_xr(a));
    out.area_locations.push_back({XR_TYPE_ROOM_AREA_LOCATION_EXTX, nullptr, a.storey,
                                  a.room == kNoRoom ? XR_ROOM_INDEX_NONE_EXTX : static_cast<std::uint32_t>(a.room)});
  }
  out.bounds_vertices.reserve(r.bounds.vertices.size());
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const glm::vec3& v : r.bounds.vertices) {
    out.bounds_vertices.push_back({v.x, v.y, v.z});
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  if (!r.bounds.vertices.empty()) {
    out.bounds_min = {lo.x, lo.y, lo.z};
    out.bounds_max = {hi.x, hi.y, hi.z};
  }
  out.bounds_indices = r.bounds.indices;
  for (const BoundsMesh& mesh : r.room_bounds) {
    RoomResult::Mesh& m = out.room_bounds.emplace_back();
    m.vertices.reserve(mesh.vertices.size());
    for (const glm::vec3& v : mesh.vertices) m.vertices.push_back({v.x, v.y, v.z});
    m.indices = mesh.indices;
  }
  out.input_vertices = clamp32(r.input.vertices);
  out.input_triangles = clamp32(r.input.triangles);
  out.duration = duration;
  out.lazy = std::make_shared<const LazyResultParts>(std::move(analysis), sources, duration);
  return out;
}

void export_files(const std::string& dir, const RoomResult& result, const BoundsMesh& bounds) {
  try {
    std::filesystem::create_directories(dir);
    const std::filesystem::path json_path = std::filesystem::path(dir) / "analysis.json";
    {
      std::ofstream out(json_path);
      if (!out || !(out << result.json() << '\n')) throw std::runtime_error("cannot write " + json_path.string());
    }
    write_obj(bounds, (std::filesystem::path(dir) / "bounds.obj").string());
    log_info("exported analysis.json and bounds.obj to " + dir);
  } catch (const std::exception& e) {
    log_warn(std::string("ROOMSENSE_EXPORT_DIR: ") + e.what());
  }
}

}  // namespace roomsense::layer
