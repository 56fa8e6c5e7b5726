// plan.svg: the top view of a room analysis, looking down -Y, with +X to the right and +Z down the page
// (the right-handed frame seen from above). Page units are pixels; world metres map to them by one scale.
#include "report_common.h"
#include "roomsense/report.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace roomsense {
namespace {

// Page layout, in pixels.
constexpr float kMargin = 24.0f;
constexpr float kAxisLabelRoom = 30.0f;  // left of and above the drawing, for the metre grid's labels
constexpr float kLegendGap = 28.0f;
constexpr float kLegendWidth = 250.0f;
constexpr float kMaxDrawingWidth = 1000.0f, kMaxDrawingHeight = 760.0f;
constexpr float kMinScale = 20.0f, kMaxScale = 150.0f;  // pixels per metre
constexpr float kMaxPageSide = 4000.0f;
constexpr float kPadding = 0.25f;                       // metres of room around the drawn content
constexpr float kOutlineAboveFloor = 1.6f;  // the bounds are cut here: above furniture tops (<= 1.5 m)
constexpr float kFloorSearch = 0.5f;  // metres around floor_y where the bounds' floor faces are looked for
constexpr float kSameLevel = 0.02f;   // metres: faces this close in height are one level
// Wall areas project to a line: they are drawn as strips in front of the wall, one lane per size.
constexpr float kWallLane = 0.09f;  // metres

constexpr const char* kFootprintFill = "#e4e4e4";
constexpr const char* kFurnitureFill = "#d8b98f";
constexpr const char* kWallFill = "#6b6b6b";
constexpr const char* kNormalStroke = "#d95f02";
constexpr const char* kOutlineStroke = "#222222";
constexpr const char* kGridStroke = "#9a9a9a";

std::string num(float v, int decimals = 1) {
  if (!std::isfinite(v)) v = 0.0f;
  if (std::fabs(v) < 0.5f * std::pow(10.0f, float(-decimals))) v = 0.0f;  // no "-0.0"
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  return ec == std::errc() ? std::string(buf, end) : std::string("0");
}

// Appends pieces without building temporaries ("M" + std::string trips GCC 12's -Wrestrict).
template <class... Parts>
void append(std::string& out, const Parts&... parts) {
  (out.append(std::string_view(parts)), ...);
}

std::string escape(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0; a file name could hold one.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') out += '?';
        else out += c;
    }
  }
  return out;
}

struct Extent {
  float x0 = INFINITY, z0 = INFINITY, x1 = -INFINITY, z1 = -INFINITY;
  void add(float x, float z) {
    if (!std::isfinite(x) || !std::isfinite(z)) return;
    x0 = std::min(x0, x);
    z0 = std::min(z0, z);
    x1 = std::max(x1, x);
    z1 = std::max(z1, z);
  }
  bool empty() const { return !(x0 <= x1 && z0 <= z1); }
};

// World (x, z) to page pixels.
struct Mapper {
  Extent world;
  float scale = 1.0f;
  float left = 0.0f, top = 0.0f;
  float px(float x) const { return left + (x - world.x0) * scale; }
  float pz(float z) const { return top + (z - world.z0) * scale; }
  std::string point(float x, float z) const { return num(px(x)) + "," + num(pz(z)); }
  float width() const { return (world.x1 - world.x0) * scale; }
  float height() const { return (world.z1 - world.z0) * scale; }
};

bool valid_mesh(const BoundsMesh* m) {
  if (m == nullptr || m->indices.size() % 3 != 0) return false;
  for (const std::uint32_t i : m->indices)
    if (i >= m->vertices.size()) return false;
  return !m->indices.empty();
}

// Features whose sizes match the grid (an app can hand over any).
bool valid_storey_features(const GridSpec& g, const RoomFeatures& f) {
  const std::size_t columns = g.column_count();
  return columns > 0 && f.walls.size() == columns && f.room.size() == columns && f.furniture.size() == columns &&
         (f.normals.empty() || f.normals.size() == g.voxel_count());
}

bool valid_features(const ReportFeatures& v) {
  return v.grid != nullptr && v.features != nullptr && valid_storey_features(*v.grid, *v.features);
}

// One <path> of axis-aligned cells, merged into runs along x per row.
template <class Pred>
std::string cell_path(const GridSpec& g, const Mapper& map, Pred on) {
  std::string d;
  const float s = g.voxel_size;
  for (int z = 0; z < g.nz; ++z)
    for (int x = 0; x < g.nx;) {
      if (!on(x, z)) {
        ++x;
        continue;
      }
      int end = x + 1;
      while (end < g.nx && on(end, z)) ++end;
      const float wx0 = g.origin.x + float(x) * s, wx1 = g.origin.x + float(end) * s;
      const float wz0 = g.origin.z + float(z) * s, wz1 = wz0 + s;
      append(d, "M", map.point(wx0, wz0), "H", num(map.px(wx1)), "V", num(map.pz(wz1)), "H", num(map.px(wx0)), "Z");
      x = end;
    }
  return d;
}

// The segments where the plane y = cut crosses the mesh's triangles. A vertex on the plane counts as above,
// so a triangle yields either no segment or exactly one.
std::string slice_path(const BoundsMesh& m, float cut, const Mapper& map) {
  std::string d;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::vec3 v[3] = {m.vertices[m.indices[t]], m.vertices[m.indices[t + 1]], m.vertices[m.indices[t + 2]]};
    glm::vec2 hits[2];
    int n = 0;
    for (int e = 0; e < 3; ++e) {
      const glm::vec3 &a = v[e], &b = v[(e + 1) % 3];
      if ((a.y >= cut) == (b.y >= cut)) continue;
      const float f = (cut - a.y) / (b.y - a.y);
      if (n < 2) hits[n++] = glm::vec2(a.x + f * (b.x - a.x), a.z + f * (b.z - a.z));
    }
    if (n == 2) append(d, "M", map.point(hits[0].x, hits[0].y), "L", map.point(hits[1].x, hits[1].y));
  }
  return d;
}

// The up-facing faces of the bounds below the cut: the floor (the level within kFloorSearch of floor_y
// with the largest area; where the bounds put it depends on their voxel size) and the raised surfaces above it.
void split_floor_faces(const BoundsMesh& m, float floor_y, std::vector<std::size_t>& floor,
                       std::vector<std::size_t>& raised) {
  std::vector<std::pair<std::size_t, float>> faces;  // (first index, mean y)
  std::map<long, float> area_by_bin;                 // up-facing area per kSameLevel of height
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::vec3 a = m.vertices[m.indices[t]], b = m.vertices[m.indices[t + 1]], c = m.vertices[m.indices[t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float area2 = glm::length(n);
    if (!(area2 > 0.0f) || n.y < 0.9f * area2) continue;  // up-facing only
    const float y = (a.y + b.y + c.y) / 3.0f;
    if (!(y >= floor_y - kFloorSearch && y <= floor_y + kOutlineAboveFloor)) continue;
    faces.emplace_back(t, y);
    area_by_bin[std::lround(y / kSameLevel)] += 0.5f * area2;
  }
  float best_y = floor_y, best_area = 0.0f;
  for (const auto& [bin, unused] : area_by_bin) {
    const float y = float(bin) * kSameLevel;
    if (std::fabs(y - floor_y) > kFloorSearch) continue;
    float area = 0.0f;
    for (long k = bin - 1; k <= bin + 1; ++k)
      if (const auto it = area_by_bin.find(k); it != area_by_bin.end()) area += it->second;
    if (area > best_area) {
      best_area = area;
      best_y = y;
    }
  }
  for (const auto& [t, y] : faces) (y <= best_y + 1.5f * kSameLevel ? floor : raised).push_back(t);
}

std::string triangle_path(const BoundsMesh& m, const std::vector<std::size_t>& triangles, const Mapper& map) {
  std::string d;
  for (const std::size_t t : triangles) {
    const glm::vec3 a = m.vertices[m.indices[t]], b = m.vertices[m.indices[t + 1]], c = m.vertices[m.indices[t + 2]];
    append(d, "M", map.point(a.x, a.z), "L", map.point(b.x, b.z), "L", map.point(c.x, c.z), "Z");
  }
  return d;
}

// The page polygon of an area: horizontal areas their rectangle; walls a strip on the room side of the
// wall, in the lane of their size (large next to the wall, small furthest out).
std::array<glm::vec2, 4> area_outline(const Area& a) {
  const auto xz = [](const glm::vec3& p) { return glm::vec2(p.x, p.z); };
  if (a.type != AreaType::Wall) return {xz(a.corners[0]), xz(a.corners[1]), xz(a.corners[2]), xz(a.corners[3])};
  glm::vec2 n(a.normal.x, a.normal.z);
  const float len = glm::length(n);
  n = len > 1e-6f ? n / len : glm::vec2(0.0f);
  const float lane = float(int(a.size) - 1);
  const glm::vec2 near = n * (lane * kWallLane), far = n * ((lane + 1.0f) * kWallLane);
  // corners[0] -> corners[1] is the lower edge along the wall.
  const glm::vec2 p0 = xz(a.corners[0]), p1 = xz(a.corners[1]);
  return {p0 + near, p1 + near, p1 + far, p0 + far};
}

const char* dash_for(AreaType type) {
  switch (type) {
    case AreaType::Ceiling: return "7 4";
    case AreaType::Furniture: return "2 2.5";
    default: return nullptr;
  }
}

float fill_opacity_for(AreaType type) {
  switch (type) {
    case AreaType::Wall: return 0.6f;
    case AreaType::Ceiling: return 0.10f;
    default: return 0.22f;
  }
}

std::string area_title(std::size_t index, const Area& a) {
  std::string t = "area " + std::to_string(index) + ": " + std::string(to_string(a.type)) + ", " +
                  std::string(to_string(a.size)) + ", reach " + std::string(to_string(a.reach)) + "; " +
                  num(2.0f * a.half_width, 2) + " x " + num(2.0f * a.half_height, 2) + " m; centre (" +
                  num(a.center.x, 2) + ", " + num(a.center.y, 2) + ", " + num(a.center.z, 2) + "); normal (" +
                  num(a.normal.x, 2) + ", " + num(a.normal.y, 2) + ", " + num(a.normal.z, 2) + ")";
  if (a.type == AreaType::Wall) {
    float lo = a.corners[0].y, hi = a.corners[0].y;
    for (const glm::vec3& c : a.corners) {
      lo = std::min(lo, c.y);
      hi = std::max(hi, c.y);
    }
    t += "; from y " + num(lo, 2) + " to " + num(hi, 2) + " m";
  }
  return t;
}

// A metre length for the scale bar that comes out between about 90 and 260 pixels.
float scale_bar_metres(float scale) {
  constexpr float kChoices[] = {0.5f, 1.0f, 2.0f, 5.0f, 10.0f, 20.0f, 50.0f};
  for (const float m : kChoices)
    if (m * scale >= 90.0f) return m;
  return kChoices[std::size(kChoices) - 1];
}

class Page {
 public:
  std::string out;
  void line(const std::string& s) {
    out += s;
    out += '\n';
  }
  void text(float x, float y, const std::string& s, int size = 13, const char* extra = "") {
    line("<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"" + std::to_string(size) + "\"" + extra + ">" +
         escape(s) + "</text>");
  }
  void rect(float x, float y, float w, float h, const std::string& attrs) {
    line("<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(w) + "\" height=\"" + num(h) + "\" " +
         attrs + "/>");
  }
  void segment(float x0, float y0, float x1, float y1, const std::string& attrs) {
    line("<line x1=\"" + num(x0) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(x1) + "\" y2=\"" + num(y1) + "\" " + attrs +
         "/>");
  }
};

// One storey's drawing: which features, heights and id suffix it has.
struct StoreyView {
  std::size_t index = 0;
  const RoomFeatures* features = nullptr;  // null: draw from the bounds
  float floor_y = 0.0f, ceiling_y = 0.0f;
  std::string suffix;                      // "" for the main storey, "-storeyN" for storey N (from 2)
  std::size_t first_room = 0;              // index into ReportInput::rooms of its room 0
};

// Each room's border, with walls, the outside and other rooms: the cell edges between a column of the room
// and one that is not, as one path per room.
std::vector<std::string> room_borders(const GridSpec& g, const RoomSplit& split, const Mapper& map) {
  std::vector<std::string> out(std::size_t(std::max(split.count, 0)));
  const float s = g.voxel_size;
  const auto label = [&](int x, int z) {
    return x < 0 || z < 0 || x >= g.nx || z >= g.nz ? kNoRoom : split.room[g.column(x, z)];
  };
  for (int z = 0; z < g.nz; ++z)
    for (int x = 0; x < g.nx; ++x) {
      const int k = label(x, z);
      if (k == kNoRoom || k >= split.count) continue;
      std::string& d = out[std::size_t(k)];
      const float x0 = g.origin.x + float(x) * s, x1 = x0 + s, z0 = g.origin.z + float(z) * s, z1 = z0 + s;
      if (label(x - 1, z) != k) append(d, "M", map.point(x0, z0), "V", num(map.pz(z1)));
      if (label(x + 1, z) != k) append(d, "M", map.point(x1, z0), "V", num(map.pz(z1)));
      if (label(x, z - 1) != k) append(d, "M", map.point(x0, z0), "H", num(map.px(x1)));
      if (label(x, z + 1) != k) append(d, "M", map.point(x0, z1), "H", num(map.px(x1)));
    }
  return out;
}

// Areas: ceilings at the bottom, then floors, furniture, walls; larger before smaller within a type.
std::vector<std::size_t> drawing_order(std::span<const Area> areas) {
  std::vector<std::size_t> order(areas.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto layer = [](AreaType t) {
    switch (t) {
      case AreaType::Ceiling: return 0;
      case AreaType::Floor: return 1;
      case AreaType::Furniture: return 2;
      case AreaType::Wall: return 3;
    }
    return 3;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Area &A = areas[a], &B = areas[b];
    if (layer(A.type) != layer(B.type)) return layer(A.type) < layer(B.type);
    return int(A.size) < int(B.size);
  });
  return order;
}

// Everything of one storey inside its drawing frame: footprint, furniture tops, grid, wall columns and
// normals, the bounds cut above its floor, room borders, its areas and placements. Returns whether it drew
// raised surfaces from the bounds (for the legend).
bool draw_storey(Page& p, const ReportInput& input, const StoreyView& v, const Mapper& map, const BoundsMesh* bounds,
                 std::span<const std::size_t> order, bool& drew_rooms) {
  const Extent& world = map.world;
  const std::string& sfx = v.suffix;
  const float draw_w = map.width(), draw_h = map.height();
  // Drawing frame and its clip: nothing of the room is drawn over the labels around it.
  p.line("<defs><clipPath id=\"drawing" + sfx + "\"><rect x=\"" + num(map.left) + "\" y=\"" + num(map.top) +
         "\" width=\"" + num(draw_w) + "\" height=\"" + num(draw_h) + "\"/></clipPath></defs>");
  p.rect(map.left, map.top, draw_w, draw_h, "fill=\"#fbfbfb\" stroke=\"#bbbbbb\" stroke-width=\"1\"");
  p.line("<g id=\"room" + sfx + "\" class=\"storey\" data-storey=\"" + std::to_string(v.index) +
         "\" clip-path=\"url(#drawing" + sfx + ")\">");

  // Footprint and furniture tops.
  std::vector<std::size_t> floor_faces, raised_faces;
  if (bounds && !v.features) split_floor_faces(*bounds, v.floor_y, floor_faces, raised_faces);
  if (v.features) {
    const GridSpec& g = *input.voxels.grid;
    const RoomFeatures& f = *v.features;
    p.line("<path id=\"footprint" + sfx + "\" fill=\"" + std::string(kFootprintFill) +
           "\" shape-rendering=\"crispEdges\" d=\"" +
           cell_path(g, map, [&](int x, int z) { return f.room[g.column(x, z)] != 0; }) + "\"/>");
    p.line("<path id=\"furniture-tops" + sfx + "\" fill=\"" + std::string(kFurnitureFill) +
           "\" shape-rendering=\"crispEdges\" d=\"" +
           cell_path(g, map, [&](int x, int z) { return f.furniture[g.column(x, z)] != kNoFurniture; }) + "\"/>");
  } else if (bounds) {
    // Up-facing faces of the bounds near the floor are the floor; higher ones, below the cut, raised surfaces.
    p.line("<path id=\"footprint" + sfx + "\" fill=\"" + std::string(kFootprintFill) + "\" stroke=\"" +
           kFootprintFill + "\" stroke-width=\"0.5\" d=\"" + triangle_path(*bounds, floor_faces, map) + "\"/>");
    p.line("<path id=\"furniture-tops" + sfx + "\" fill=\"" + std::string(kFurnitureFill) + "\" stroke=\"" +
           kFurnitureFill + "\" stroke-width=\"0.5\" d=\"" + triangle_path(*bounds, raised_faces, map) + "\"/>");
  }

  // A metre grid, faint, over the footprint.
  std::string grid_d;
  for (float x = std::ceil(world.x0); x <= world.x1; x += 1.0f)
    append(grid_d, "M", map.point(x, world.z0), "V", num(map.pz(world.z1)));
  for (float z = std::ceil(world.z0); z <= world.z1; z += 1.0f)
    append(grid_d, "M", map.point(world.x0, z), "H", num(map.px(world.x1)));
  p.line("<path id=\"metre-grid" + sfx + "\" fill=\"none\" stroke=\"" + std::string(kGridStroke) +
         "\" stroke-opacity=\"0.45\" stroke-width=\"0.6\" d=\"" + grid_d + "\"/>");

  // Wall columns, then their normals: a tick from each wall column into the room, one voxel long.
  if (v.features) {
    const GridSpec& g = *input.voxels.grid;
    const RoomFeatures& f = *v.features;
    p.line("<path id=\"wall-columns" + sfx + "\" fill=\"" + std::string(kWallFill) +
           "\" shape-rendering=\"crispEdges\" d=\"" +
           cell_path(g, map, [&](int x, int z) { return f.walls[g.column(x, z)] != 0; }) + "\"/>");
    std::string ticks;
    if (!f.normals.empty()) {
      const int y0 = std::clamp(f.levels.floor, 0, g.ny - 1), y1 = std::clamp(f.levels.ceiling, 0, g.ny - 1);
      const float s = g.voxel_size;
      const float tick = std::max(0.8f * s, 7.0f / map.scale);
      struct Dir {
        std::uint8_t bit;
        int dx, dz;
      };
      constexpr Dir kDirs[] = {{kNormalLeft, -1, 0}, {kNormalRight, 1, 0}, {kNormalBackward, 0, -1}, {kNormalForward, 0, 1}};
      for (int z = 0; z < g.nz; ++z)
        for (int x = 0; x < g.nx; ++x) {
          std::uint8_t bits = 0;
          for (int y = y0; y <= y1; ++y) bits |= f.normals[g.index(x, y, z)];
          for (const Dir& d : kDirs) {
            if (!(bits & d.bit)) continue;
            // F marks the free voxel in front of the wall; the tick starts on the wall's face.
            const float cx = g.origin.x + (float(x) + 0.5f - 0.5f * float(d.dx)) * s;
            const float cz = g.origin.z + (float(z) + 0.5f - 0.5f * float(d.dz)) * s;
            append(ticks, "M", map.point(cx, cz), "l", num(float(d.dx) * tick * map.scale), ",",
                   num(float(d.dz) * tick * map.scale));
          }
        }
    }
    p.line("<path id=\"wall-normals" + sfx + "\" fill=\"none\" stroke=\"" + std::string(kNormalStroke) +
           "\" stroke-width=\"1.2\" stroke-linecap=\"round\" d=\"" + ticks + "\"/>");
  }

  // The bounds cut above furniture height: the walls' surfaces as the bounds mesh sees them.
  if (bounds)
    p.line("<path id=\"bounds-outline" + sfx + "\" fill=\"none\" stroke=\"" + std::string(kOutlineStroke) +
           "\" stroke-width=\"" + (v.features ? "1" : "2") + "\" stroke-linecap=\"round\" d=\"" +
           slice_path(*bounds, v.floor_y + kOutlineAboveFloor, map) + "\"/>");

  const auto on_plan = [&](const Area& a) { return report_detail::drawable(a) && a.storey == v.index; };
  p.line("<g id=\"areas" + sfx + "\" stroke-linejoin=\"round\">");
  for (const std::size_t i : order) {
    const Area& a = input.areas[i];
    if (!on_plan(a)) continue;
    std::string pts;
    for (const glm::vec2& q : area_outline(a)) append(pts, pts.empty() ? "" : " ", map.point(q.x, q.y));
    const std::string colour(reach_colour(a.reach));
    std::string attrs = "fill=\"" + colour + "\" fill-opacity=\"" + num(fill_opacity_for(a.type), 2) + "\" stroke=\"" +
                        colour + "\" stroke-width=\"" + (a.type == AreaType::Wall ? "1" : "1.6") + "\"";
    if (const char* dash = dash_for(a.type)) attrs += " stroke-dasharray=\"" + std::string(dash) + "\"";
    p.line("<polygon class=\"area\" data-index=\"" + std::to_string(i) + "\" data-type=\"" +
           std::string(to_string(a.type)) + "\" data-size=\"" + std::string(to_string(a.size)) + "\" data-reach=\"" +
           std::string(to_string(a.reach)) + "\" points=\"" + pts + "\" " + attrs + "><title>" +
           escape(area_title(i, a)) + "</title></polygon>");
  }
  p.line("</g>");
  // Rooms (issue 15), over the areas: each one's border in its colour, labelled at its centre.
  if (v.features && !input.rooms.empty() && v.features->rooms.room.size() == input.voxels.grid->column_count()) {
    const std::vector<std::string> borders = room_borders(*input.voxels.grid, v.features->rooms, map);
    p.line("<g id=\"rooms" + sfx + "\">");
    for (std::size_t k = 0; k < borders.size(); ++k) {
      const std::size_t global = v.first_room + k;
      if (global >= input.rooms.size()) break;
      const Room& room = input.rooms[global];
      const std::string colour(room_colour(global));
      p.line("<path class=\"room-outline\" data-room=\"" + std::to_string(global) + "\" fill=\"none\" stroke=\"" +
             colour + "\" stroke-width=\"2.5\" stroke-linecap=\"square\" d=\"" + borders[k] + "\"><title>room " +
             std::to_string(global) + ": " + num(room.floor_area, 1) + " m2 of free floor</title></path>");
      p.text(map.px(room.center.x), map.pz(room.center.z), "room " + std::to_string(global) + ", " +
             num(room.floor_area, 1) + " m\u00b2", 13,
             (" text-anchor=\"middle\" font-weight=\"bold\" fill=\"" + colour +
              "\" stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\"").c_str());
      drew_rooms = true;
    }
    p.line("</g>");
  }

  // Placements: black outlines over everything, numbered best first.
  p.line("<g id=\"placements" + sfx + "\">");
  for (std::size_t i = 0; i < input.placements.size(); ++i) {
    const Placement& pl = input.placements[i];
    if (!report_detail::drawable_type(pl.surface) || !report_detail::drawable_reach(pl.reach)) continue;
    if (pl.storey != v.index) continue;
    const auto xz = [](const glm::vec3& q) { return glm::vec2(q.x, q.z); };
    const std::array<glm::vec3, 4> c = pl.corners();
    std::array<glm::vec2, 4> outline = {xz(c[0]), xz(c[1]), xz(c[2]), xz(c[3])};
    if (pl.surface == AreaType::Wall) {  // a strip before the wall, as deep as a lane
      const glm::vec2 n = glm::vec2(pl.normal.x, pl.normal.z) * kWallLane;
      outline = {xz(c[0]), xz(c[1]), xz(c[1]) + n, xz(c[0]) + n};
    }
    std::string pts;
    for (const glm::vec2& q : outline) append(pts, pts.empty() ? "" : " ", map.point(q.x, q.y));
    const std::string title = "placement " + std::to_string(i + 1) + ": " + std::string(to_string(pl.surface)) + ", " +
                              std::string(to_string(pl.reach)) + ", at (" + num(pl.center.x, 2) + ", " +
                              num(pl.center.y, 2) + ", " + num(pl.center.z, 2) + ")";
    p.line("<polygon class=\"placement\" data-index=\"" + std::to_string(i) + "\" data-surface=\"" +
           std::string(to_string(pl.surface)) + "\" points=\"" + pts +
           "\" fill=\"#000000\" fill-opacity=\"0.25\" stroke=\"#000000\" stroke-width=\"2\"><title>" + escape(title) +
           "</title></polygon>");
    const glm::vec2 mid = 0.25f * (outline[0] + outline[1] + outline[2] + outline[3]);
    p.text(map.px(mid.x), map.pz(mid.y) + 4.0f, std::to_string(i + 1), 11, " text-anchor=\"middle\" font-weight=\"bold\"");
  }
  p.line("</g>");
  p.line("</g>");  // room

  // Metre labels along the top and left of the drawing.
  for (float x = std::ceil(world.x0); x <= world.x1; x += 1.0f)
    p.text(map.px(x), map.top - 8.0f, num(x, 0), 11, " text-anchor=\"middle\" fill=\"#555555\"");
  for (float z = std::ceil(world.z0); z <= world.z1; z += 1.0f)
    p.text(map.left - 6.0f, map.pz(z) + 4.0f, num(z, 0), 11, " text-anchor=\"end\" fill=\"#555555\"");
  p.text(map.left + draw_w, map.top - 8.0f, "x (m)", 11, " text-anchor=\"end\" fill=\"#555555\" dx=\"0\" dy=\"-12\"");
  p.text(map.left - 6.0f, map.top - 20.0f, "z (m)", 11, " text-anchor=\"end\" fill=\"#555555\"");
  return !raised_faces.empty();
}

}  // namespace

std::string plan_svg(const ReportInput& input) {
  const bool have_features = valid_features(input.voxels);
  const BoundsMesh* bounds = valid_mesh(input.bounds) ? input.bounds : nullptr;
  const float floor_y = input.floor_y, ceiling_y = input.ceiling_y;

  // One drawing per storey; the main storey's heights are the input's own.
  std::vector<StoreyView> views;
  for (std::size_t i = 0; i < std::max<std::size_t>(1, input.storeys.size()); ++i) {
    StoreyView v;
    v.index = i;
    v.floor_y = i == 0 ? floor_y : input.storeys[i].floor_y;
    v.ceiling_y = i == 0 ? ceiling_y : input.storeys[i].ceiling_y;
    v.suffix = i == 0 ? "" : "-storey" + std::to_string(i + 1);
    if (have_features) {
      const RoomFeatures* f = i == 0 ? input.voxels.features
                                     : (i - 1 < input.voxels.other_storeys.size() ? &input.voxels.other_storeys[i - 1] : nullptr);
      if (f && valid_storey_features(*input.voxels.grid, *f)) v.features = f;
    }
    for (const Room& room : input.rooms) v.first_room += room.storey < i ? 1 : 0;
    views.push_back(std::move(v));
  }

  // What the drawings must show: every storey's room mask, the bounds and the areas; the scan only when none.
  Extent world;
  for (const StoreyView& v : views) {
    if (!v.features) continue;
    const GridSpec& g = *input.voxels.grid;
    for (int z = 0; z < g.nz; ++z)
      for (int x = 0; x < g.nx; ++x)
        if (v.features->room[g.column(x, z)] || v.features->walls[g.column(x, z)]) {
          world.add(g.origin.x + float(x) * g.voxel_size, g.origin.z + float(z) * g.voxel_size);
          world.add(g.origin.x + float(x + 1) * g.voxel_size, g.origin.z + float(z + 1) * g.voxel_size);
        }
  }
  if (bounds)
    for (const glm::vec3& v : bounds->vertices) world.add(v.x, v.z);
  for (const Area& a : input.areas)
    if (report_detail::drawable(a) && a.storey < views.size())
      for (const glm::vec2& p : area_outline(a)) world.add(p.x, p.y);
  if (world.empty())
    for (const Scan& s : input.scan)
      for (const glm::vec3& v : s.vertices) world.add(v.x, v.z);
  if (world.empty()) world = {-0.5f, -0.5f, 0.5f, 0.5f};
  world.x0 -= kPadding;
  world.z0 -= kPadding;
  world.x1 += kPadding;
  world.z1 += kPadding;

  Mapper map;
  map.world = world;
  const float ww = world.x1 - world.x0, wd = world.z1 - world.z0;
  map.scale = std::clamp(std::min(kMaxDrawingWidth / ww, kMaxDrawingHeight / wd), kMinScale, kMaxScale);
  // Far-flung input (an app's stray area) must not make a page of many thousand pixels.
  map.scale = std::min(map.scale, kMaxPageSide / std::max(ww, wd));

  // Heading lines: the main storey's heights, then what is drawn.
  std::vector<std::string> heading;
  heading.push_back("floor y = " + num(floor_y, 2) + " m,  ceiling y = " + num(ceiling_y, 2) + " m,  room height " +
                    num(ceiling_y - floor_y, 2) + " m");
  std::array<std::size_t, 3> per_reach{};
  std::array<std::size_t, 4> per_type{};
  for (const Area& a : input.areas) {
    if (!report_detail::drawable(a) || a.storey >= views.size()) continue;
    ++per_reach[std::size_t(a.reach) - 1];
    ++per_type[std::size_t(a.type) - 1];
  }
  const std::size_t drawn = per_type[0] + per_type[1] + per_type[2] + per_type[3];
  heading.push_back(std::to_string(drawn) + " areas: " + std::to_string(per_type[0]) + " wall, " +
                    std::to_string(per_type[1]) + " floor, " + std::to_string(per_type[2]) + " ceiling, " +
                    std::to_string(per_type[3]) + " furniture; " + std::to_string(per_reach[0]) + " close, " +
                    std::to_string(per_reach[1]) + " distance, " + std::to_string(per_reach[2]) + " none" +
                    (views.size() > 1 ? "; " + std::to_string(views.size()) + " storeys, one drawing each" : ""));
  // Each drawing's own line: its storey, heights, areas and rooms.
  const auto storey_line = [&](const StoreyView& v) {
    const auto areas = std::count_if(input.areas.begin(), input.areas.end(),
                                     [&](const Area& a) { return report_detail::drawable(a) && a.storey == v.index; });
    std::size_t rooms = 0;
    for (const Room& room : input.rooms) rooms += room.storey == v.index ? 1 : 0;
    return "storey " + std::to_string(v.index + 1) + (v.index == 0 ? " (main)" : "") + ": floor y = " +
           num(v.floor_y, 2) + " m, ceiling y = " + num(v.ceiling_y, 2) + " m, " + std::to_string(areas) + " areas" +
           (input.rooms.empty() ? "" : ", " + std::to_string(rooms) + (rooms == 1 ? " room" : " rooms"));
  };

  const float heading_h = 30.0f + 18.0f * float(heading.size()) + 8.0f;
  constexpr float kStoreyLine = 24.0f;  // the drawing's own line above its metre labels
  constexpr float kPanelGap = 24.0f;
  map.left = kMargin + kAxisLabelRoom;
  const float draw_w = map.width(), draw_h = map.height();
  const float panel_h = kStoreyLine + kAxisLabelRoom + draw_h + kPanelGap;
  const float first_top = heading_h + kStoreyLine + kAxisLabelRoom;
  const float legend_x = map.left + draw_w + kLegendGap;
  const float below_y = first_top + float(views.size() - 1) * panel_h + draw_h + 18.0f;  // scale bar and axes
  const float legend_h = input.placements.empty() ? 460.0f : 485.0f;  // one more swatch for placements
  const float page_w = std::ceil(legend_x + kLegendWidth + kMargin);
  const float page_h = std::ceil(std::max(below_y + 70.0f, first_top + legend_h + kMargin));

  Page p;
  p.line("<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
  p.line("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(page_w, 0) + "\" height=\"" +
         num(page_h, 0) + "\" viewBox=\"0 0 " + num(page_w, 0) + " " + num(page_h, 0) +
         "\" font-family=\"DejaVu Sans, Verdana, sans-serif\" data-generator=\"roomsense\">");
  p.line("<title>roomsense plan: " + escape(input.title) + "</title>");
  p.line("<desc>Top view looking down -Y: +X to the right, +Z down the page (right-handed, +Y towards the viewer). "
         "Metres. One drawing per storey, main storey first.</desc>");
  p.rect(0, 0, page_w, page_h, "fill=\"#ffffff\"");

  // Heading.
  p.text(kMargin, 30.0f, "roomsense plan: " + input.title, 18, " font-weight=\"bold\"");
  for (std::size_t i = 0; i < heading.size(); ++i) p.text(kMargin, 30.0f + 20.0f * float(i + 1), heading[i], 13);

  bool raised = false, drew_rooms = false;
  const std::vector<std::size_t> order = drawing_order(input.areas);
  for (std::size_t i = 0; i < views.size(); ++i) {
    map.top = first_top + float(i) * panel_h;
    p.text(kMargin, map.top - kAxisLabelRoom - 6.0f, storey_line(views[i]), 14, " font-weight=\"bold\"");
    raised = draw_storey(p, input, views[i], map, bounds, order, drew_rooms) || raised;
  }
  map.top = first_top;

  // Scale bar, in alternating black and white metre segments.
  {
    const float metres = scale_bar_metres(map.scale);
    const int parts = metres <= 1.0f ? 2 : (metres <= 5.0f ? int(metres) : 5);
    const float part_px = metres * map.scale / float(parts);
    const float x0 = map.left, y0 = below_y + 6.0f;
    p.line("<g id=\"scale-bar\">");
    for (int i = 0; i < parts; ++i)
      p.rect(x0 + float(i) * part_px, y0, part_px, 7.0f,
             std::string("fill=\"") + (i % 2 == 0 ? "#222222" : "#ffffff") + "\" stroke=\"#222222\" stroke-width=\"1\"");
    for (int i = 0; i <= parts; ++i) {
      const float v = metres * float(i) / float(parts);
      p.text(x0 + float(i) * part_px, y0 + 22.0f, num(v, v == std::round(v) ? 0 : 1) + (i == parts ? " m" : ""), 12,
             " text-anchor=\"middle\"");
    }
    p.line("</g>");
  }
  // Axes: +X right, +Z down; +Y towards the viewer.
  {
    const float ax = std::max(map.left + draw_w - 150.0f, map.left + 300.0f), ay = below_y + 6.0f;
    p.line("<g id=\"axes\" stroke=\"#222222\" stroke-width=\"1.5\" fill=\"#222222\">");
    p.segment(ax, ay, ax + 34.0f, ay, "");
    p.line("<path d=\"M" + num(ax + 40.0f) + "," + num(ay) + "l-7,-3.5v7z\" stroke=\"none\"/>");
    p.segment(ax, ay, ax, ay + 34.0f, "");
    p.line("<path d=\"M" + num(ax) + "," + num(ay + 40.0f) + "l-3.5,-7h7z\" stroke=\"none\"/>");
    p.line("<circle cx=\"" + num(ax) + "\" cy=\"" + num(ay) + "\" r=\"3\" fill=\"#ffffff\"/>");
    p.line("<circle cx=\"" + num(ax) + "\" cy=\"" + num(ay) + "\" r=\"1\" stroke=\"none\"/>");
    p.line("</g>");
    p.text(ax + 44.0f, ay + 4.0f, "+X", 12);
    p.text(ax + 6.0f, ay + 46.0f, "+Z", 12);
    p.text(ax + 50.0f, ay + 28.0f, "view from above", 11, " fill=\"#555555\"");
    p.text(ax + 50.0f, ay + 42.0f, "(+Y towards you)", 11, " fill=\"#555555\"");
  }

  // Legend.
  {
    float y = map.top;
    const float x = legend_x, label_x = legend_x + 34.0f;
    p.line("<g id=\"legend\">");
    p.text(x, y + 4.0f, "Legend", 14, " font-weight=\"bold\"");
    y += 24.0f;
    const auto swatch = [&](const std::string& attrs, const std::string& label) {
      p.rect(x, y - 10.0f, 24.0f, 13.0f, attrs);
      p.text(label_x, y, label, 12);
      y += 21.0f;
    };
    if (have_features || bounds)
      swatch("fill=\"" + std::string(kFootprintFill) + "\"",
             have_features ? "room footprint (mask B)" : "floor footprint (bounds)");
    if (have_features || raised)
      swatch("fill=\"" + std::string(kFurnitureFill) + "\"",
             have_features ? "furniture tops (C)" : "raised surfaces (bounds)");
    if (have_features) {
      swatch("fill=\"" + std::string(kWallFill) + "\"", "wall columns (A)");
      p.segment(x + 4.0f, y - 4.0f, x + 20.0f, y - 4.0f,
                "stroke=\"" + std::string(kNormalStroke) + "\" stroke-width=\"2\" stroke-linecap=\"round\"");
      p.segment(x + 4.0f, y - 9.0f, x + 4.0f, y + 1.0f, "stroke=\"" + std::string(kWallFill) + "\" stroke-width=\"3\"");
      p.text(label_x, y, "wall normal (F), into the room", 12);
      y += 21.0f;
    }
    if (bounds) {
      p.segment(x, y - 4.0f, x + 24.0f, y - 4.0f, "stroke=\"" + std::string(kOutlineStroke) + "\" stroke-width=\"2\"");
      p.text(label_x, y, "bounds, cut " + num(kOutlineAboveFloor, 1) + " m above the floor", 12);
      y += 21.0f;
    }
    if (drew_rooms) {
      p.segment(x, y - 4.0f, x + 24.0f, y - 4.0f, "stroke=\"" + std::string(room_colour(0)) + "\" stroke-width=\"2.5\"");
      p.text(label_x, y, "room border: walls, doorways", 12);
      y += 21.0f;
    }
    p.segment(x, y - 4.0f, x + 24.0f, y - 4.0f, "stroke=\"" + std::string(kGridStroke) + "\" stroke-width=\"1\"");
    p.text(label_x, y, "1 m grid", 12);
    y += 30.0f;

    p.text(x, y, "Areas, coloured by reach", 13, " font-weight=\"bold\"");
    y += 20.0f;
    constexpr Reach kReaches[] = {Reach::Close, Reach::Distance, Reach::None};
    constexpr const char* kReachLabels[] = {"close: free floor next to it", "distance: free floor in sight", "none: no free floor in sight"};
    for (int i = 0; i < 3; ++i) {
      const std::string c(reach_colour(kReaches[i]));
      swatch("fill=\"" + c + "\" fill-opacity=\"0.35\" stroke=\"" + c + "\" stroke-width=\"1.6\"", kReachLabels[i]);
    }
    y += 9.0f;
    p.text(x, y, "Area types", 13, " font-weight=\"bold\"");
    y += 20.0f;
    const std::string grey = "fill=\"#888888\" fill-opacity=\"0.15\" stroke=\"#444444\" stroke-width=\"1.6\"";
    swatch(grey, "floor: its rectangle");
    swatch(grey + " stroke-dasharray=\"2 2.5\"", "furniture top: its rectangle");
    swatch(grey + " stroke-dasharray=\"7 4\"", "ceiling: its rectangle");
    p.rect(x, y - 10.0f, 24.0f, 4.0f, "fill=\"" + std::string(kWallFill) + "\"");
    p.rect(x, y - 6.0f, 24.0f, 5.0f, "fill=\"#888888\" fill-opacity=\"0.6\"");
    p.text(label_x, y, "wall: a strip in front of it,", 12);
    y += 16.0f;
    p.text(label_x, y, "large next to the wall, then", 12);
    y += 16.0f;
    p.text(label_x, y, "medium, small further out", 12);
    y += 16.0f;
    if (!input.placements.empty()) {
      y += 4.0f;
      swatch("fill=\"#000000\" fill-opacity=\"0.25\" stroke=\"#000000\" stroke-width=\"2\"", "placement, numbered best first");
    }
    p.line("</g>");
  }

  p.line("</svg>");
  return p.out;
}

}  // namespace roomsense
