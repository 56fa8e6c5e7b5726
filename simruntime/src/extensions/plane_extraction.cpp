// See plane_extraction.h.
#include "plane_extraction.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <unordered_map>

namespace roomsense::sim {
namespace {

constexpr double kCell = 0.10;               // raster for connectivity, metres
constexpr double kMinArea = 0.25;            // m²: smaller regions are not served
constexpr double kTolerance = 30.0;          // degrees a triangle's normal may be off its group's
constexpr double kOffsetGap = 0.03;          // metres between two offset clusters
constexpr double kOffsetSpan = 0.10;         // the most one cluster may span along its normal
constexpr double kLevelTolerance = 0.05;     // planes at the floor's (ceiling's) level within this are floor (ceiling)
constexpr double kPi = 3.14159265358979323846;

XrSpatialPlaneAlignmentEXT alignment_of(const glm::dvec3& normal) {
  if (normal.y > 0.9) return XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT;
  if (normal.y < -0.9) return XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT;
  if (std::fabs(normal.y) < 0.1) return XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT;
  return XR_SPATIAL_PLANE_ALIGNMENT_ARBITRARY_EXT;
}

// The plane frame for a normal: +Z the normal; +Y up for walls, world -Z (floors) or +Z (ceilings) otherwise.
glm::dquat frame_for(const glm::dvec3& n) {
  glm::dvec3 x, y;
  if (std::fabs(n.y) > 0.9) {
    y = glm::normalize(glm::cross(n, glm::dvec3(1, 0, 0)));
    x = glm::cross(y, n);
  } else {
    y = glm::normalize(glm::dvec3(0, 1, 0) - n * n.y);
    x = glm::cross(y, n);
  }
  return glm::normalize(glm::quat_cast(glm::dmat3(x, y, n)));
}

void fill_rectangle(ServedPlane& p) {
  const float w = p.extents.width * 0.5f, h = p.extents.height * 0.5f;
  p.polygon = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
  p.vertices = p.polygon;
  p.indices = {0, 1, 2, 0, 2, 3};
}

struct Tri {
  std::array<std::uint32_t, 3> v{};
  glm::dvec3 normal{0.0};
  glm::dvec3 centroid{0.0};
  double area = 0.0;
};

struct Group {
  glm::dvec3 normal{0.0};
  std::vector<std::size_t> tris;
};

std::int64_t cell_key(std::int64_t x, std::int64_t y) { return (x << 32) ^ (y & 0xffffffffll); }

double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Vertical triangles grouped by the direction of their normal: the strongest direction first, then the next.
std::vector<Group> vertical_groups(const std::vector<Tri>& tris, const std::vector<std::size_t>& vertical) {
  std::array<double, 360> histogram{};
  std::vector<int> degree(vertical.size());
  for (std::size_t k = 0; k < vertical.size(); ++k) {
    const Tri& t = tris[vertical[k]];
    double a = std::atan2(t.normal.x, t.normal.z) * 180.0 / kPi;
    if (a < 0) a += 360.0;
    degree[k] = std::min(359, static_cast<int>(a));
    histogram[static_cast<std::size_t>(degree[k])] += t.area;
  }
  std::vector<bool> taken(vertical.size(), false);
  std::vector<Group> groups;
  const int half = static_cast<int>(kTolerance / 2);
  for (int round = 0; round < 128; ++round) {
    int best = -1;
    double best_sum = 0.0;
    for (int b = 0; b < 360; ++b) {
      double sum = 0.0;
      for (int d = -half; d <= half; ++d) sum += histogram[static_cast<std::size_t>((b + d + 360) % 360)];
      if (sum > best_sum) best_sum = sum, best = b;
    }
    if (best < 0 || best_sum < kMinArea) break;
    Group g;
    glm::dvec3 sum(0.0);
    for (std::size_t k = 0; k < vertical.size(); ++k) {
      if (taken[k]) continue;
      const int diff = std::abs(((degree[k] - best) % 360 + 540) % 360 - 180);
      if (diff > half) continue;
      taken[k] = true;
      histogram[static_cast<std::size_t>(degree[k])] -= tris[vertical[k]].area;
      g.tris.push_back(vertical[k]);
      sum += tris[vertical[k]].normal * tris[vertical[k]].area;
    }
    sum.y = 0.0;
    if (g.tris.empty() || glm::length(sum) == 0.0) continue;
    g.normal = glm::normalize(sum);
    groups.push_back(std::move(g));
  }
  return groups;
}

// The connected regions of one group at one offset, each a plane when large enough.
void regions_of(const Room& room, const std::vector<Tri>& tris, const glm::dvec3& normal, std::vector<std::size_t> cluster,
                std::vector<ServedPlane>& out) {
  const glm::dquat q = frame_for(normal);
  const glm::dvec3 ax = q * glm::dvec3(1, 0, 0), ay = q * glm::dvec3(0, 1, 0);
  auto project = [&](const glm::dvec3& p) { return glm::dvec2(glm::dot(p, ax), glm::dot(p, ay)); };
  auto vertex = [&](std::uint32_t i) { return glm::dvec3(room.mesh.vertices[i]); };

  std::unordered_map<std::int64_t, int> cells;  // cell -> region (-1 before the search)
  std::vector<std::int64_t> home(cluster.size());
  for (std::size_t k = 0; k < cluster.size(); ++k) {
    const Tri& t = tris[cluster[k]];
    const glm::dvec2 c = project(t.centroid);
    home[k] = cell_key(static_cast<std::int64_t>(std::floor(c.x / kCell)), static_cast<std::int64_t>(std::floor(c.y / kCell)));
    cells.emplace(home[k], -1);
    const glm::dvec2 a = project(vertex(t.v[0])), b = project(vertex(t.v[1])), d = project(vertex(t.v[2]));
    const glm::dvec2 lo = glm::min(a, glm::min(b, d)), hi = glm::max(a, glm::max(b, d));
    if (hi.x - lo.x < kCell && hi.y - lo.y < kCell) continue;  // a small triangle: its centroid's cell will do
    const double s = edge(a, b, d) >= 0 ? 1.0 : -1.0;
    for (auto x = static_cast<std::int64_t>(std::floor(lo.x / kCell)); x <= static_cast<std::int64_t>(std::floor(hi.x / kCell)); ++x)
      for (auto y = static_cast<std::int64_t>(std::floor(lo.y / kCell)); y <= static_cast<std::int64_t>(std::floor(hi.y / kCell)); ++y) {
        const glm::dvec2 p((static_cast<double>(x) + 0.5) * kCell, (static_cast<double>(y) + 0.5) * kCell);
        if (s * edge(a, b, p) >= 0 && s * edge(b, d, p) >= 0 && s * edge(d, a, p) >= 0) cells.emplace(cell_key(x, y), -1);
      }
  }
  // Connected regions (8-neighbourhood), seeded in triangle order for a stable result.
  int regions = 0;
  for (std::size_t k = 0; k < cluster.size(); ++k) {
    if (cells[home[k]] >= 0) continue;
    std::deque<std::int64_t> todo{home[k]};
    cells[home[k]] = regions;
    while (!todo.empty()) {
      const std::int64_t key = todo.front();
      todo.pop_front();
      const std::int64_t x = key >> 32, y = static_cast<std::int32_t>(key & 0xffffffffll);
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          const auto it = cells.find(cell_key(x + dx, y + dy));
          if (it == cells.end() || it->second >= 0) continue;
          it->second = regions;
          todo.push_back(it->first);
        }
    }
    ++regions;
  }
  std::vector<std::vector<std::size_t>> members(static_cast<std::size_t>(regions));
  for (std::size_t k = 0; k < cluster.size(); ++k) members[static_cast<std::size_t>(cells[home[k]])].push_back(cluster[k]);

  for (const auto& region : members) {
    double area = 0.0, offset = 0.0;
    for (std::size_t i : region) {
      const double a = tris[i].area * std::fabs(glm::dot(tris[i].normal, normal));
      area += a;
      offset += a * glm::dot(tris[i].centroid, normal);
    }
    if (area < kMinArea) continue;
    offset /= area;
    glm::dvec2 lo(1e30), hi(-1e30);
    for (std::size_t i : region)
      for (std::uint32_t v : tris[i].v) {
        const glm::dvec2 p = project(vertex(v));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    const glm::dvec2 mid = (lo + hi) * 0.5;
    ServedPlane plane;
    plane.pose.rotation = q;
    plane.pose.translation = normal * offset + ax * mid.x + ay * mid.y;
    plane.extents = {static_cast<float>(hi.x - lo.x), static_cast<float>(hi.y - lo.y)};
    plane.alignment = alignment_of(normal);
    const float w = plane.extents.width * 0.5f, h = plane.extents.height * 0.5f;
    plane.polygon = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
    std::unordered_map<std::uint32_t, std::uint32_t> index;
    for (std::size_t i : region) {
      std::array<glm::dvec2, 3> p;
      for (int c = 0; c < 3; ++c) p[static_cast<std::size_t>(c)] = project(vertex(tris[i].v[static_cast<std::size_t>(c)])) - mid;
      if (edge(p[0], p[1], p[2]) <= 0.0) continue;  // folded over in the projection
      for (int c = 0; c < 3; ++c) {
        const auto [it, fresh] = index.emplace(tris[i].v[static_cast<std::size_t>(c)], static_cast<std::uint32_t>(plane.vertices.size()));
        if (fresh)
          plane.vertices.push_back({static_cast<float>(p[static_cast<std::size_t>(c)].x), static_cast<float>(p[static_cast<std::size_t>(c)].y)});
        plane.indices.push_back(it->second);
      }
    }
    out.push_back(std::move(plane));
  }
}

std::vector<ServedPlane> planes_of_mesh(const Room& room) {
  const Scan& mesh = room.mesh;
  std::vector<Tri> tris;
  tris.reserve(mesh.indices.size() / 3);
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    Tri t;
    t.v = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
    if (t.v[0] >= mesh.vertices.size() || t.v[1] >= mesh.vertices.size() || t.v[2] >= mesh.vertices.size()) continue;
    const glm::dvec3 a(mesh.vertices[t.v[0]]), b(mesh.vertices[t.v[1]]), c(mesh.vertices[t.v[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    if (!(len > 1e-12)) continue;
    t.normal = n / len;
    t.area = 0.5 * len;
    t.centroid = (a + b + c) / 3.0;
    tris.push_back(t);
  }
  const double cos_tol = std::cos(kTolerance * kPi / 180.0), sin_tol = std::sin(kTolerance * kPi / 180.0);
  Group up{{0, 1, 0}, {}}, down{{0, -1, 0}, {}};
  std::vector<std::size_t> vertical;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    if (tris[i].normal.y >= cos_tol) up.tris.push_back(i);
    else if (tris[i].normal.y <= -cos_tol) down.tris.push_back(i);
    else if (std::fabs(tris[i].normal.y) <= sin_tol) vertical.push_back(i);
  }
  std::vector<Group> groups = {std::move(up), std::move(down)};
  for (Group& g : vertical_groups(tris, vertical)) groups.push_back(std::move(g));

  std::vector<ServedPlane> planes;
  for (Group& g : groups) {
    std::vector<std::pair<double, std::size_t>> by_offset;
    by_offset.reserve(g.tris.size());
    for (std::size_t i : g.tris) by_offset.emplace_back(glm::dot(tris[i].centroid, g.normal), i);
    std::sort(by_offset.begin(), by_offset.end());
    std::vector<std::size_t> cluster;
    double start = 0.0, previous = 0.0, area = 0.0;
    auto flush = [&] {
      if (area >= kMinArea) regions_of(room, tris, g.normal, cluster, planes);
      cluster.clear();
      area = 0.0;
    };
    for (const auto& [d, i] : by_offset) {
      if (!cluster.empty() && (d - previous > kOffsetGap || d - start > kOffsetSpan)) flush();
      if (cluster.empty()) start = d;
      cluster.push_back(i);
      area += tris[i].area;
      previous = d;
    }
    flush();
  }

  // Labels: the lowest big upward level is the floor, the highest big downward one the ceiling.
  auto big_level = [&](XrSpatialPlaneAlignmentEXT alignment, bool lowest) -> std::optional<double> {
    double largest = 0.0;
    for (const ServedPlane& p : planes)
      if (p.alignment == alignment) largest = std::max(largest, double(p.extents.width) * p.extents.height);
    std::optional<double> level;
    for (const ServedPlane& p : planes) {
      if (p.alignment != alignment || double(p.extents.width) * p.extents.height < 0.25 * largest) continue;
      const double y = p.pose.translation.y;
      if (!level || (lowest ? y < *level : y > *level)) level = y;
    }
    return level;
  };
  const std::optional<double> floor_y = big_level(XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT, true);
  const std::optional<double> ceiling_y = big_level(XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT, false);
  for (ServedPlane& p : planes) {
    const double y = p.pose.translation.y;
    switch (p.alignment) {
      case XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT:
        if (floor_y && std::fabs(y - *floor_y) <= kLevelTolerance) p.label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT;
        else if (floor_y && y - *floor_y >= 0.3 && y - *floor_y <= 1.5) p.label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT;
        break;
      case XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT:
        if (ceiling_y && std::fabs(y - *ceiling_y) <= kLevelTolerance) p.label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT;
        break;
      case XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT: p.label = XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT; break;
      default: break;
    }
  }
  return planes;
}

}  // namespace

XrSpatialPlaneSemanticLabelEXT plane_label_for(const std::string& label) {
  static const std::map<std::string, XrSpatialPlaneSemanticLabelEXT> labels = {
      {"FLOOR", XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT},
      {"CEILING", XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT},
      {"WALL_FACE", XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT},
      {"INNER_WALL_FACE", XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT},
      {"INVISIBLE_WALL_FACE", XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT},
      {"TABLE", XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT},
  };
  const auto it = labels.find(label);
  return it == labels.end() ? XR_SPATIAL_PLANE_SEMANTIC_LABEL_UNCATEGORIZED_EXT : it->second;
}

std::vector<ServedPlane> extract_planes(const Room& room) {
  if (room.objects.empty()) return planes_of_mesh(room);
  std::vector<ServedPlane> planes;
  for (const RoomObject& object : room.objects) {
    if (!(object.plane_size.width > 0.0f) || !(object.plane_size.height > 0.0f)) continue;
    ServedPlane p;
    p.pose = to_rigid(object.plane_pose);
    p.extents = object.plane_size;
    p.alignment = alignment_of(p.pose.rotation * glm::dvec3(0, 0, 1));
    p.label = plane_label_for(object.label);
    fill_rectangle(p);
    planes.push_back(std::move(p));
  }
  return planes;
}

}  // namespace roomsense::sim
