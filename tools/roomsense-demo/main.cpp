// roomsense-demo [--spatial-entities] [--output DIR] [--runtime MANIFEST] [--runtime-extensions LIST] [ROOMFILE]
//
// A real OpenXR application: through the Khronos loader, the simulated runtime (serving ROOMFILE, or the
// built-in default room) and the implicit roomsense layer, it enables XR_EXTX_room_understanding, computes
// the room from the runtime's scene meshes, prints the classified placement areas and the room bounds, and
// writes analysis.json, bounds.obj, bounds.glb, plan.svg and scene.glb into the output folder.
// With --spatial-entities it is instead an app that knows only the standard spatial-entity API (XR_EXT_future,
// XR_EXT_spatial_entity, XR_EXT_spatial_plane_tracking; spatial_entities.h): it prints the planes of a
// plane-tracking context and, where listed, the placement areas and room mesh of the layer's
// XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX, with two timings, and writes spatial_entities.json.
#include "environment.h"
#include "room_app.h"
#include "spatial_entities.h"

#include "roomsense/areas.h"
#include "roomsense/queries.h"
#include "roomsense/bounds.h"
#include "roomsense/export.h"
#include "roomsense/platform.h"
#include "roomsense/report.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace roomsense;

constexpr const char* kUsage =
    "usage: roomsense-demo [--spatial-entities] [--output DIR] [--runtime MANIFEST] [--runtime-extensions LIST] [ROOMFILE]\n"
    "  ROOMFILE   a room for the simulated runtime: OBJ, PLY, glTF/GLB, a Quest capture .json, or\n"
    "             synthetic:NAME (default: synthetic:default, the built-in 5 x 4 m room)\n"
    "  --spatial-entities\n"
    "             be an app that knows only the standard API (XR_EXT_spatial_entity, XR_EXT_spatial_plane_tracking):\n"
    "             print the planes (and the placement areas and room mesh of XR_SPATIAL_CAPABILITY_PLACEMENT_AREAS_EXTX\n"
    "             where listed) and write spatial_entities.json, instead of the XR_EXTX_room_understanding analysis\n"
    "  --output   where to write analysis.json, bounds.obj, bounds.glb, plan.svg, scene.glb, or with --spatial-entities\n"
    "             spatial_entities.json (default: demo-output)\n"
    "  --runtime  another OpenXR runtime's manifest (default: the simulated runtime beside this program)\n"
    "  --runtime-extensions LIST\n"
    "             the scene extensions the simulated runtime offers, comma-separated, to play a given headset\n"
    "             (sets ROOMSENSE_SIM_EXTENSIONS; default: all it serves), e.g. XR_META_spatial_entity_mesh\n";

struct Options {
  std::string room = "synthetic:default";
  std::string output = "demo-output";
  std::string runtime;
  std::string runtime_extensions;
  bool spatial_entities = false;
};

Options parse(int argc, char** argv) {
  Options o;
  bool room_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (a == "--spatial-entities") {
      o.spatial_entities = true;
    } else if ((a == "--output" || a == "--runtime") && i + 1 < argc) {
      (a == "--output" ? o.output : o.runtime) = argv[++i];
    } else if (a == "--runtime-extensions" && i + 1 < argc) {
      o.runtime_extensions = argv[++i];
      if (o.runtime_extensions.empty()) throw std::invalid_argument("--runtime-extensions needs at least one extension");
    } else if (!a.empty() && a[0] != '-' && !room_given) {
      o.room = a;
      room_given = true;
    } else {
      throw std::invalid_argument("unexpected argument '" + a + "'");
    }
  }
  // A file is handed to the runtime by absolute path: the loader may run it from anywhere.
  if (o.room.rfind("synthetic:", 0) != 0) {
    if (!fs::exists(o.room)) throw std::invalid_argument("no such room file: " + o.room);
    o.room = fs::absolute(o.room).string();
  }
  return o;
}

const char* type_name(XrRoomAreaTypeEXTX t) { return to_string(static_cast<AreaType>(t)).data(); }
const char* size_name(XrRoomAreaSizeEXTX s) { return to_string(static_cast<AreaSize>(s)).data(); }
const char* reach_name(XrRoomInteractionEXTX r) { return to_string(static_cast<Reach>(r)).data(); }

void print_report(const demo::Setup& setup, const demo::RoomReport& r, const std::string& room) {
  const XrRoomLayoutEXTX& l = r.layout;
  std::printf("runtime     %s (XR_RUNTIME_JSON=%s)\n", r.runtime_name.c_str(), setup.runtime_manifest.c_str());
  std::printf("layer       %s (manifest found through XDG_DATA_DIRS in %s)\n", r.layer_library.c_str(),
              setup.layer_search_dir.c_str());
  std::printf("room        %s\n", room.c_str());
  std::printf("input       %u vertices, %u triangles of the runtime's scene meshes\n", l.inputVertexCount,
              l.inputTriangleCount);
  const auto openxr = nlohmann::json::parse(r.json).value("openxr", nlohmann::json::object());
  std::printf("source      %s: %s\n", openxr.value("mesh_source", std::string("none")).c_str(),
              openxr.value("mesh_source_reason", std::string()).c_str());
  std::printf("floor       y = %.2f m\n", double(l.floorHeight));
  std::printf("ceiling     y = %.2f m (room height %.2f m, %u storey%s)\n", double(l.ceilingHeight),
              double(l.ceilingHeight - l.floorHeight), l.storeyCount, l.storeyCount == 1 ? "" : "s");
  std::printf("compute     %.1f ms through the layer (scene query and analysis), %d frames ran meanwhile\n",
              double(l.computeDuration) / 1e6, r.frames);

  std::size_t count[5][4] = {};
  for (const auto& a : r.areas)
    if (a.areaType >= 1 && a.areaType <= 4 && a.size >= 1 && a.size <= 3) ++count[a.areaType][a.size], ++count[a.areaType][0];
  std::printf("areas       %zu placement areas\n", r.areas.size());
  for (int t = 1; t <= 4; ++t)
    std::printf("            %-9s %3zu  (large %zu, medium %zu, small %zu)\n", type_name(XrRoomAreaTypeEXTX(t)), count[t][0],
                count[t][1], count[t][2], count[t][3]);
  std::printf("\n   #  type       size    reach     centre x, y, z (m)          width x height (m)\n");
  for (std::size_t i = 0; i < r.areas.size(); ++i) {
    const XrRoomAreaEXTX& a = r.areas[i];
    std::printf("%4zu  %-9s  %-6s  %-8s  (%6.2f, %5.2f, %6.2f)      %.2f x %.2f\n", i + 1, type_name(a.areaType),
                size_name(a.size), reach_name(a.interaction), double(a.pose.position.x), double(a.pose.position.y),
                double(a.pose.position.z), double(a.extents.width), double(a.extents.height));
  }
  BoundsMesh bounds;
  for (const auto& v : r.bounds_vertices) bounds.vertices.push_back({v.x, v.y, v.z});
  bounds.indices = r.bounds_indices;
  const MeshClosure closure = check_closure(bounds);
  std::printf("\nbounds      %zu vertices, %zu triangles, %s; box (%.2f, %.2f, %.2f) to (%.2f, %.2f, %.2f)\n",
              bounds.vertices.size(), bounds.indices.size() / 3, closure.closed() ? "closed" : "NOT closed",
              double(l.boundsMin.x), double(l.boundsMin.y), double(l.boundsMin.z), double(l.boundsMax.x),
              double(l.boundsMax.y), double(l.boundsMax.z));
  if (l.inputTriangleCount > 0 && !bounds.indices.empty())
    std::printf("            %.1fx fewer triangles than the scene meshes\n",
                double(l.inputTriangleCount) / double(bounds.indices.size() / 3));

  const XrRoomPlacementQueryEXTX& q = r.placement_query;
  std::printf("\nplace       xrFindRoomPlacementsEXTX: %u spots for a %.2f x %.2f x %.2f m object on furniture tops: %zu found%s\n",
              q.maxPlacements, double(q.objectSize.x), double(q.objectSize.y), double(q.objectSize.z), r.placements.size(),
              r.placement_shortfall == XR_ROOM_PLACEMENT_SHORTFALL_NONE_EXTX
                  ? ""
                  : (std::string(" (") + std::string(to_string(static_cast<PlacementShortfall>(r.placement_shortfall))) + ")").c_str());
  for (std::size_t i = 0; i < r.placements.size(); ++i) {
    const XrRoomPlacementEXTX& p = r.placements[i];
    std::printf("%4zu  %-9s  %-8s  at (%6.2f, %5.2f, %6.2f)  orientation (%.3f, %.3f, %.3f, %.3f)\n", i + 1,
                type_name(p.surfaceType), reach_name(p.interaction), double(p.pose.position.x), double(p.pose.position.y),
                double(p.pose.position.z), double(p.pose.orientation.x), double(p.pose.orientation.y),
                double(p.pose.orientation.z), double(p.pose.orientation.w));
  }
}

void write_files(const demo::RoomReport& r, const std::string& room, const fs::path& dir) {
  fs::create_directories(dir);
  {
    std::ofstream json(dir / "analysis.json");
    if (!json || !(json << r.json << '\n')) throw std::runtime_error("cannot write " + (dir / "analysis.json").string());
  }
  BoundsMesh bounds;
  for (const auto& v : r.bounds_vertices) bounds.vertices.push_back({v.x, v.y, v.z});
  bounds.indices = r.bounds_indices;
  write_obj(bounds, (dir / "bounds.obj").string());
  write_glb(bounds, (dir / "bounds.glb").string());

  // The pictures, from what the extension returned (no voxel features, no scan: the app never saw them).
  std::vector<Area> areas;
  for (const auto& a : r.areas)
    areas.push_back(area_from_pose(static_cast<AreaType>(a.areaType), static_cast<AreaSize>(a.size),
                                   static_cast<Reach>(a.interaction), {a.pose.position.x, a.pose.position.y, a.pose.position.z},
                                   glm::quat(a.pose.orientation.w, a.pose.orientation.x, a.pose.orientation.y, a.pose.orientation.z),
                                   a.extents.width, a.extents.height));
  // The placements xrFindRoomPlacementsEXTX returned, as the object's pose and box.
  std::vector<Placement> placements;
  for (const XrRoomPlacementEXTX& p : r.placements) {
    const glm::quat q(p.pose.orientation.w, p.pose.orientation.x, p.pose.orientation.y, p.pose.orientation.z);
    Placement pl;
    pl.surface = static_cast<AreaType>(p.surfaceType);
    pl.reach = static_cast<Reach>(p.interaction);
    pl.storey = p.storeyIndex;
    pl.center = {p.pose.position.x, p.pose.position.y, p.pose.position.z};
    pl.normal = q * glm::vec3(0.0f, 0.0f, 1.0f);
    pl.x_axis = q * glm::vec3(1.0f, 0.0f, 0.0f);
    pl.footprint = {p.extents.width, p.extents.height};
    pl.height = r.placement_query.objectSize.z;
    pl.margin = p.margin;
    placements.push_back(pl);
  }
  ReportInput report;
  report.title = room + " (through OpenXR)";
  report.placements = placements;
  report.floor_y = r.layout.floorHeight;
  report.ceiling_y = r.layout.ceilingHeight;
  report.areas = areas;
  report.bounds = &bounds;
  write_report(report, dir.string());
  std::printf("wrote %s: analysis.json, bounds.obj, bounds.glb, %s, %s\n", dir.string().c_str(), kPlanSvgName.data(),
              kSceneGlbName.data());
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomsense-demo: %s\n%s", e.what(), kUsage);
    return 2;
  }
  try {
    if (!options.runtime_extensions.empty()) platform::set_environment("ROOMSENSE_SIM_EXTENSIONS", options.runtime_extensions);
    const demo::Setup setup = demo::prepare_environment(options.runtime, options.room);
    std::printf("roomsense-demo: an OpenXR app through the Khronos loader, the %s runtime and the roomsense layer\n",
                options.runtime.empty() ? "simulated" : "given");
    for (const std::string& note : setup.notes) std::printf("note        %s\n", note.c_str());
    if (options.spatial_entities) {
      std::printf("mode        --spatial-entities: the standard spatial-entity API only\n");
      demo::run_spatial_entities(options.room, options.output);
      return 0;
    }
    const demo::RoomReport report = demo::analyse_room_through_openxr();
    print_report(setup, report, options.room);
    write_files(report, options.room, options.output);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomsense-demo: %s\n", e.what());
    return 1;
  }
}
