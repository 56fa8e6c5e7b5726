// Eq. 3.54-3.58: a reduced rectangle in metres, in our right-handed frame with counter-clockwise corners.
#include "classify.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace roomsense::detail {
namespace {

glm::vec3 voxel_centre(const GridSpec& spec, const glm::ivec3& v) {  // Eq. 3.54
  return spec.lattice_to_world(float(v.x) + 0.5f, float(v.y) + 0.5f, float(v.z) + 0.5f);
}

// Eq. 3.55 for walls, derived for our frame: the normal is horizontal and at a right angle to the top edge,
// on the side the wall normals F of the two corner voxels point to (away from the wall, Alg. 1). Where they
// do not decide, the side without a wall column next to the edge's middle is the room side, as the thesis's
// check of wall pieces around corner 1.
glm::vec3 wall_normal(const Candidate& c, const PlacementContext& ctx) {
  const GridSpec& s = ctx.spec;
  const glm::ivec3 &p1 = c.corners[0], &p2 = c.corners[1];
  glm::vec3 perp(-float(p2.z - p1.z), 0.0f, float(p2.x - p1.x));
  perp = glm::normalize(perp);
  const auto bits = [&](const glm::ivec3& v) { return ctx.features.normals[s.index(v.x, v.y, v.z)]; };
  const float vote = glm::dot(normal_bits_direction(bits(p1)) + normal_bits_direction(bits(p2)), perp);
  if (vote > 0.0f) return perp;
  if (vote < 0.0f) return -perp;
  const glm::vec2 mid(0.5f * float(p1.x + p2.x), 0.5f * float(p1.z + p2.z));
  const auto wall_at = [&](float side) {
    const int x = int(std::lround(mid.x + side * perp.x)), z = int(std::lround(mid.y + side * perp.z));
    return x >= 0 && z >= 0 && x < s.nx && z < s.nz && ctx.features.walls[s.column(x, z)] != 0;
  };
  return wall_at(1.0f) && !wall_at(-1.0f) ? -perp : perp;
}

// Beyond the thesis (issue 15): the plane of the ceiling facet under a ceiling square's centre, when it has
// one (a roof's slope, a soffit's underside).
std::optional<glm::vec3> ceiling_plane(const Candidate& c, AreaType type, const PlacementContext& ctx) {
  if (type != AreaType::Ceiling || ctx.features.ceiling_facet.empty()) return std::nullopt;
  const GridSpec& s = ctx.spec;
  const glm::ivec3 sum = corner_sum(c);
  const int x = std::clamp((sum.x + 2) / 4, 0, s.nx - 1), z = std::clamp((sum.z + 2) / 4, 0, s.nz - 1);
  const int facet = ctx.features.ceiling_facet[s.column(x, z)];
  if (facet <= 0 || std::size_t(facet) > ctx.surfaces.ceiling_planes.size()) return std::nullopt;
  return ctx.surfaces.ceiling_planes[std::size_t(facet - 1)];
}

// The ceiling square `a` (its footprint seen from above) lifted onto the plane y = p.x x + p.y z + p.z: a
// rectangle on the plane around the footprint's lifted centre, its first edge the lifted first edge, its
// normal the plane's, downwards into the room.
void place_on_plane(const glm::vec3& p, Area& a) {
  const auto lift = [&](const glm::vec3& q) { return glm::vec3(q.x, p.x * q.x + p.y * q.z + p.z, q.z); };
  const glm::vec3 centre = lift(0.25f * (a.corners[0] + a.corners[1] + a.corners[2] + a.corners[3]));
  a.normal = glm::normalize(glm::vec3(p.x, -1.0f, p.y));
  const glm::vec3 e1 = lift(a.corners[1]) - lift(a.corners[0]), e2 = lift(a.corners[2]) - lift(a.corners[1]);
  const glm::vec3 x = glm::normalize(e1 - glm::dot(e1, a.normal) * a.normal), y = glm::cross(a.normal, x);
  const float hw = 0.5f * glm::length(e1), hh = 0.5f * std::fabs(glm::dot(e2, y));
  a.corners = {centre - hw * x - hh * y, centre + hw * x - hh * y, centre + hw * x + hh * y, centre - hw * x + hh * y};
}

}  // namespace

glm::vec3 normal_bits_direction(std::uint8_t bits) {
  glm::vec3 d(0.0f);
  if (bits & kNormalLeft) d.x -= 1.0f;
  if (bits & kNormalRight) d.x += 1.0f;
  if (bits & kNormalForward) d.z += 1.0f;
  if (bits & kNormalBackward) d.z -= 1.0f;
  return d;
}

namespace {

// A horizontal area's corners at height y: v1..v4 run clockwise seen from above (Eq. 3.28); upward areas reverse
// them to run counter-clockwise seen from their front. The start is the corner whose first edge makes the
// rotation lie in [0°, 90°).
std::array<glm::vec3, 4> horizontal_corners(const Candidate& c, bool up, float y, const GridSpec& s) {
  std::array<glm::ivec3, 4> v = c.corners;
  if (up) std::swap(v[1], v[3]);
  std::size_t start = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const glm::ivec3 e = v[(k + 1) % 4] - v[k];
    if (e.x > 0 && (up ? e.z <= 0 : e.z >= 0)) start = k;
  }
  std::array<glm::vec3, 4> corners;
  for (std::size_t k = 0; k < 4; ++k) {
    glm::vec3 p = voxel_centre(s, v[(start + k) % 4]);
    p.y = y;
    corners[k] = p;
  }
  return corners;
}

glm::vec3 centre_of(const std::array<glm::vec3, 4>& corners) {  // Eq. 3.42
  return 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
}

float half_width_of(const std::array<glm::vec3, 4>& corners) { return 0.5f * glm::distance(corners[0], corners[1]); }  // Eq. 3.56

}  // namespace

ReachFloor reach_floor(const Sized& found, const PlacementContext& ctx) {
  const std::array<glm::vec3, 4> corners = horizontal_corners(found.c(), true, ctx.surfaces.floor_y, ctx.spec);
  const glm::vec3 centre = centre_of(corners);
  return ReachFloor(glm::vec2(centre.x, centre.z), half_width_of(corners));
}

Area to_area(const Sized& found, AreaType type, const PlacementContext& ctx) {
  const GridSpec& s = ctx.spec;
  const Candidate c = found.c();
  const float voxel = s.voxel_size;
  Area a;
  a.type = type;
  a.size = found.size;
  if (type == AreaType::Wall) {
    a.normal = wall_normal(c, ctx);
    // Walls sit on the wall-side face of the free voxels F marks (Alg. 1), not at their centres (Eq. 3.54):
    // half a voxel nearer the wall, so content is placed on the wall rather than floating in front of it.
    std::array<glm::vec3, 4> p;
    for (std::size_t i = 0; i < 4; ++i) p[i] = voxel_centre(s, c.corners[i]) - a.normal * (0.5f * voxel);
    const glm::vec3 x_axis(a.normal.z, 0.0f, -a.normal.x);  // up × normal, so that X × Y = normal
    // Thesis order p1, p2 on top, p3, p4 below; ours starts bottom-left seen from the room.
    a.corners = glm::dot(p[1] - p[0], x_axis) >= 0.0f ? std::array{p[3], p[2], p[1], p[0]}
                                                      : std::array{p[2], p[3], p[0], p[1]};
    a.volume_height = ctx.feature_params.wall_normal_reach;
  } else {
    // Horizontal areas lie on the surface rather than at the centre of the free voxel above it (Eq. 3.54):
    // floors and ceilings at the measured surface height, furniture on top of its highest voxel (y_Actual).
    float y = 0.0f;
    if (type == AreaType::Floor) y = ctx.surfaces.floor_y;
    if (type == AreaType::Ceiling) y = ctx.surfaces.ceiling_y;
    if (type == AreaType::Furniture) y = s.origin.y + float(c.corners[0].y) * voxel;
    const bool up = type != AreaType::Ceiling;
    a.normal = glm::vec3(0.0f, up ? 1.0f : -1.0f, 0.0f);  // Eq. 3.55
    a.corners = horizontal_corners(c, up, y, s);
    const glm::vec3 e = a.corners[1] - a.corners[0];
    if (const auto plane = ceiling_plane(c, type, ctx)) place_on_plane(*plane, a);
    // Eq. 3.57 as a signed angle about the normal: about -Y for ceilings, so the thesis's "negative rotation".
    a.rotation_deg = float(std::atan2(up ? -e.z : e.z, e.x) * 180.0 / std::numbers::pi);
    const FeatureParams& fp = ctx.feature_params;
    a.volume_height = type == AreaType::Floor ? fp.furniture_top : type == AreaType::Ceiling ? fp.ceiling_clear
                                                                                          : fp.furniture_clear;
  }
  a.center = centre_of(a.corners);
  a.half_width = half_width_of(a.corners);
  a.half_height = 0.5f * glm::distance(a.corners[1], a.corners[2]);
  a.reach = Reach::None;
  a.flags = category_flags(a.type, a.size, a.reach);
  return a;
}

}  // namespace roomsense::detail
