// scene.glb: the scan in grey, the translucent bounds, every area as a thin quad coloured by reach, every
// placement as the object's box and every room's floor in its colour, each its own named node of a GlbScene (export.h), so a glTF viewer can toggle them.
#include "report_common.h"
#include "roomsense/report.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace roomsense {
namespace {

constexpr float kAreaLift = 0.01f;  // metres in front of the surface, so the quad does not fight the scan
constexpr std::array<float, 4> kScanGrey = {0.55f, 0.55f, 0.55f, 1.0f};
constexpr std::array<float, 4> kBoundsColour = {0.95f, 0.72f, 0.30f, 0.30f};
constexpr float kAreaAlpha = 0.75f;
constexpr float kRoomAlpha = 0.5f;
constexpr std::array<float, 4> kPlacementColour = {0.80f, 0.05f, 0.75f, 0.85f};  // magenta: no reach colour
constexpr float kMinBoxHeight = 0.01f;  // metres: a flat object still shows as a slab

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The object's box of a placement: its footprint on the surface, extruded along the normal. Outward faces
// counter-clockwise. Empty when a coordinate is not finite.
std::vector<glm::vec3> placement_box(const Placement& p) {
  const std::array<glm::vec3, 4> base = p.corners();
  const glm::vec3 up = p.normal * std::max(p.height, kMinBoxHeight);
  std::vector<glm::vec3> box(base.begin(), base.end());
  for (const glm::vec3& c : base) box.push_back(c + up);
  for (const glm::vec3& c : box)
    if (!finite(c)) return {};
  return box;
}

// Bottom (seen from below), top, then the four sides; base corners 0-3 counter-clockwise seen from the normal's
// side, top corners 4-7 above them.
const std::vector<std::uint32_t> kBoxIndices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                                 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

// glTF's baseColorFactor is linear; the report's colours are sRGB.
std::array<float, 4> linear_rgba(std::string_view hex, float alpha) {
  std::array<float, 4> c{0.0f, 0.0f, 0.0f, alpha};
  for (int i = 0; i < 3 && hex.size() >= 7; ++i) {
    const auto digit = [](char ch) {
      return ch >= '0' && ch <= '9' ? ch - '0' : (ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : (ch >= 'A' && ch <= 'F' ? ch - 'A' + 10 : 0));
    };
    const float s = float(digit(hex[std::size_t(1 + 2 * i)]) * 16 + digit(hex[std::size_t(2 + 2 * i)])) / 255.0f;
    c[std::size_t(i)] = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
  }
  return c;
}

// All meshes as one, without non-finite vertices and without triangles that touch one or an index out of range.
void merge_meshes(std::span<const Scan> meshes, std::vector<glm::vec3>& vertices, std::vector<std::uint32_t>& indices) {
  constexpr std::uint32_t kDropped = std::numeric_limits<std::uint32_t>::max();
  for (const Scan& s : meshes) {
    std::vector<std::uint32_t> remap(s.vertices.size(), kDropped);
    for (std::size_t i = 0; i < s.vertices.size(); ++i)
      if (finite(s.vertices[i])) {
        remap[i] = std::uint32_t(vertices.size());
        vertices.push_back(s.vertices[i]);
      }
    for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3) {
      std::uint32_t tri[3];
      bool keep = true;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t i = s.indices[t + std::size_t(k)];
        tri[k] = i < remap.size() ? remap[i] : kDropped;
        keep = keep && tri[k] != kDropped;
      }
      if (keep) indices.insert(indices.end(), tri, tri + 3);
    }
  }
}

// Issue 15: each room's free floor, 1 cm above its storey's floor, in the room's colour: one node per room,
// its columns merged into runs along x per row. Needs the features of every storey with rooms.
void add_rooms(const ReportInput& input, GlbScene& scene) {
  const ReportFeatures& v = input.voxels;
  if (v.grid == nullptr || v.features == nullptr || input.rooms.empty()) return;
  const GridSpec& g = *v.grid;
  std::size_t first = 0;  // the storey's room 0 in input.rooms
  for (std::size_t storey = 0; storey <= v.other_storeys.size(); ++storey) {
    const RoomSplit& split = storey == 0 ? v.features->rooms : v.other_storeys[storey - 1].rooms;
    if (split.room.size() != g.column_count()) return;
    for (int k = 0; k < split.count && first + std::size_t(k) < input.rooms.size(); ++k) {
      const Room& room = input.rooms[first + std::size_t(k)];
      const float y = room.floor_y + kAreaLift, s = g.voxel_size;
      std::vector<glm::vec3> vertices;
      std::vector<std::uint32_t> indices;
      for (int z = 0; z < g.nz; ++z)
        for (int x = 0; x < g.nx;) {
          if (split.room[g.column(x, z)] != k) {
            ++x;
            continue;
          }
          int end = x + 1;
          while (end < g.nx && split.room[g.column(end, z)] == k) ++end;
          const float x0 = g.origin.x + float(x) * s, x1 = g.origin.x + float(end) * s;
          const float z0 = g.origin.z + float(z) * s, z1 = z0 + s;
          const auto base = std::uint32_t(vertices.size());
          vertices.insert(vertices.end(), {{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}});
          // Counter-clockwise seen from above (+Y).
          indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
          x = end;
        }
      if (!indices.empty())
        scene.add_mesh("room " + std::to_string(first + std::size_t(k)), vertices, indices,
                       linear_rgba(room_colour(first + std::size_t(k)), kRoomAlpha));
    }
    first += std::size_t(std::max(split.count, 0));
  }
}

}  // namespace

GlbScene scene_glb(const ReportInput& input) {
  GlbScene scene;
  {
    std::vector<glm::vec3> vertices;
    std::vector<std::uint32_t> indices;
    merge_meshes(input.scan, vertices, indices);
    scene.add_mesh("scan", vertices, indices, kScanGrey);
  }
  if (input.bounds != nullptr) {
    const Scan bounds{input.bounds->vertices, input.bounds->indices};
    std::vector<glm::vec3> vertices;
    std::vector<std::uint32_t> indices;
    merge_meshes(std::span<const Scan>(&bounds, 1), vertices, indices);
    scene.add_mesh("bounds", vertices, indices, kBoundsColour);
  }
  for (std::size_t i = 0; i < input.areas.size(); ++i) {
    const Area& a = input.areas[i];
    if (!report_detail::drawable(a)) continue;
    glm::vec3 n = a.normal;
    n = finite(n) && glm::length(n) > 1e-6f ? glm::normalize(n) : glm::vec3(0.0f);
    std::vector<glm::vec3> quad;
    for (const glm::vec3& c : a.corners) quad.push_back(c + kAreaLift * n);
    bool ok = true;
    for (const glm::vec3& c : quad) ok = ok && finite(c);
    if (!ok) continue;
    const std::string name = "area " + std::to_string(i) + " " + std::string(to_string(a.type)) + " " +
                             std::string(to_string(a.size)) + " " + std::string(to_string(a.reach));
    // Counter-clockwise from the front, like the corners.
    scene.add_mesh(name, quad, {0, 1, 2, 0, 2, 3}, linear_rgba(reach_colour(a.reach), kAreaAlpha));
  }
  for (std::size_t i = 0; i < input.placements.size(); ++i) {
    const Placement& p = input.placements[i];
    const std::vector<glm::vec3> box = placement_box(p);
    if (box.empty() || !report_detail::drawable_type(p.surface)) continue;  // its name is undefined
    scene.add_mesh("placement " + std::to_string(i) + " " + std::string(to_string(p.surface)), box, kBoxIndices,
                   kPlacementColour);
  }
  add_rooms(input, scene);
  return scene;
}

}  // namespace roomsense
