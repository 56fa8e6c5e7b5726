// raycast and locate (queries.h): a voxel walk (Amanatides and Woo, "A Fast Voxel Traversal Algorithm", 1987)
// through the grid, stopping at the first scanned voxel or where the ray leaves the room's free space.
#include "query_support.h"
#include "room_index.h"

#include "roomsense/error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomsense {
namespace {

// What a voxel of the scan is, by where it lies: the floor's band, the ceiling's, a wall column (Eq. 3.11), else
// furniture or clutter.
AreaType kind_of(const RoomQueries::Index& ix, int x, int y, int z) {
  if (y <= ix.levels.floor) return AreaType::Floor;
  if (y >= ix.levels.ceiling) return AreaType::Ceiling;
  if (ix.walls[ix.spec.column(x, z)]) return AreaType::Wall;
  return AreaType::Furniture;
}

}  // namespace

RoomLocation RoomQueries::locate(const glm::vec3& point) const {
  RoomLocation out;
  if (!index_ || !std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) return out;
  const Index& ix = *index_;
  const GridSpec& s = ix.spec;
  const glm::vec3 g = (point - s.origin) / s.voxel_size;
  if (!(g.x >= 0.0f && g.z >= 0.0f && g.x < float(s.nx) && g.z < float(s.nz))) return out;
  const int x = int(g.x), z = int(g.z);
  out.inside = ix.inside[s.column(x, z)] && point.y >= ix.floor_y && point.y <= ix.ceiling_y;
  const int y = int(std::floor(g.y));
  out.free = out.inside && !(y >= 0 && y < s.ny && ix.cells[s.index(x, y, z)]);
  return out;
}

std::optional<RayHit> RoomQueries::raycast(const glm::vec3& origin, const glm::vec3& direction,
                                           float max_distance) const {
  detail::check_finite(origin, "the ray's origin");
  detail::check_finite(direction, "the ray's direction");
  const float length = glm::length(direction);
  if (!(length > 1e-12f) || !std::isfinite(length)) throw Error(ErrorCode::BadParameter, "the ray's direction must not be zero");
  if (std::isnan(max_distance) || max_distance < 0.0f)
    throw Error(ErrorCode::BadParameter, "the ray's max_distance must not be negative");
  if (!index_) return std::nullopt;
  const Index& ix = *index_;
  const GridSpec& s = ix.spec;
  const glm::dvec3 d = glm::dvec3(direction) / double(length);
  const glm::dvec3 o = (glm::dvec3(origin) - glm::dvec3(s.origin)) / double(s.voxel_size);  // grid units
  const double voxel = s.voxel_size;
  const glm::dvec3 size(s.nx, s.ny, s.nz);

  // Where the ray enters the grid's box (slab test), and through which face.
  double t = 0.0, t_exit = std::numeric_limits<double>::infinity();
  int entry_axis = -1;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < 0.0 || o[a] >= size[a]) return std::nullopt;
      continue;
    }
    double t0 = (0.0 - o[a]) / d[a], t1 = (size[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t) {
      t = t0;
      entry_axis = a;
    }
    t_exit = std::min(t_exit, t1);
  }
  const double t_max = std::min(t_exit, double(max_distance) / voxel);
  if (t > t_max) return std::nullopt;

  glm::ivec3 cell;
  glm::ivec3 step;
  glm::dvec3 next, delta;
  const glm::dvec3 p = o + d * t;
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::clamp(int(std::floor(p[a])), 0, int(size[a]) - 1);
    if (entry_axis == a) cell[a] = d[a] > 0.0 ? 0 : int(size[a]) - 1;
    step[a] = d[a] > 0.0 ? 1 : d[a] < 0.0 ? -1 : 0;
    delta[a] = step[a] == 0 ? std::numeric_limits<double>::infinity() : 1.0 / std::abs(d[a]);
    next[a] = step[a] == 0 ? std::numeric_limits<double>::infinity()
                           : ((step[a] > 0 ? cell[a] + 1 : cell[a]) - o[a]) / d[a];
  }
  int axis = entry_axis;  // the face the walk entered the current cell through; -1 at the origin
  bool was_inside = false;
  const auto hit_at = [&](double t_grid, AreaType kind, bool scanned) {
    RayHit h;
    h.surface = kind;
    h.scanned = scanned;
    h.normal = glm::vec3(0.0f);
    if (axis >= 0) h.normal[axis] = float(-step[axis]);
    else h.normal = -glm::vec3(d);
    double t_hit = t_grid;
    // Floors and ceilings: on their measured surface, where it lies beyond the voxel face the walk entered.
    if ((kind == AreaType::Floor || kind == AreaType::Ceiling) && axis == 1) {
      const double plane = ((kind == AreaType::Floor ? ix.floor_y : ix.ceiling_y) - s.origin.y) / voxel;
      const double t_plane = (plane - o.y) / d.y;
      // Up to the voxel's far face included: a scan whose floor lies on a voxel boundary (the grid starts there)
      // fills the voxel above it.
      if (t_plane > t_grid && t_plane <= t_grid + delta.y * (1.0 + 1e-6)) t_hit = t_plane;
    }
    h.distance = float(t_hit * voxel);
    h.position = origin + glm::vec3(d) * h.distance;
    return h;
  };
  const auto edge_kind = [&] { return axis == 1 ? (step.y < 0 ? AreaType::Floor : AreaType::Ceiling) : AreaType::Wall; };
  while (t <= t_max) {
    const bool occupied = ix.cells[s.index(cell.x, cell.y, cell.z)] != 0;
    if (occupied) return hit_at(t, kind_of(ix, cell.x, cell.y, cell.z), true);
    const bool inside = !outside_room(ix, cell.x, cell.y, cell.z);
    if (was_inside && !inside) return hit_at(t, edge_kind(), false);
    was_inside = inside;
    axis = next.x < next.y ? (next.x < next.z ? 0 : 2) : (next.y < next.z ? 1 : 2);
    t = next[axis];
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= int(size[axis])) {  // leaving the grid is leaving the room too
      if (was_inside && t <= t_max) return hit_at(t, edge_kind(), false);
      break;
    }
    next[axis] += delta[axis];
  }
  return std::nullopt;
}

}  // namespace roomsense
