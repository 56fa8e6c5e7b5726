// Placement areas (§3.3-3.5) against the synthetic rooms' ground truth: every area on a real surface of its
// type, coverage of the free floor and walls, minor overlaps, classification rules, determinism.
#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "synthetic_fixture.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <functional>

namespace roomsense {
namespace {

using test::analysed;

// Points on a grid over the area, kept `inset` metres inside its edges (one voxel: the search works on voxels).
std::vector<glm::vec3> samples(const Area& a, float inset, int n = 7) {
  std::vector<glm::vec3> out;
  const float hw = std::max(0.0f, a.half_width - inset), hh = std::max(0.0f, a.half_height - inset);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const float u = -hw + 2.0f * hw * float(i) / float(n - 1), v = -hh + 2.0f * hh * float(j) / float(n - 1);
      out.push_back(a.center + u * a.x_axis() + v * a.y_axis());
    }
  return out;
}

// Is p on the area: within its rectangle and within `tolerance` of its plane?
bool on_area(const Area& a, const glm::vec3& p, float tolerance) {
  const glm::vec3 d = p - a.center;
  return std::abs(glm::dot(d, a.x_axis())) <= a.half_width && std::abs(glm::dot(d, a.y_axis())) <= a.half_height &&
         std::abs(glm::dot(d, a.normal)) <= tolerance;
}

using test::xz;

// The wall (outline edge) nearest to p, with p's position along it.
struct WallHit {
  int wall = 0;
  float u = 0;
  glm::vec2 inward{0.0f};
};
WallHit nearest_wall(const synth::RoomSpec& spec, glm::vec2 p) {
  WallHit best;
  float best_d = INFINITY;
  for (std::size_t i = 0; i < spec.outline.size(); ++i) {
    const glm::vec2 a = spec.outline[i], b = spec.outline[(i + 1) % spec.outline.size()];
    const glm::vec2 e = b - a;
    const float t = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0f, 1.0f);
    const float d = glm::distance(p, a + t * e);
    if (d < best_d) {
      best_d = d;
      // Counter-clockwise seen from +Y, i.e. seen from above with +Z down the page: inside is to the right.
      best = {int(i), t * glm::length(e), glm::normalize(glm::vec2(-e.y, e.x))};
      if (!synth::inside_outline(spec, a + t * e + 0.05f * best.inward)) best.inward = -best.inward;
    }
  }
  return best;
}

bool in_window(const synth::RoomSpec& spec, const WallHit& hit, float height, float margin) {
  return std::any_of(spec.windows.begin(), spec.windows.end(), [&](const synth::Window& w) {
    return w.wall == hit.wall && hit.u > w.u0 + margin && hit.u < w.u1 - margin && height > w.y0 + margin &&
           height < w.y1 - margin;
  });
}

bool on_free_floor(const synth::RoomSpec& spec, glm::vec2 p) {
  return synth::inside_outline(spec, p) && !synth::furniture_top_at(spec, p);
}

std::vector<const Area*> of_type(const AnalysisResult& r, AreaType type) {
  std::vector<const Area*> out;
  for (const Area& a : r.areas)
    if (a.type == type) out.push_back(&a);
  return out;
}

class RoomAreas : public testing::TestWithParam<synth::RoomSpec> {};

TEST_P(RoomAreas, EveryTypeIsFound) {
  const AnalysisResult& r = analysed(GetParam()).result;
  ASSERT_TRUE(r.ok());
  for (AreaType type : {AreaType::Wall, AreaType::Floor, AreaType::Ceiling})
    EXPECT_FALSE(of_type(r, type).empty()) << to_string(type);
  if (!GetParam().boxes.empty() || !GetParam().tables.empty()) {
    EXPECT_FALSE(of_type(r, AreaType::Furniture).empty());
  }
}

// Vertical surfaces the pipeline must treat as walls: the outline, and furniture taller than half the room
// (Eq. 3.11 makes such columns wall columns, like the default room's cabinet). Each with its free side.
struct Surface2D {
  glm::vec2 a, b, free_side;
};
std::vector<Surface2D> wall_surfaces(const synth::RoomSpec& spec) {
  std::vector<Surface2D> out;
  const auto add_loop = [&](const std::vector<glm::vec2>& loop, bool free_inside) {
    glm::vec2 centre(0.0f);
    for (const glm::vec2& p : loop) centre += p / float(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const glm::vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
      glm::vec2 n = glm::normalize(glm::vec2(-(b - a).y, (b - a).x));
      if ((glm::dot(centre - a, n) > 0.0f) != free_inside) n = -n;
      out.push_back({a, b, n});
    }
  };
  add_loop(spec.outline, true);
  for (const synth::Box& box : spec.boxes)
    if (box.height > 0.5f * (spec.ceiling_y - spec.floor_y)) {
      std::vector<glm::vec2> loop;
      for (glm::vec2 c : {glm::vec2(-0.5f, -0.5f), glm::vec2(-0.5f, 0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(0.5f, -0.5f)}) {
        const glm::vec2 v = c * box.size;
        const float cs = std::cos(box.yaw), sn = std::sin(box.yaw);  // as the generator turns footprints
        loop.push_back(box.centre + glm::vec2(cs * v.x - sn * v.y, sn * v.x + cs * v.y));
      }
      add_loop(loop, false);
    }
  return out;
}

const Surface2D& nearest_surface(const std::vector<Surface2D>& surfaces, glm::vec2 p, float* distance) {
  std::size_t best = 0;
  *distance = INFINITY;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const glm::vec2 e = surfaces[i].b - surfaces[i].a;
    const float t = std::clamp(glm::dot(p - surfaces[i].a, e) / glm::dot(e, e), 0.0f, 1.0f);
    const float d = glm::distance(p, surfaces[i].a + t * e);
    if (d < *distance) *distance = d, best = i;
  }
  return surfaces[best];
}

TEST_P(RoomAreas, WallAreasLieOnWallsFacingTheRoomAndMissWindows) {
  const synth::RoomSpec& spec = GetParam();
  const AnalysisResult& r = analysed(spec).result;
  const std::vector<Surface2D> surfaces = wall_surfaces(spec);
  int in_windows = 0, samples_total = 0;
  for (const Area* a : of_type(r, AreaType::Wall)) {
    SCOPED_TRACE(testing::Message() << "wall area at " << a->center.x << ", " << a->center.y << ", " << a->center.z);
    // On a wall surface, to within the voxel between the wall and the free space (plus the staircase of
    // voxels on walls off the axes), with the normal to its free side.
    float distance = 0;
    const Surface2D& wall = nearest_surface(surfaces, xz(a->center), &distance);
    EXPECT_LT(distance, 0.2f);
    EXPECT_GT(glm::dot(glm::normalize(xz(a->normal)), wall.free_side), 0.95f) << "normal not into the room";
    EXPECT_NEAR(a->normal.y, 0.0f, 1e-6f);
    EXPECT_GE(a->corners[0].y, spec.floor_y - 0.1f);
    EXPECT_LE(a->corners[2].y, spec.ceiling_y + 0.1f);
    for (const glm::vec3& p : samples(*a, 0.1f)) {
      ++samples_total;
      nearest_surface(surfaces, xz(p), &distance);
      EXPECT_LT(distance, 0.25f);
      in_windows += in_window(spec, nearest_wall(spec, xz(p)), p.y - spec.floor_y, 0.1f) ? 1 : 0;
    }
  }
  // Eq. 3.25 lets 20 % of a wall rectangle lack wall voxels: none of that may fall in a window opening
  // farther than a voxel from its frame.
  EXPECT_EQ(in_windows, 0) << "of " << samples_total << " samples";
}

TEST_P(RoomAreas, FloorAreasLieOnFreeFloor) {
  const synth::RoomSpec& spec = GetParam();
  const AnalysisResult& r = analysed(spec).result;
  int good = 0, total = 0;
  for (const Area* a : of_type(r, AreaType::Floor)) {
    EXPECT_NEAR(a->center.y, spec.floor_y, 0.03f);
    EXPECT_EQ(a->normal, glm::vec3(0, 1, 0));
    int area_good = 0;
    const auto pts = samples(*a, 0.1f);
    for (const glm::vec3& p : pts) area_good += on_free_floor(spec, xz(p)) ? 1 : 0;
    // Eq. 3.38 lets 5 % of a square be no free tile, such as a furniture edge.
    EXPECT_GE(double(area_good) / double(pts.size()), 0.9) << "floor area at " << a->center.x << ", " << a->center.z;
    good += area_good;
    total += int(pts.size());
  }
  if (total > 0) {
    EXPECT_GE(double(good) / total, 0.98);
  }
}

TEST_P(RoomAreas, FurnitureAreasLieOnFurnitureTops) {
  const synth::RoomSpec& spec = GetParam();
  const AnalysisResult& r = analysed(spec).result;
  for (const Area* a : of_type(r, AreaType::Furniture)) {
    int good = 0;
    const auto pts = samples(*a, 0.1f);
    for (const glm::vec3& p : pts) {
      const std::optional<float> top = synth::furniture_top_at(spec, xz(p));
      // The area sits on top of the highest voxel of the top: at most one voxel above it.
      good += top && p.y - (spec.floor_y + *top) > -0.02f && p.y - (spec.floor_y + *top) < 0.12f ? 1 : 0;
    }
    EXPECT_GE(double(good) / double(pts.size()), 0.9) << "furniture area at " << a->center.x << ", " << a->center.y
                                                      << ", " << a->center.z;
  }
}

TEST_P(RoomAreas, CeilingAreasLieOnTheCeiling) {
  const synth::RoomSpec& spec = GetParam();
  for (const Area* a : of_type(analysed(spec).result, AreaType::Ceiling)) {
    EXPECT_NEAR(a->center.y, spec.ceiling_y, 0.03f);
    EXPECT_EQ(a->normal, glm::vec3(0, -1, 0));
    for (const glm::vec3& p : samples(*a, 0.1f)) EXPECT_TRUE(synth::inside_outline(spec, xz(p)));
  }
}

// Coverage and overlap on a 5 cm raster: how much of the true free floor / free wall the areas cover, and how
// much of what they cover is covered twice.
struct Coverage {
  double covered = 0, overlap = 0;
};

Coverage floor_coverage(const synth::RoomSpec& spec, const std::vector<const Area*>& areas) {
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec2& p : spec.outline) lo = glm::min(lo, p), hi = glm::max(hi, p);
  int truth = 0, hit = 0, once = 0, twice = 0;
  for (float x = lo.x; x <= hi.x; x += 0.05f)
    for (float z = lo.y; z <= hi.y; z += 0.05f) {
      const glm::vec2 p(x, z);
      // Free floor the search can use: a voxel away from walls and furniture.
      const bool free = on_free_floor(spec, p) && synth::distance_to_walls(spec, p) > 0.1f &&
                        synth::distance_to_furniture(spec, p) > 0.1f;
      int n = 0;
      for (const Area* a : areas) n += on_area(*a, glm::vec3(x, spec.floor_y, z), 0.05f) ? 1 : 0;
      truth += free ? 1 : 0;
      hit += free && n > 0 ? 1 : 0;
      once += n >= 1 ? 1 : 0;
      twice += n >= 2 ? 1 : 0;
    }
  return {truth ? double(hit) / truth : 0.0, once ? double(twice) / once : 0.0};
}

Coverage wall_coverage(const synth::RoomSpec& spec, const std::vector<const Area*>& areas) {
  int truth = 0, hit = 0, once = 0, twice = 0;
  for (std::size_t i = 0; i < spec.outline.size(); ++i) {
    const glm::vec2 a = spec.outline[i], b = spec.outline[(i + 1) % spec.outline.size()];
    const float length = glm::distance(a, b);
    for (float u = 0.15f; u < length - 0.15f; u += 0.05f)
      for (float y = spec.floor_y + 0.15f; y < spec.ceiling_y - 0.15f; y += 0.05f) {
        const glm::vec2 p = a + (b - a) * (u / length);
        const WallHit hit_wall = nearest_wall(spec, p);
        // Free wall: no window, and 1 m clear in front of it (Alg. 1's reach) above any furniture there.
        bool free = !in_window(spec, {int(i), u, hit_wall.inward}, y - spec.floor_y, -0.1f);
        for (float s = 0.1f; s <= 1.0f && free; s += 0.1f) {
          const std::optional<float> top = synth::furniture_top_at(spec, p + s * hit_wall.inward);
          free = !top || spec.floor_y + *top < y - 0.15f;
        }
        int n = 0;
        for (const Area* area : areas) n += on_area(*area, glm::vec3(p.x, y, p.y), 0.2f) ? 1 : 0;
        truth += free ? 1 : 0;
        hit += free && n > 0 ? 1 : 0;
        once += n >= 1 ? 1 : 0;
        twice += n >= 2 ? 1 : 0;
      }
  }
  return {truth ? double(hit) / truth : 0.0, once ? double(twice) / once : 0.0};
}

TEST_P(RoomAreas, AreasCoverMostFreeFloorAndWallWithMinorOverlaps) {
  const synth::RoomSpec& spec = GetParam();
  const AnalysisResult& r = analysed(spec).result;
  const Coverage floor = floor_coverage(spec, of_type(r, AreaType::Floor));
  const Coverage wall = wall_coverage(spec, of_type(r, AreaType::Wall));
  std::printf("[ coverage ] %-16s floor %5.1f %% (overlap %4.1f %%), wall %5.1f %% (overlap %4.1f %%)\n",
              spec.name.c_str(), 100 * floor.covered, 100 * floor.overlap, 100 * wall.covered, 100 * wall.overlap);
  RecordProperty("floor_coverage_percent", int(std::lround(100 * floor.covered)));
  RecordProperty("wall_coverage_percent", int(std::lround(100 * wall.covered)));
  EXPECT_GE(floor.covered, 0.5);
  EXPECT_GE(wall.covered, 0.5);
  EXPECT_LE(floor.overlap, 0.15);
  EXPECT_LE(wall.overlap, 0.15);
}

// Does the area hold a rectangle of the size class: its width less the search's 0.1 m tolerance (and height,
// for walls)?
bool holds_class(const Area& a, AreaSize size) {
  const std::size_t s = std::size_t(size) - 1;
  const AreaParams p;
  const float w = 2 * a.half_width, h = 2 * a.half_height, tolerance = p.width_tolerance + 1e-4f;
  if (a.type == AreaType::Wall) return w >= p.wall_width[s] - tolerance && h >= p.wall_height[s] - tolerance;
  return std::min(w, h) >= p.square_width[s] - tolerance;
}

TEST_P(RoomAreas, ClassificationFollowsTheThesisRules) {
  const synth::RoomSpec& spec = GetParam();
  const AnalysisResult& r = analysed(spec).result;
  for (const Area& a : r.areas) {
    SCOPED_TRACE(testing::Message() << to_string(a.type) << " " << to_string(a.size) << " at " << a.center.x << ", "
                                    << a.center.y << ", " << a.center.z);
    // Eq. 3.58: exactly one bit per group, matching the fields.
    EXPECT_EQ(a.flags, category_flags(a.type, a.size, a.reach));
    for (std::uint32_t group : {0x7u, 0x38u, 0x3C0u}) EXPECT_EQ(std::popcount(a.flags & group), 1);
    // A counter-clockwise rectangle seen from the front, with a unit normal = X × Y.
    EXPECT_NEAR(glm::length(a.normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(a.x_axis(), a.y_axis()), 0.0f, 1e-4f);
    EXPECT_GT(glm::dot(glm::cross(a.x_axis(), a.y_axis()), a.normal), 0.999f);
    EXPECT_NEAR(glm::distance(a.center, 0.25f * (a.corners[0] + a.corners[1] + a.corners[2] + a.corners[3])), 0.0f, 1e-4f);
    const glm::quat q = a.orientation();
    EXPECT_NEAR(glm::distance(q * glm::vec3(0, 0, 1), a.normal), 0.0f, 1e-4f);
    // Sizes: grown areas hold their class (its width - 0.1 m, and height for walls), and not the next larger.
    EXPECT_TRUE(holds_class(a, a.size));
    if (a.size != AreaSize::Large) {
      EXPECT_FALSE(holds_class(a, AreaSize(int(a.size) - 1)));
    }
    if (a.type == AreaType::Wall) {
      EXPECT_EQ(a.rotation_deg, 0.0f);
      EXPECT_EQ(a.x_axis().y, 0.0f);  // +Y is up on walls
      EXPECT_NEAR(a.y_axis().y, 1.0f, 1e-6f);
    } else {
      EXPECT_GE(a.rotation_deg, 0.0f);
      EXPECT_LT(a.rotation_deg, 90.0f);
    }
    // §3.5: floors are always within reach; ceilings never within a hand's reach; walls high up neither.
    if (a.type == AreaType::Floor) {
      EXPECT_EQ(a.reach, Reach::Close);
    }
    if (a.type == AreaType::Ceiling || (a.type == AreaType::Wall && a.center.y - r.floor_y > 1.5f)) {
      EXPECT_NE(a.reach, Reach::Close);
    }
    // A single convex room: every area can be seen from the floor.
    EXPECT_NE(a.reach, Reach::None);
  }
}

TEST_P(RoomAreas, IdenticalForAnyThreadCountAndRun) {
  const test::AnalysedRoom& room = analysed(GetParam());
  for (unsigned threads : {1u, 3u}) {
    AnalysisOptions o;
    o.threads = threads;
    o.build_bounds = false;
    const AnalysisResult again = analyze(room.scan, o);
    ASSERT_EQ(again.areas.size(), room.result.areas.size()) << threads << " threads";
    for (std::size_t i = 0; i < again.areas.size(); ++i) {
      const Area &x = again.areas[i], &y = room.result.areas[i];
      EXPECT_EQ(x.flags, y.flags);
      EXPECT_EQ(x.corners, y.corners);
      EXPECT_EQ(x.rotation_deg, y.rotation_deg);
    }
  }
}

// AreaParams::grow = false gives the thesis's fixed sizes; growth keeps the same areas, each holding its exact
// rectangle, and only adds surface.
TEST_P(RoomAreas, GrowthOnlyStretchesTheThesissExactSizes) {
  const test::AnalysedRoom& room = analysed(GetParam());
  AnalysisOptions o;
  o.areas.grow = false;
  o.build_bounds = false;
  const AnalysisResult exact = analyze(room.scan, o);
  ASSERT_EQ(exact.areas.size(), room.result.areas.size());
  int grown = 0;
  for (std::size_t i = 0; i < exact.areas.size(); ++i) {
    const Area &e = exact.areas[i], &g = room.result.areas[i];
    SCOPED_TRACE(testing::Message() << to_string(e.type) << " " << to_string(e.size) << " at " << e.center.x << ", "
                                    << e.center.y << ", " << e.center.z);
    const std::size_t s = std::size_t(e.size) - 1;
    const AreaParams p;
    EXPECT_NEAR(2 * e.half_width, e.type == AreaType::Wall ? p.wall_width[s] : p.square_width[s], 0.11f);
    if (e.type == AreaType::Wall) {
      EXPECT_NEAR(2 * e.half_height, p.wall_height[s], 0.11f);
    } else {
      EXPECT_NEAR(e.half_height, e.half_width, 1e-4f);
    }
    ASSERT_EQ(g.type, e.type);
    EXPECT_LE(int(g.size), int(e.size));  // the same class or a larger one
    EXPECT_EQ(g.normal, e.normal);
    EXPECT_NEAR(g.rotation_deg, e.rotation_deg, 1e-3f);
    for (const glm::vec3& c : e.corners) EXPECT_TRUE(on_area(g, c + 1e-3f * glm::normalize(e.center - c), 1e-3f));
    grown += g.half_width * g.half_height > e.half_width * e.half_height + 1e-4f ? 1 : 0;
  }
  EXPECT_GT(grown, 0);
  const synth::RoomSpec& spec = GetParam();
  EXPECT_GE(floor_coverage(spec, of_type(room.result, AreaType::Floor)).covered,
            floor_coverage(spec, of_type(exact, AreaType::Floor)).covered);
  EXPECT_GE(wall_coverage(spec, of_type(room.result, AreaType::Wall)).covered,
            wall_coverage(spec, of_type(exact, AreaType::Wall)).covered);
}

INSTANTIATE_TEST_SUITE_P(Synthetic, RoomAreas,
                         testing::Values(synth::default_room(), synth::rotated_room(30.0f), synth::pentagon_room(),
                                         synth::large_triangle_room(), synth::thesis_room1()),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

TEST(Areas, CloseReachNeedsAFloorAreaNearby) {
  // In the default room the sofa's seat touches free floor: close; the cabinet top stands against a wall
  // but has floor in front of it too. A wall area low on a wall with free floor before it is close.
  const AnalysisResult& r = analysed(synth::default_room()).result;
  int close_walls = 0;
  for (const Area& a : r.areas)
    if (a.type == AreaType::Wall && a.reach == Reach::Close) ++close_walls;
  EXPECT_GT(close_walls, 0);
}

TEST(Areas, ANegativeOrNaNCloseDistanceIsAClearError) {
  // An engine's AreaParams are checked (check_params): a close distance of -inf, -1e30 or NaN is refused by name,
  // not searched with.
  const Scan scan = synth::generate(synth::default_room());
  AnalysisOptions options;
  options.build_bounds = false;
  for (const float close : {-INFINITY, -1e30f, NAN}) {
    options.areas.close_distance = close;
    try {
      (void)analyze(scan, options);
      ADD_FAILURE() << "close distance " << close << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::BadParameter);
      EXPECT_NE(std::string(e.what()).find("close_distance"), std::string::npos) << e.what();
    }
  }
}

TEST(Areas, SearchingNothingFindsNothing) {
  // A room without free floor tiles (everything below 1.5 m occupied) has no floor areas and does not fail.
  synth::RoomSpec spec = synth::default_room();
  spec.name = "crammed";
  spec.boxes = {{{0.0f, 0.0f}, {5.0f, 4.0f}, 1.0f, 0.0f}};
  spec.tables.clear();
  const AnalysisResult r = analyze(synth::generate(spec));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(of_type(r, AreaType::Floor).empty());
  for (const Area* a : of_type(r, AreaType::Furniture)) EXPECT_NEAR(a->center.y, spec.floor_y + 1.0f, 0.11f);
}

}  // namespace
}  // namespace roomsense
