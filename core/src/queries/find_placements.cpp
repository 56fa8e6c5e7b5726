// find_placements (queries.h): every spot of the asked surfaces that may hold the object's clear box is scored at
// once from a distance transform of the free surface (horizontal surfaces) or checked exactly from prefix sums
// (walls); then, best first, each is checked cell by cell at the rotations allowed until max_count are found.
// A footprint is accepted only when every raster cell it shares area with is free surface of its kind (and, on a
// furniture top, every cell of its clearance is that top or free air), so it lies on free surface by construction.
#include "distance_transform.h"
#include "footprint.h"
#include "query_support.h"
#include "room_index.h"

#include "roomsense/error.h"
#include "roomsense/number_text.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>

namespace roomsense {
namespace {

using detail::ClearBox;
using detail::RasterRect;

constexpr float kMarginCap = 0.5f;   // more free space around a spot than this makes it no better
constexpr float kJitter = 0.05f;     // seeded, so equally good spots come in a different order per seed
constexpr float kFaceWeight = 0.25f; // walls facing face_direction rank higher, by up to this

struct Need {
  float half_w = 0, half_d = 0;
  float grow = 0;        // on the surface: max(clearance, edge distance)
  float edge = 0, clearance = 0;
  float up = 0;          // size.z + clearance_above
};

struct Spot {
  float score = 0;
  std::uint64_t key = 0;  // unique per spot: a total, deterministic order
  AreaType type = AreaType::Floor;
  std::uint32_t face = 0;
  int a = 0, b = 0;       // horizontal: half-cell lattice (x, z); walls: half-cell steps along u and up
  float margin = 0;
};

// The order of spots: higher score first, then lower key (a total order, so the result is deterministic).
bool worse(const Spot& l, const Spot& r) { return l.score != r.score ? l.score < r.score : l.key > r.key; }

struct Found {
  Placement placement;
  ClearBox object, clear;
};

float horizontal_part_angle(const glm::vec3& d) { return std::atan2(d.z, d.x); }

// The footprint's x axis in the world for a world angle phi in the x-z plane.
glm::vec3 axis_at(float phi) { return glm::vec3(std::cos(phi), 0.0f, std::sin(phi)); }

class Search {
 public:
  Search(const RoomQueries::Index& ix, const PlacementQuery& q) : ix_(ix), q_(q) {
    need_.half_w = 0.5f * q.size.x;
    need_.half_d = 0.5f * q.size.y;
    need_.edge = q.edge_distance;
    need_.clearance = q.clearance;
    need_.grow = std::max(q.clearance, q.edge_distance);
    need_.up = q.size.z + q.clearance_above;
    const glm::vec3 face(q.face_direction.x, 0.0f, q.face_direction.z);
    if (glm::length(face) > 1e-6f) face_ = glm::normalize(face);
  }

  // Every spot that may hold the clear box, scored, as a heap: best() takes them out best first. Most queries
  // take a few dozen of tens of thousands, so ordering them all would cost more than the rest of the query.
  // `up` is the clear space asked along the normal.
  std::vector<Spot> spots(float up) const {
    std::vector<Spot> out;
    out.reserve(4 * ix_.spec.column_count() + 4 * ix_.wall_cells.size());
    for (AreaType type : {AreaType::Floor, AreaType::Ceiling, AreaType::Furniture})
      if (q_.surfaces & surface_bit(type)) horizontal_spots(type, up, out);
    if (q_.surfaces & kOnWall) wall_spots(up, out);
    std::make_heap(out.begin(), out.end(), worse);
    return out;
  }
  static Spot best(std::vector<Spot>& heap) {
    std::pop_heap(heap.begin(), heap.end(), worse);
    const Spot spot = heap.back();
    heap.pop_back();
    return spot;
  }

  // The placement a spot holds, if any, ignoring reach and other placements.
  std::optional<Found> place(const Spot& spot, float up) const {
    return spot.type == AreaType::Wall ? place_on_wall(spot, up) : place_horizontal(spot, up);
  }

  Reach reach_of(const Found& f) const;
  const Need& need() const { return need_; }

 private:
  std::uint64_t key(AreaType type, std::uint64_t a, std::uint64_t b, std::uint64_t c) const {
    return (std::uint64_t(type) << 60) ^ (a << 40) ^ (b << 20) ^ c;
  }
  float jitter(std::uint64_t k) const {
    return kJitter * float(double(detail::mix64(k ^ detail::mix64(q_.seed)) >> 11) * 0x1.0p-53);
  }
  float base_score(std::uint64_t k, float margin, const glm::vec3& centre, const glm::vec3& normal) const {
    float score = q_.near ? -glm::distance(centre, *q_.near) : std::min(margin, kMarginCap);
    if (glm::length(face_) > 0.0f && normal.y == 0.0f) score += kFaceWeight * glm::dot(normal, face_);
    return score + jitter(k);
  }

  // Free surface of one kind with `up` metres clear along its normal, per column.
  std::vector<std::uint8_t> free_mask(AreaType type, float up) const;
  void horizontal_spots(AreaType type, float up, std::vector<Spot>& out) const;
  void wall_spots(float up, std::vector<Spot>& out) const;
  std::optional<Found> place_horizontal(const Spot& spot, float up) const;
  std::optional<Found> place_on_wall(const Spot& spot, float up) const;
  bool footprint_fits(AreaType type, const glm::dvec2& centre, const glm::vec3& x_axis, float up, int& level) const;

  const RoomQueries::Index& ix_;
  const PlacementQuery& q_;
  Need need_;
  glm::vec3 face_{0.0f};
};

std::vector<std::uint8_t> Search::free_mask(AreaType type, float up) const {
  const GridSpec& s = ix_.spec;
  std::vector<std::uint8_t> m(s.column_count(), 0);
  for (std::size_t c = 0; c < m.size(); ++c) {
    if (type == AreaType::Floor) m[c] = ix_.floor_clear[c] >= up;
    if (type == AreaType::Ceiling) m[c] = ix_.ceiling_clear[c] >= up;
    if (type == AreaType::Furniture) m[c] = ix_.top_region[c] >= 0 && ix_.top_clear[c] >= up;
  }
  if (type != AreaType::Furniture) return m;
  // A cell beside another top is that top's edge too: the distance transform then measures each top alone.
  std::vector<std::uint8_t> out = m;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const std::size_t c = s.column(x, z);
      if (!m[c]) continue;
      const int n[4][2] = {{x - 1, z}, {x + 1, z}, {x, z - 1}, {x, z + 1}};
      for (const auto& p : n)
        if (p[0] >= 0 && p[1] >= 0 && p[0] < s.nx && p[1] < s.nz) {
          const std::int32_t r = ix_.top_region[s.column(p[0], p[1])];
          if (r >= 0 && r != ix_.top_region[c]) out[c] = 0;
        }
    }
  return out;
}

void Search::horizontal_spots(AreaType type, float up, std::vector<Spot>& out) const {
  const GridSpec& s = ix_.spec;
  const float voxel = s.voxel_size;
  const std::vector<std::uint8_t> mask = free_mask(type, up);
  const std::vector<float> dist = detail::distance_to_unmasked(s.nx, s.nz, mask);
  // On a furniture top the clearance may lie in free air beside it; the edge distance may not.
  const float grow = type == AreaType::Furniture ? need_.edge : need_.grow;
  const float r_min = std::min(need_.half_w, need_.half_d) + grow;
  const float r_all = std::hypot(need_.half_w, need_.half_d) + grow;
  const auto d_at = [&](int x, int z) {
    return x < 0 || z < 0 || x >= s.nx || z >= s.nz ? 0.0f : dist[s.column(x, z)] * voxel;
  };
  const float half_diagonal = 0.5f * std::numbers::sqrt2_v<float> * voxel;
  // Cell centres (odd half-cell coordinates) and cell corners (even): footprints with an even or an odd number
  // of cells across both have a spot that fits them tightly.
  for (int hz = 0; hz <= 2 * s.nz; ++hz)
    for (int hx = 0; hx <= 2 * s.nx; ++hx) {
      if ((hx & 1) != (hz & 1)) continue;
      float upper = 0.0f;  // at least the distance from this point to the nearest cell outside the mask
      if (hx & 1) {
        upper = d_at(hx / 2, hz / 2);
      } else {
        upper = std::min({d_at(hx / 2 - 1, hz / 2 - 1), d_at(hx / 2, hz / 2 - 1), d_at(hx / 2 - 1, hz / 2),
                          d_at(hx / 2, hz / 2)}) + half_diagonal;
      }
      // Necessary for the footprint to cover no cell outside the mask: its inner disc keeps half a cell from
      // every such cell's centre.
      if (upper < r_min + 0.5f * voxel) continue;
      const int cx = std::min(hx / 2, s.nx - 1), cz = std::min(hz / 2, s.nz - 1);
      float y = type == AreaType::Floor ? ix_.floor_y : ix_.ceiling_y;
      if (type == AreaType::Furniture) {
        const int level = ix_.top_level[s.column(cx, cz)];
        y = level == kNoFurniture ? ix_.floor_y : ix_.top_y(level);
      }
      const glm::vec3 centre = s.origin + glm::vec3(0.5f * float(hx) * voxel, 0.0f, 0.5f * float(hz) * voxel);
      const float margin = std::max(0.0f, upper - 0.5f * voxel - r_all);
      Spot spot;
      spot.type = type;
      spot.a = hx;
      spot.b = hz;
      spot.margin = margin;
      spot.key = key(type, std::uint64_t(hx), std::uint64_t(hz), 0);
      spot.score = base_score(spot.key, margin, glm::vec3(centre.x, y, centre.z), glm::vec3(0.0f, 1.0f, 0.0f));
      out.push_back(spot);
    }
}

void Search::wall_spots(float up, std::vector<Spot>& out) const {
  const float voxel = ix_.spec.voxel_size;
  for (std::uint32_t fi = 0; fi < ix_.faces.size(); ++fi) {
    const WallFace& face = ix_.faces[fi];
    const int nu = face.nu, nv = face.nv;
    if (nv <= 0) continue;
    std::vector<std::uint8_t> free(std::size_t(nu) * std::size_t(nv));
    for (std::size_t c = 0; c < free.size(); ++c) free[c] = face.depth[c] > 0.0f && face.depth[c] >= up;
    // Prefix sums: any rectangle of cells is all free in O(1).
    std::vector<std::uint32_t> sum(std::size_t(nu + 1) * std::size_t(nv + 1), 0);
    const auto at = [&](int u, int v) -> std::uint32_t& { return sum[std::size_t(v) * std::size_t(nu + 1) + std::size_t(u)]; };
    for (int v = 0; v < nv; ++v)
      for (int u = 0; u < nu; ++u)
        at(u + 1, v + 1) = at(u, v + 1) + at(u + 1, v) - at(u, v) + free[std::size_t(v) * std::size_t(nu) + std::size_t(u)];
    const std::vector<float> dist = detail::distance_to_unmasked(nu, nv, free);
    constexpr double kEps = 1e-6;
    const float hw = need_.half_w + need_.grow, hh = need_.half_d + need_.grow;
    // Centres on cell centres for a footprint an odd number of cells across, on cell edges for an even number:
    // each then covers as few cells as it can. In half cells, so m and n count half-voxel steps.
    const auto odd_cells = [&](float half) { return (int(std::ceil(2.0f * half / voxel - 1e-4f)) & 1) != 0; };
    const int m_first = odd_cells(hw) ? 1 : 0, n_first = odd_cells(hh) ? 1 : 0;
    for (int n = n_first; n <= 2 * nv; n += 2) {
      const float yc = 0.5f * float(n) * voxel;  // metres above the face's lowest row
      const int v0 = int(std::floor((yc - hh) / voxel + kEps)), v1 = int(std::ceil((yc + hh) / voxel - kEps)) - 1;
      if (v0 < 0 || v1 >= nv || v1 < v0) continue;
      for (int m = m_first; m <= 2 * nu; m += 2) {
        const float uc = 0.5f * float(m) * voxel;
        const int u0 = int(std::floor((uc - hw) / voxel + kEps)), u1 = int(std::ceil((uc + hw) / voxel - kEps)) - 1;
        if (u0 < 0 || u1 >= nu || u1 < u0) continue;
        const std::uint32_t cells = std::uint32_t((u1 - u0 + 1) * (v1 - v0 + 1));
        if (at(u1 + 1, v1 + 1) - at(u0, v1 + 1) - at(u1 + 1, v0) + at(u0, v0) != cells) continue;
        const int cu = std::min(m / 2, nu - 1), cv = std::min(n / 2, nv - 1);
        const float margin = std::max(0.0f, dist[std::size_t(cv) * std::size_t(nu) + std::size_t(cu)] * voxel -
                                                std::hypot(hw, hh));
        const glm::vec3 centre = face.start + face.x_axis * uc + glm::vec3(0.0f, ix_.top_y(face.level0) + yc, 0.0f);
        Spot spot;
        spot.type = AreaType::Wall;
        spot.face = fi;
        spot.a = m;
        spot.b = n;
        spot.margin = margin;
        spot.key = key(AreaType::Wall, fi, std::uint64_t(m), std::uint64_t(n));
        spot.score = base_score(spot.key, margin, centre, face.normal);
        out.push_back(spot);
      }
    }
  }
}

bool Search::footprint_fits(AreaType type, const glm::dvec2& centre, const glm::vec3& x_axis, float up,
                            int& level) const {
  const GridSpec& s = ix_.spec;
  const double voxel = s.voxel_size;
  const glm::dvec2 u(x_axis.x, x_axis.z);
  const auto rect = [&](float grow) {
    return RasterRect{centre, u, (double(need_.half_w) + grow) / voxel, (double(need_.half_d) + grow) / voxel};
  };
  const auto in_grid = [&](int x, int z) { return x >= 0 && z >= 0 && x < s.nx && z < s.nz; };
  if (type != AreaType::Furniture) {
    const std::vector<float>& clear = type == AreaType::Floor ? ix_.floor_clear : ix_.ceiling_clear;
    return detail::for_cells_under(rect(need_.grow), [&](int x, int z) {
      return in_grid(x, z) && clear[s.column(x, z)] >= up;
    });
  }
  // A furniture top: the footprint and its edge distance on one top; the object stands on its highest cell.
  std::int32_t region = -1;
  level = kNoFurniture;
  const bool on_top = detail::for_cells_under(rect(need_.edge), [&](int x, int z) {
    if (!in_grid(x, z)) return false;
    const std::size_t c = s.column(x, z);
    if (ix_.top_region[c] < 0 || (region >= 0 && ix_.top_region[c] != region)) return false;
    region = ix_.top_region[c];
    level = std::max(level, ix_.top_level[c]);
    return true;
  });
  if (!on_top || region < 0) return false;
  const float base = ix_.top_y(level);
  const int levels_up = int(std::ceil(double(up) / voxel - 1e-6));
  // Every cell of the clear box: the same top with the space above it, or free air from the object's base up.
  return detail::for_cells_under(rect(need_.grow), [&](int x, int z) {
    if (!in_grid(x, z)) return false;
    const std::size_t c = s.column(x, z);
    if (ix_.top_region[c] == region) return ix_.top_y(ix_.top_level[c]) + ix_.top_clear[c] >= base + up;
    if (!ix_.inside[c] || ix_.walls[c]) return false;
    for (int y = level; y < level + levels_up; ++y)
      if (y >= s.ny || ix_.solid(x, y, z)) return false;
    return true;
  });
}

std::optional<Found> Search::place_horizontal(const Spot& spot, float up) const {
  const GridSpec& s = ix_.spec;
  const bool down = spot.type == AreaType::Ceiling;
  const glm::vec3 normal(0.0f, down ? -1.0f : 1.0f, 0.0f);
  const glm::dvec2 centre(0.5 * spot.a, 0.5 * spot.b);
  std::vector<float> angles;
  if (glm::length(face_) > 0.0f) {
    // +Y = normal × x along the facing direction: x = facing × normal.
    angles.push_back(horizontal_part_angle(glm::cross(face_, normal)));
  } else {
    const float base = float(-ix_.dominant_deg * std::numbers::pi / 180.0);
    const bool square = need_.half_w == need_.half_d;
    const float steps_square[] = {0, 45, 15, 30, 60, 75};
    const float steps[] = {0, 90, 45, 135, 15, 30, 60, 75, 105, 120, 150, 165};
    for (float deg : square ? std::span<const float>(steps_square) : std::span<const float>(steps))
      angles.push_back(base + deg * std::numbers::pi_v<float> / 180.0f);
  }
  for (float phi : angles) {
    const glm::vec3 x_axis = axis_at(phi);
    int level = kNoFurniture;
    if (!footprint_fits(spot.type, centre, x_axis, up, level)) continue;
    float y = spot.type == AreaType::Floor ? ix_.floor_y : spot.type == AreaType::Ceiling ? ix_.ceiling_y
                                                                                        : ix_.top_y(level);
    Found f;
    Placement& p = f.placement;
    p.surface = spot.type;
    p.center = glm::vec3(s.origin.x + float(centre.x) * s.voxel_size, y, s.origin.z + float(centre.y) * s.voxel_size);
    p.normal = normal;
    p.x_axis = x_axis;
    p.footprint = glm::vec2(q_.size.x, q_.size.y);
    p.height = q_.size.z;
    p.margin = spot.margin;
    const glm::vec2 c(p.center.x, p.center.z), u(x_axis.x, x_axis.z);
    const float y_far = down ? y - up : y + up;
    f.object = {c, u, need_.half_w, need_.half_d, std::min(y, down ? y - q_.size.z : y + q_.size.z),
                std::max(y, down ? y - q_.size.z : y + q_.size.z)};
    f.clear = {c, u, need_.half_w + need_.clearance, need_.half_d + need_.clearance, std::min(y, y_far),
               std::max(y, y_far)};
    return f;
  }
  return std::nullopt;
}

std::optional<Found> Search::place_on_wall(const Spot& spot, float up) const {
  (void)up;  // the spot was checked exactly against `up` already (wall_spots)
  const WallFace& face = ix_.faces[spot.face];
  const float voxel = ix_.spec.voxel_size;
  Found f;
  Placement& p = f.placement;
  p.surface = AreaType::Wall;
  p.center = face.start + face.x_axis * (0.5f * float(spot.a) * voxel) +
             glm::vec3(0.0f, ix_.top_y(face.level0) + 0.5f * float(spot.b) * voxel, 0.0f);
  p.normal = face.normal;
  p.x_axis = face.x_axis;
  p.storey = face.storey;
  p.footprint = glm::vec2(q_.size.x, q_.size.y);
  p.height = q_.size.z;
  p.margin = spot.margin;
  const glm::vec2 u(face.x_axis.x, face.x_axis.z), n(face.normal.x, face.normal.z), c(p.center.x, p.center.z);
  f.object = {c + n * (0.5f * q_.size.z), u, need_.half_w, 0.5f * q_.size.z, p.center.y - need_.half_d,
              p.center.y + need_.half_d};
  const float depth = need_.up;
  f.clear = {c + n * (0.5f * depth), u, need_.half_w + need_.clearance, 0.5f * depth,
             p.center.y - need_.half_d - need_.clearance, p.center.y + need_.half_d + need_.clearance};
  return f;
}

Reach Search::reach_of(const Found& f) const {
  const Placement& p = f.placement;
  const GridSpec& s = ix_.spec;
  const bool low_enough = p.center.y - ix_.floor_y <= ix_.close_height;
  const glm::vec2 c(p.center.x, p.center.z), u(f.object.u);
  const glm::vec2 across(-u.y, u.x);
  if (q_.user_position) {
    const glm::vec2 user(q_.user_position->x, q_.user_position->z);
    const glm::vec2 d = user - c;
    // Horizontal distance from the user to the footprint (a segment on walls).
    const float half_across = p.surface == AreaType::Wall ? 0.0f : need_.half_d;
    const float du = std::max(std::abs(glm::dot(d, u)) - need_.half_w, 0.0f);
    const float dv = std::max(std::abs(glm::dot(d, across)) - half_across, 0.0f);
    if (low_enough && std::hypot(du, dv) <= q_.user_reach) return Reach::Close;
    // §3.5.1: a wall area is seen from within the view cone in front of it.
    if (p.surface == AreaType::Wall) {
      const glm::vec2 n(p.normal.x, p.normal.z);
      const float cone = std::cos(AreaParams{}.wall_view_cone_deg * std::numbers::pi_v<float> / 180.0f);
      if (glm::length(d) < 1e-6f || glm::dot(glm::normalize(d), n) < cone) return Reach::None;
    }
    return Reach::Distance;
  }
  // From any free floor a person stands on: the nearest one to the footprint's centre, its corners, or (walls)
  // the point a voxel in front of it.
  const auto stand = [&](const glm::vec3& w) {
    const int x = int(std::floor((w.x - s.origin.x) / s.voxel_size)), z = int(std::floor((w.z - s.origin.z) / s.voxel_size));
    if (x < 0 || z < 0 || x >= s.nx || z >= s.nz) return std::numeric_limits<float>::infinity();
    return ix_.stand_distance[s.column(x, z)];
  };
  float nearest = std::numeric_limits<float>::infinity();
  if (p.surface == AreaType::Wall) {
    nearest = stand(p.center + p.normal * s.voxel_size);
  } else {
    nearest = stand(p.center);
    for (const glm::vec3& corner : p.corners()) nearest = std::min(nearest, stand(corner));
  }
  const bool close = low_enough && nearest <= ix_.close_distance + 0.5f * s.voxel_size;
  return close ? Reach::Close : Reach::Distance;
}

void check_query(const PlacementQuery& q) {
  using namespace detail;
  check_finite(q.size, "size");
  if (!(q.size.x > 0.0f && q.size.y > 0.0f && q.size.z > 0.0f))
    throw Error(ErrorCode::BadParameter, "size must be positive in all three directions");
  check_length(q.size.x, "size.x");
  check_length(q.size.y, "size.y");
  check_length(q.size.z, "size.z");
  check_length(q.clearance, "clearance");
  check_length(q.clearance_above, "clearance_above");
  check_length(q.edge_distance, "edge_distance");
  check_length(q.user_reach, "user_reach");
  check_surfaces(q.surfaces);
  if (q.reach != ReachFilter::Any && q.reach != ReachFilter::Close && q.reach != ReachFilter::Distance)
    throw Error(ErrorCode::BadParameter, "reach must be any, close or distance");
  if (q.user_position) check_finite(*q.user_position, "user_position");
  if (q.near) check_finite(*q.near, "near");
  check_finite(q.face_direction, "face_direction");
  if (q.max_count == 0 || q.max_count > kMaxPlacements)
    throw Error(ErrorCode::BadParameter, "max_count must be between 1 and " + std::to_string(kMaxPlacements));
}

std::string metres(float v) { return fixed_or_g(v, 2) + " m"; }

}  // namespace

PlacementResult RoomQueries::find_placements(const PlacementQuery& query) const {
  check_query(query);
  PlacementResult result;
  const std::string kinds = detail::surface_names(query.surfaces);
  const auto fail = [&](PlacementShortfall why, std::string reason) {
    result.shortfall = why;
    result.reason = std::move(reason);
    return result;
  };
  if (!index_) return fail(PlacementShortfall::NoSurface, "no room was analysed");
  const Index& ix = *index_;
  const bool any_surface = ((query.surfaces & kOnFloor) && !ix.floor_cells.empty()) ||
                           ((query.surfaces & kOnCeiling) && !ix.ceiling_cells.empty()) ||
                           ((query.surfaces & kOnFurniture) && !ix.top_cells.empty()) ||
                           ((query.surfaces & kOnWall) && !ix.wall_cells.empty());
  if (!any_surface) return fail(PlacementShortfall::NoSurface, "the room has no free " + kinds);

  Search search(ix, query);
  const float up = search.need().up;
  std::vector<Found> found;
  bool fits_any = false;
  for (std::vector<Spot> spots = search.spots(up); !spots.empty();) {
    std::optional<Found> f = search.place(Search::best(spots), up);
    if (!f) continue;
    fits_any = true;
    f->placement.reach = search.reach_of(*f);
    if (query.reach != ReachFilter::Any && int(f->placement.reach) != int(query.reach)) continue;
    const auto collides = [&](const Found& other) {
      return detail::overlap(f->clear, other.object) || detail::overlap(other.clear, f->object);
    };
    if (!query.allow_overlap && std::any_of(found.begin(), found.end(), collides)) continue;
    found.push_back(std::move(*f));
    if (found.size() == query.max_count) break;
  }
  for (const Found& f : found) result.placements.push_back(f.placement);
  if (found.size() == query.max_count) return result;

  const std::string footprint = fixed_or_g(query.size.x, 2) + " x " + fixed_or_g(query.size.y, 2) + " m footprint";
  if (!found.empty())
    return fail(PlacementShortfall::TooFew, "found " + std::to_string(found.size()) + " of " +
                                                std::to_string(query.max_count) + " without overlapping");
  if (fits_any)
    return fail(PlacementShortfall::NoReach, "spots on free " + kinds + " hold the " + footprint + ", none within " +
                                                 (query.reach == ReachFilter::Close ? "close" : "distance") + " reach");
  // Would it fit with no clear space along the normal? Then the height was what failed.
  for (std::vector<Spot> spots = search.spots(0.0f); !spots.empty();)
    if (search.place(Search::best(spots), 0.0f))
      return fail(PlacementShortfall::NoHeadroom, "free " + kinds + " holds the " + footprint + ", but none has " +
                                                      metres(up) + " clear along its normal");
  std::string with;
  if (query.clearance > 0.0f) with += " with " + metres(query.clearance) + " clearance";
  if (query.edge_distance > 0.0f) with += std::string(with.empty() ? " with " : " and ") + metres(query.edge_distance) + " from the edge";
  return fail(PlacementShortfall::NoSpace, "no free " + kinds + " holds a " + footprint + with);
}

}  // namespace roomsense
