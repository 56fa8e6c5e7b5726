#include "summary.h"

#include "roomsense/number_text.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <iterator>
#include <numeric>

namespace roomsense::cli {
namespace {

template <class... Args>
std::string format(const char* fmt, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

std::size_t count_set(const std::vector<std::uint8_t>& v) { return std::size_t(std::count(v.begin(), v.end(), 1)); }

// Areas per type, by size and by reach: the full list is in the JSON.
std::string areas_summary(const std::vector<Area>& areas, const std::string& indent) {
  std::string out = indent + format("  areas     %zu placement areas   large medium small | close distance none\n", areas.size());
  for (const AreaType type : kAreaTypes) {
    std::array<int, 3> sizes{}, reach{};
    for (const Area& a : areas)
      if (a.type == type) ++sizes[std::size_t(a.size) - 1], ++reach[std::size_t(a.reach) - 1];
    out += indent + format("            %-24s %5d %6d %5d | %5d %8d %4d\n", std::string(to_string(type)).c_str(), sizes[0],
                  sizes[1], sizes[2], reach[0], reach[1], reach[2]);
  }
  return out;
}

// The rooms of storey `storey`, a line each, with their areas per type.
std::string rooms_summary(const AnalysisResult& r, std::size_t storey, const std::string& indent) {
  std::size_t count = 0;
  for (const Room& room : r.rooms) count += room.storey == storey ? 1 : 0;
  std::string out = indent + format("  rooms     %zu (split at passages up to %s m wide; numbered as in the JSON)\n",
                                    count, fixed_or_g(FeatureParams{}.min_passage, 2).c_str());
  for (std::size_t k = 0; k < r.rooms.size(); ++k) {
    const Room& room = r.rooms[k];
    if (room.storey != storey) continue;
    std::array<int, 4> by_type{};
    for (const Area& a : r.areas)
      if (a.room == int(k)) ++by_type[std::size_t(a.type) - 1];
    out += indent + format("            room %-3zu %6s m2 at (%s, %s): %d wall, %d floor, %d ceiling, %d furniture areas\n",
                           k, fixed_or_g(room.floor_area, 1).c_str(), fixed_or_g(room.center.x, 1).c_str(),
                           fixed_or_g(room.center.z, 1).c_str(), by_type[0], by_type[1], by_type[2], by_type[3]);
  }
  return out;
}

}  // namespace

std::string summary(const AnalysisResult& r, const std::string& source, double load_ms) {
  const GridSpec& g = r.voxels.grid.spec;
  const double tile = double(g.voxel_size) * double(g.voxel_size);
  std::string out = "roomsense analysis of " + source + "\n";
  out += format("  input     %zu vertices, %zu triangles (%s mode)\n", r.input.vertices, r.input.triangles,
                r.mode == VoxelMode::Triangles ? "triangle" : "vertex");
  for (const std::string& w : r.warnings) out += "  warning   " + w + "\n";
  out += format("  grid      %d x %d x %d voxels of %s m (%s backend)\n", g.nx, g.ny, g.nz,
                fixed_or_g(g.voxel_size, 2).c_str(), r.backend.c_str());
  if (!r.ok()) return out + "  status    " + r.status_message + "\n";
  out += format("  floor     y = %s m\n  ceiling   y = %s m (room height %s m)\n", fixed_or_g(r.floor_y, 2).c_str(),
                fixed_or_g(r.ceiling_y, 2).c_str(), fixed_or_g(double(r.ceiling_y) - double(r.floor_y), 2).c_str());
  // With several storeys each gets its own block, bottom to top, indented under its heading.
  const bool several = r.storeys.size() > 1;
  std::vector<std::size_t> order(r.storeys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return r.storeys[a].floor_y < r.storeys[b].floor_y; });
  if (several) out += format("  storeys   %zu, bottom to top (the main one is the thesis's floor and ceiling)\n", r.storeys.size());
  for (const std::size_t i : order) {
    const Storey& s = r.storeys[i];
    const RoomFeatures& f = r.storey_features(i);
    const std::string indent = several ? "  " : "";
    if (several)
      out += format("  storey %zu  floor y = %s m, ceiling y = %s m (height %s m)%s\n", i + 1,
                    fixed_or_g(s.floor_y, 2).c_str(), fixed_or_g(s.ceiling_y, 2).c_str(),
                    fixed_or_g(double(s.ceiling_y) - double(s.floor_y), 2).c_str(), i == 0 ? ", main" : "");
    const std::size_t furniture =
        std::size_t(std::count_if(f.furniture.begin(), f.furniture.end(), [](int c) { return c != kNoFurniture; }));
    const std::size_t normals =
        std::size_t(std::count_if(f.normals.begin(), f.normals.end(), [](std::uint8_t n) { return n != 0; }));
    const auto line = [&](const char* label, const std::string& text) { out += indent + "  " + label + text + "\n"; };
    line("room      ", fixed_or_g(double(count_set(f.room)) * tile, 1) + " m2 inside the walls");
    line("walls     ", format("%zu wall columns, %zu voxels facing into the room", count_set(f.walls), normals));
    line("floor     ", fixed_or_g(double(count_set(f.free_floor)) * tile, 1) + " m2 free floor (1.5 m clear above)");
    line("ceiling   ", fixed_or_g(double(count_set(f.free_ceiling)) * tile, 1) + " m2 free ceiling (1 m clear below)");
    line("furniture ", fixed_or_g(double(furniture) * tile, 1) + " m2 of furniture tops below 1.5 m");
    std::vector<Area> areas;
    std::copy_if(r.areas.begin(), r.areas.end(), std::back_inserter(areas), [&](const Area& a) { return a.storey == i; });
    out += areas_summary(areas, indent);
    out += rooms_summary(r, i, indent);
  }
  const std::size_t bt = r.bounds.indices.size() / 3;
  out += format("  bounds    %zu vertices, %zu triangles, %s", r.bounds.vertices.size(), bt,
                check_closure(r.bounds).closed() ? "closed" : "NOT closed");
  if (r.input.triangles > 0 && bt > 0) out += format(" (%sx fewer triangles than the scan)", fixed_or_g(double(r.input.triangles) / double(bt), 1).c_str());
  out += "\n";
  const StageTimings& t = r.timings;
  out += format("  time      load %.1f ms; voxelize %.2f, features %.2f, areas %.2f, reduce %.2f, classify %.2f,"
                " bounds %.2f, total %.2f ms\n",
                load_ms, t.voxelize, t.features, t.areas, t.reduce, t.classify, t.bounds, t.total);
  return out;
}

}  // namespace roomsense::cli
