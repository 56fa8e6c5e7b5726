#include "place_command.h"

#include "analyze_command.h"
#include "options.h"
#include "roomsense/error.h"
#include "roomsense/queries.h"
#include "roomsense/report.h"

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace roomsense::cli {

const char* const kPlaceUsage = R"(usage: roomsense place SCAN --size WxDxH [options] [analyze's options]

Analyses SCAN, then finds where an object fits: poses on free surface, best first, each footprint fully on
free surface of the asked kind with the asked clearance, never overlapping another (issue 16's queries).

  --size WxDxH          the object in metres: W x D its footprint on the surface (on a wall, W along it and
                        D up it), H its height along the surface's normal (on a wall, how far it stands out)
  --on KINDS            wall, floor, ceiling, furniture or any, or a comma-separated list (default any)
  --reach R             close, distance or any (default any)
  --count N             how many placements, 1 to 1024 (default 1)
  --clearance M         free space around the footprint (default 0)
  --clearance-above M   free space above the object's height (default 0)
  --edge M              distance from the footprint to the free surface's edge (default 0)
  --user X,Y,Z          judge reach from this position (default: from any free floor)
  --user-reach M        the user's reach with --user (default 0.7)
  --near X,Y,Z          best first means nearest this point (default: most free space around)
  --face X,Y,Z          horizontal footprints turn their +Y along this direction; walls facing it first
  --seed N              breaks ties between equally good spots (default 0)
  --overlap             placements may overlap
  --json OUT.json       write the placements (schema roomsense.placements/1)
  --report DIR          write plan.svg and scene.glb with the placements drawn
Every option of `roomsense analyze` (--up, --units, --voxel, --no-labels, --backend, ...) applies to the
analysis. Poses are in the scan's frame after conversion; +Z is the surface's normal. A query the room
cannot satisfy prints why and exits 0; bad usage exits 2, bad input 1.
)";

namespace {

glm::vec3 parse_vec3(const std::string& flag, const std::string& text) {
  glm::vec3 v(0.0f);
  std::istringstream in(text);
  char comma = 0;
  if (!(in >> v.x >> comma >> v.y) || comma != ',' || !(in >> comma >> v.z) || comma != ',' || !in.eof() ||
      !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw std::invalid_argument(flag + " needs X,Y,Z, not '" + text + "'");
  return v;
}

float parse_metres(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const float v = std::strtof(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0') throw std::invalid_argument(flag + " needs a number, not '" + text + "'");
  return v;
}

std::uint32_t parse_surfaces(const std::string& text) {
  std::uint32_t bits = 0;
  std::istringstream in(text);
  for (std::string kind; std::getline(in, kind, ',');) {
    if (kind == "wall") bits |= kOnWall;
    else if (kind == "floor") bits |= kOnFloor;
    else if (kind == "ceiling") bits |= kOnCeiling;
    else if (kind == "furniture") bits |= kOnFurniture;
    else if (kind == "any") bits |= kOnAnySurface;
    else throw std::invalid_argument("--on takes wall, floor, ceiling, furniture or any, not '" + kind + "'");
  }
  if (bits == 0) throw std::invalid_argument("--on needs at least one surface kind");
  return bits;
}

// Takes place's own options out of `args`; what is left is analyze's.
PlacementQuery parse_query(std::vector<std::string>& args) {
  PlacementQuery q;
  bool sized = false;
  std::vector<std::string> rest;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "--size") {
      const std::string text = value();
      std::istringstream in(text);
      char x1 = 0, x2 = 0;
      if (!(in >> q.size.x >> x1 >> q.size.y >> x2 >> q.size.z) || x1 != 'x' || x2 != 'x' || !in.eof())
        throw std::invalid_argument("--size needs WxDxH in metres, e.g. 0.6x0.4x0.3, not '" + text + "'");
      sized = true;
    } else if (a == "--on") q.surfaces = parse_surfaces(value());
    else if (a == "--reach") {
      const std::string& v = value();
      if (v == "any") q.reach = ReachFilter::Any;
      else if (v == "close") q.reach = ReachFilter::Close;
      else if (v == "distance") q.reach = ReachFilter::Distance;
      else throw std::invalid_argument("--reach takes close, distance or any, not '" + v + "'");
    } else if (a == "--count") {
      const std::string& v = value();
      const float n = parse_metres(a, v);
      if (!(n >= 1.0f && n <= float(kMaxPlacements)) || n != std::floor(n))
        throw std::invalid_argument("--count takes a whole number from 1 to " + std::to_string(kMaxPlacements) + ", not '" + v + "'");
      q.max_count = std::uint32_t(n);
    } else if (a == "--clearance") q.clearance = parse_metres(a, value());
    else if (a == "--clearance-above") q.clearance_above = parse_metres(a, value());
    else if (a == "--edge") q.edge_distance = parse_metres(a, value());
    else if (a == "--user") q.user_position = parse_vec3(a, value());
    else if (a == "--user-reach") q.user_reach = parse_metres(a, value());
    else if (a == "--near") q.near = parse_vec3(a, value());
    else if (a == "--face") q.face_direction = parse_vec3(a, value());
    else if (a == "--seed") {
      const std::string& v = value();
      char* end = nullptr;
      q.seed = std::strtoull(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || v[0] == '-') throw std::invalid_argument("--seed needs a whole number, not '" + v + "'");
    } else if (a == "--overlap") q.allow_overlap = true;
    else rest.push_back(a);
  }
  if (!sized) throw std::invalid_argument("place needs --size WxDxH");
  args = std::move(rest);
  return q;
}

nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }

std::string placements_json(const std::string& source, const PlacementQuery& q, const PlacementResult& r) {
  nlohmann::json doc;
  doc["schema"] = "roomsense.placements/1";
  doc["input"] = {{"file", source}};
  doc["query"] = {{"size", vec(q.size)},       {"surfaces", q.surfaces},       {"clearance", q.clearance},
                  {"clearance_above", q.clearance_above}, {"edge_distance", q.edge_distance},
                  {"reach", q.reach == ReachFilter::Any ? "any" : std::string(to_string(Reach(q.reach)))},
                  {"max_count", q.max_count}, {"seed", q.seed}};
  doc["placements"] = nlohmann::json::array();
  for (const Placement& p : r.placements) {
    const glm::quat o = p.orientation();
    nlohmann::json corners = nlohmann::json::array();
    for (const glm::vec3& c : p.corners()) corners.push_back(vec(c));
    doc["placements"].push_back({{"surface", to_string(p.surface)}, {"reach", to_string(p.reach)},
                                 {"storey", p.storey}, {"center", vec(p.center)}, {"normal", vec(p.normal)},
                                 {"x_axis", vec(p.x_axis)}, {"orientation", {o.x, o.y, o.z, o.w}},
                                 {"corners", corners}, {"footprint", {p.footprint.x, p.footprint.y}},
                                 {"margin", p.margin}});
  }
  doc["shortfall"] = to_string(r.shortfall);
  doc["reason"] = r.reason;
  return doc.dump(2);
}

}  // namespace

int place_command(const std::vector<std::string>& given) {
  std::vector<std::string> args = given;
  PlacementQuery query;
  AnalyzeOptions options;
  try {
    query = parse_query(args);
    options = parse_analyze_options(args);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "roomsense place: %s (see roomsense place --help)\n", e.what());
    return 2;
  }
  const char* step = "reading";
  try {
    const LoadedAnalysis loaded = load_and_analyze(options, step);
    if (!loaded.result.ok()) {
      std::fprintf(stderr, "roomsense place: %s: %s\n", options.scan.c_str(), loaded.result.status_message.c_str());
      return 1;
    }
    step = "querying";
    const RoomQueries queries(loaded.result);
    PlacementResult found;
    try {
      found = queries.find_placements(query);
    } catch (const Error& e) {
      if (e.code() != ErrorCode::BadParameter) throw;
      std::fprintf(stderr, "roomsense place: %s (see roomsense place --help)\n", e.what());
      return 2;
    }
    for (std::size_t i = 0; i < found.placements.size(); ++i) {
      const Placement& p = found.placements[i];
      const glm::quat o = p.orientation();
      std::printf("%3zu  %-9s  %-8s  at (%6.2f, %5.2f, %6.2f)  normal (%5.2f, %5.2f, %5.2f)  orientation (%6.3f, %6.3f, %6.3f, %6.3f)  margin %.2f m\n",
                  i + 1, to_string(p.surface).data(), to_string(p.reach).data(), double(p.center.x), double(p.center.y),
                  double(p.center.z), double(p.normal.x), double(p.normal.y), double(p.normal.z), double(o.x),
                  double(o.y), double(o.z), double(o.w), double(p.margin));
    }
    if (found.shortfall != PlacementShortfall::None)
      std::printf("found %zu of %u: %s: %s\n", found.placements.size(), query.max_count, to_string(found.shortfall).data(),
                  found.reason.c_str());
    step = "writing the results of";
    if (options.json_path) {
      std::ofstream file(*options.json_path);
      if (!file || !(file << placements_json(options.scan, query, found) << '\n'))
        throw Error(ErrorCode::Io, "cannot write '" + *options.json_path + "'");
    }
    if (options.report_dir) {
      ReportInput report = report_input(loaded.result, loaded.scan, report_title(options.scan));
      report.placements = found.placements;
      write_report(report, *options.report_dir);
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "roomsense place: %s\n", e.what());
    return 1;
  } catch (const std::invalid_argument& e) {  // ROOMSENSE_BACKEND
    std::fprintf(stderr, "roomsense place: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "roomsense place: out of memory %s '%s'\n", step, options.scan.c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomsense place: %s '%s': %s\n", step, options.scan.c_str(), e.what());
    return 1;
  }
}

}  // namespace roomsense::cli
