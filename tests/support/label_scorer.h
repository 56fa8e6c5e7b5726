// Scores placement areas against a labelled scene (a Quest capture or an MRUK room), by the rules of issue 14,
// which are what a person accepts:
// - a wall area lies within 0.2 m of a labelled wall face, over it, facing into the room, and overlaps no
//   window or door frame;
// - a floor or ceiling area lies inside the room's labelled outline (the chain of its wall faces), at the
//   floor or ceiling, and a floor area on free floor (no labelled furniture footprint under it);
// - a furniture area lies on the top (or seat) of a labelled table, couch, bed, storage or similar.
// Coverage: the share of the labelled free floor (inside the outline, off furniture footprints) and of the
// labelled free wall (wall faces off windows, doors, wall art and screens, not hidden behind furniture taller
// than the point) that areas of that type cover, on a 5 cm raster.
#pragma once
#include "roomsense/areas.h"
#include "roomsense/quest_capture.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace roomsense::test {

using scanio::OrientedRect;

struct LabelledScene {
  std::vector<OrientedRect> walls, floors, ceilings, openings, wall_objects, tops;
  struct Footprint {
    OrientedRect top;  // the volume's top face; the footprint is its projection onto the floor
  };
  std::vector<Footprint> footprints;
  std::vector<glm::vec2> outline;  // x, z; the wall faces' bottom edges, chained
};

inline bool is_wall_label(const std::string& l) {
  return l == "WALL_FACE" || l == "INNER_WALL_FACE" || l == "INVISIBLE_WALL_FACE";
}
inline bool is_furniture_top_label(const std::string& l) {
  return l == "TABLE" || l == "COUCH" || l == "BED" || l == "STORAGE" || l == "CHAIR" || l == "SHELF" ||
         l == "OTHER";
}

// p in the rectangle's frame: x, y in its plane, z the height above it.
inline glm::vec3 local_of(const OrientedRect& r, const glm::vec3& p) {
  return glm::inverse(r.pose.orientation) * (p - r.pose.position);
}
inline bool within(const OrientedRect& r, const glm::vec3& p, float margin) {
  const glm::vec3 l = local_of(r, p);
  return std::abs(l.x) <= 0.5f * r.width + margin && std::abs(l.y) <= 0.5f * r.height + margin;
}
inline glm::vec3 normal_of(const OrientedRect& r) { return r.pose.orientation * glm::vec3(0, 0, 1); }

// The wall faces' bottom edges chained into a polygon: from each edge's end to the nearest free start.
inline std::vector<glm::vec2> chain_outline(const std::vector<OrientedRect>& walls) {
  struct Edge {
    glm::vec2 a, b;
  };
  std::vector<Edge> edges;
  for (const OrientedRect& w : walls) {
    const glm::vec3 x = w.pose.orientation * glm::vec3(1, 0, 0);
    const glm::vec3 a = w.pose.position - 0.5f * w.width * x, b = w.pose.position + 0.5f * w.width * x;
    edges.push_back({{a.x, a.z}, {b.x, b.z}});
  }
  std::vector<glm::vec2> out;
  if (edges.empty()) return out;
  std::vector<bool> used(edges.size(), false);
  std::size_t at = 0;
  for (std::size_t n = 0; n < edges.size(); ++n) {
    used[at] = true;
    out.push_back(edges[at].a);
    float best = 1e30f;
    std::size_t next = at;
    for (std::size_t j = 0; j < edges.size(); ++j) {
      if (used[j]) continue;
      for (int flip = 0; flip < 2; ++flip) {
        const float d = glm::distance(edges[at].b, flip ? edges[j].b : edges[j].a);
        if (d < best) best = d, next = j;
      }
    }
    if (next == at) break;
    if (glm::distance(edges[at].b, edges[next].b) < glm::distance(edges[at].b, edges[next].a))
      std::swap(edges[next].a, edges[next].b);
    at = next;
  }
  return out;
}

inline bool inside_polygon(const std::vector<glm::vec2>& poly, glm::vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
        p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
      in = !in;
  return in;
}

inline float distance_to_polygon(const std::vector<glm::vec2>& poly, glm::vec2 p) {
  float best = 1e30f;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const glm::vec2 e = poly[i] - poly[j];
    const float t = std::clamp(glm::dot(p - poly[j], e) / std::max(glm::dot(e, e), 1e-12f), 0.0f, 1.0f);
    best = std::min(best, glm::distance(p, poly[j] + t * e));
  }
  return best;
}

inline LabelledScene labelled_scene(const scanio::QuestCapture& c) {
  LabelledScene s;
  for (const scanio::QuestPlane& p : c.planes) {
    const OrientedRect r = scanio::plane_rect(p);
    if (is_wall_label(p.label)) s.walls.push_back(r);
    if (p.label == "FLOOR") s.floors.push_back(r);
    if (p.label == "CEILING") s.ceilings.push_back(r);
    if (p.label == "WINDOW_FRAME" || p.label == "DOOR_FRAME") s.openings.push_back(r);
    if (p.label == "WALL_ART" || p.label == "SCREEN") s.wall_objects.push_back(r);
    // A furniture plane is its top or seat (a couch's seat lies below its volume's top, the backrest).
    if (is_furniture_top_label(p.label)) s.tops.push_back(r);
  }
  for (const scanio::QuestVolume& v : c.volumes) {
    const OrientedRect top = scanio::volume_top_rect(v);
    if (is_furniture_top_label(v.label)) s.tops.push_back(top);
    s.footprints.push_back({top});
  }
  s.outline = chain_outline(s.walls);
  return s;
}

struct SceneScore {
  int areas = 0, valid = 0;
  std::map<std::string, int> faults;  // what made areas invalid, e.g. "wall over a window"
  double free_floor_covered = 0, free_wall_covered = 0;
  double valid_share() const { return areas ? double(valid) / areas : 1.0; }
  std::string main_faults() const {
    std::vector<std::pair<int, std::string>> by_count;
    for (const auto& [what, n] : faults) by_count.push_back({-n, what});
    std::sort(by_count.begin(), by_count.end());
    std::string out;
    for (std::size_t i = 0; i < by_count.size() && i < 3; ++i)
      out += (i ? ", " : "") + std::to_string(-by_count[i].first) + " " + by_count[i].second;
    return out.empty() ? "none" : out;
  }
};

inline bool under_furniture(const LabelledScene& s, glm::vec2 p, float margin) {
  return std::any_of(s.footprints.begin(), s.footprints.end(), [&](const LabelledScene::Footprint& f) {
    return within(f.top, glm::vec3(p.x, f.top.pose.position.y, p.y), margin);
  });
}
inline bool under_furniture_taller_than(const LabelledScene& s, glm::vec2 p, float y) {
  return std::any_of(s.footprints.begin(), s.footprints.end(), [&](const LabelledScene::Footprint& f) {
    return f.top.pose.position.y > y && within(f.top, glm::vec3(p.x, f.top.pose.position.y, p.y), 0.0f);
  });
}

inline bool covers(const Area& a, const glm::vec3& p, float plane_tolerance) {
  const glm::vec3 d = p - a.center;
  return std::abs(glm::dot(d, a.x_axis())) <= a.half_width && std::abs(glm::dot(d, a.y_axis())) <= a.half_height &&
         std::abs(glm::dot(d, a.normal)) <= plane_tolerance;
}

// Does the area overlap the rectangle r lying in (nearly) the same plane? Overlaps of a voxel's width or less
// (a frame's edge) are tolerated.
inline bool overlaps_in_plane(const Area& a, const OrientedRect& r) {
  if (std::abs(local_of(r, a.center).z) > 0.3f) return false;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& c : a.corners) {
    const glm::vec3 l = local_of(r, c);
    lo = glm::min(lo, glm::vec2(l.x, l.y));
    hi = glm::max(hi, glm::vec2(l.x, l.y));
  }
  const float ox = std::min(hi.x, 0.5f * r.width) - std::max(lo.x, -0.5f * r.width);
  const float oy = std::min(hi.y, 0.5f * r.height) - std::max(lo.y, -0.5f * r.height);
  return ox > 0.05f && oy > 0.05f;
}

inline SceneScore score_areas(const LabelledScene& s, const std::vector<Area>& areas) {
  SceneScore out;
  const float floor_y = s.floors.empty() ? 0.0f : s.floors.front().pose.position.y;
  const float ceiling_y = s.ceilings.empty() ? 1e30f : s.ceilings.front().pose.position.y;
  const auto inside = [&](const glm::vec3& p, float margin) {
    const glm::vec2 q(p.x, p.z);
    return inside_polygon(s.outline, q) || distance_to_polygon(s.outline, q) <= margin;
  };
  for (const Area& a : areas) {
    ++out.areas;
    std::string fault;
    if (a.type == AreaType::Wall) {
      bool on_wall = false, facing_out = false;
      for (const OrientedRect& w : s.walls) {
        if (!within(w, a.center, 0.1f) || std::abs(local_of(w, a.center).z) > 0.2f) continue;
        (glm::dot(normal_of(w), a.normal) > 0.7f ? on_wall : facing_out) = true;
      }
      if (!on_wall) fault = facing_out ? "wall facing out of the room" : "wall not on a wall";
      else if (std::any_of(s.openings.begin(), s.openings.end(), [&](const OrientedRect& o) { return overlaps_in_plane(a, o); }))
        fault = "wall over a window or door";
    } else if (a.type == AreaType::Floor || a.type == AreaType::Ceiling) {
      const bool floor = a.type == AreaType::Floor;
      const float level = floor ? floor_y : ceiling_y;
      bool in = inside(a.center, 0.0f);
      for (const glm::vec3& c : a.corners) in = in && inside(c, 0.1f);
      if (!in) fault = std::string(floor ? "floor" : "ceiling") + " outside the room";
      else if (std::abs(a.center.y - level) > 0.2f) fault = std::string(floor ? "floor" : "ceiling") + " off its level";
      else if (floor) {
        bool free = !under_furniture(s, {a.center.x, a.center.z}, -0.1f);
        for (const glm::vec3& c : a.corners) free = free && !under_furniture(s, {c.x, c.z}, -0.1f);
        if (!free) fault = "floor under furniture";
      }
    } else {
      bool over_any = false, at_height = false;
      for (const OrientedRect& t : s.tops) {
        if (!within(t, glm::vec3(a.center.x, t.pose.position.y, a.center.z), 0.1f)) continue;
        over_any = true;
        at_height = at_height || std::abs(a.center.y - t.pose.position.y) < 0.15f;
      }
      if (!at_height) fault = over_any ? "furniture at another height" : "furniture not on a furniture top";
    }
    if (fault.empty()) ++out.valid;
    else ++out.faults[fault];
  }

  // Free floor: 5 cm raster inside the outline, 0.1 m away from it and from furniture footprints.
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec2& p : s.outline) lo = glm::min(lo, p), hi = glm::max(hi, p);
  int floor_points = 0, floor_hit = 0;
  for (float x = lo.x; x <= hi.x; x += 0.05f)
    for (float z = lo.y; z <= hi.y; z += 0.05f) {
      const glm::vec2 p(x, z);
      if (!inside_polygon(s.outline, p) || distance_to_polygon(s.outline, p) < 0.1f || under_furniture(s, p, 0.1f))
        continue;
      ++floor_points;
      const glm::vec3 q(x, floor_y, z);
      floor_hit += std::any_of(areas.begin(), areas.end(), [&](const Area& a) {
        return a.type == AreaType::Floor && covers(a, q, 0.2f);
      });
    }
  // Free wall: 5 cm raster on the wall faces, 0.15 m in from their edges; off openings, wall art and screens;
  // not behind furniture within 1 m in front that rises above the point.
  int wall_points = 0, wall_hit = 0;
  for (const OrientedRect& w : s.walls) {
    const glm::vec3 n = normal_of(w);
    for (float u = -0.5f * w.width + 0.15f; u <= 0.5f * w.width - 0.15f; u += 0.05f)
      for (float v = -0.5f * w.height + 0.15f; v <= 0.5f * w.height - 0.15f; v += 0.05f) {
        const glm::vec3 p = w.pose.apply(glm::vec3(u, v, 0.0f));
        if (p.y < floor_y + 0.15f || p.y > ceiling_y - 0.15f) continue;
        const auto on = [&](const OrientedRect& r) { return std::abs(local_of(r, p).z) < 0.3f && within(r, p, 0.0f); };
        if (std::any_of(s.openings.begin(), s.openings.end(), on) ||
            std::any_of(s.wall_objects.begin(), s.wall_objects.end(), on))
          continue;
        bool hidden = false;
        for (float d = 0.1f; d <= 1.0f && !hidden; d += 0.1f) {
          const glm::vec3 f = p + d * n;
          hidden = under_furniture_taller_than(s, {f.x, f.z}, p.y);
        }
        if (hidden) continue;
        ++wall_points;
        wall_hit += std::any_of(areas.begin(), areas.end(), [&](const Area& a) {
          return a.type == AreaType::Wall && covers(a, p, 0.25f);
        });
      }
  }
  out.free_floor_covered = floor_points ? double(floor_hit) / floor_points : 0.0;
  out.free_wall_covered = wall_points ? double(wall_hit) / wall_points : 0.0;
  return out;
}

}  // namespace roomsense::test
