// Placement queries (queries.h) against the synthetic rooms' ground truth: placements on free floor, furniture
// tops, walls and ceilings lie where the room has such free surface (checked independently of the voxels, from the
// room's outline, furniture and windows), with their clearance, never overlapping; rays hit the room's walls, floor,
// ceiling and furniture where they are; random points lie where asked; impossible queries say why.
#include "roomsense/queries.h"

#include "roomsense/error.h"
#include "roomsense/synthetic.h"
#include "synthetic_fixture.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace roomsense {
namespace {

constexpr float kVoxel = 0.1f;

const RoomQueries& queries_of(const synth::RoomSpec& spec) {
  static std::map<std::string, RoomQueries> cache;
  auto it = cache.find(spec.name);
  if (it == cache.end()) it = cache.emplace(spec.name, RoomQueries(test::analysed(spec).result)).first;
  return it->second;
}

// Points across a placement's footprint grown by `grow` (on its surface): a 7 x 7 lattice including the edges.
std::vector<glm::vec3> footprint_samples(const Placement& p, float grow) {
  std::vector<glm::vec3> out;
  const glm::vec3 x = p.x_axis * (0.5f * p.footprint.x + grow), y = p.y_axis() * (0.5f * p.footprint.y + grow);
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j) out.push_back(p.center + x * (float(i) / 3.0f - 1.0f) + y * (float(j) / 3.0f - 1.0f));
  return out;
}

using test::xz;

// Two footprints (same surface plane) overlap: separating-axis test on their rectangles, independent of core's.
bool footprints_overlap(const Placement& a, const Placement& b) {
  const auto corners = [](const Placement& p) { return p.corners(); };
  const auto ca = corners(a), cb = corners(b);
  for (const Placement* p : {&a, &b})
    for (const glm::vec3& axis : {p->x_axis, p->y_axis()}) {
      float amin = 1e9f, amax = -1e9f, bmin = 1e9f, bmax = -1e9f;
      for (const glm::vec3& c : ca) amin = std::min(amin, glm::dot(c, axis)), amax = std::max(amax, glm::dot(c, axis));
      for (const glm::vec3& c : cb) bmin = std::min(bmin, glm::dot(c, axis)), bmax = std::max(bmax, glm::dot(c, axis));
      if (amax <= bmin + 1e-4f || bmax <= amin + 1e-4f) return false;
    }
  return true;
}

void expect_frame(const Placement& p) {
  EXPECT_NEAR(glm::length(p.x_axis), 1.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(p.x_axis, p.normal), 0.0f, 1e-4f);
  const glm::quat q = p.orientation();
  EXPECT_LT(glm::distance(q * glm::vec3(0, 0, 1), p.normal), 1e-4f);
  EXPECT_LT(glm::distance(q * glm::vec3(1, 0, 0), p.x_axis), 1e-4f);
}

TEST(Placements, FloorFootprintsLieOnFreeFloorWithTheirClearance) {
  for (const synth::RoomSpec& spec : {synth::default_room(), synth::rotated_room(30.0f), synth::pentagon_room()}) {
    SCOPED_TRACE(spec.name);
    PlacementQuery q;
    q.size = {0.6f, 0.4f, 1.0f};
    q.surfaces = kOnFloor;
    q.clearance = 0.2f;
    q.max_count = 8;
    const PlacementResult r = queries_of(spec).find_placements(q);
    ASSERT_EQ(r.placements.size(), 8u) << r.reason;
    EXPECT_EQ(r.shortfall, PlacementShortfall::None);
    for (const Placement& p : r.placements) {
      expect_frame(p);
      EXPECT_EQ(p.surface, AreaType::Floor);
      EXPECT_NEAR(p.center.y, spec.floor_y, 0.03f);
      EXPECT_GT(p.normal.y, 0.999f);
      EXPECT_EQ(p.reach, Reach::Close);  // a person stands right there
      // Ground truth: the footprint and its clearance inside the walls and clear of every piece of furniture,
      // within one voxel (the features' resolution).
      for (const glm::vec3& s : footprint_samples(p, q.clearance)) {
        EXPECT_TRUE(synth::inside_outline(spec, xz(s)));
        EXPECT_GT(synth::distance_to_walls(spec, xz(s)), -kVoxel);
        EXPECT_GT(synth::distance_to_furniture(spec, xz(s)), 0.0f) << s.x << " " << s.z;
      }
      for (const glm::vec3& s : footprint_samples(p, 0.0f))
        EXPECT_GT(synth::distance_to_walls(spec, xz(s)), q.clearance - kVoxel);
    }
    for (std::size_t i = 0; i < r.placements.size(); ++i)
      for (std::size_t j = i + 1; j < r.placements.size(); ++j)
        EXPECT_FALSE(footprints_overlap(r.placements[i], r.placements[j])) << i << " " << j;
  }
}

TEST(Placements, FurnitureTopsHoldObjectsOnTheirTops) {
  const synth::RoomSpec spec = synth::default_room();
  PlacementQuery q;
  q.size = {0.3f, 0.3f, 0.3f};
  q.surfaces = kOnFurniture;
  q.max_count = 3;
  const PlacementResult r = queries_of(spec).find_placements(q);
  ASSERT_EQ(r.placements.size(), 3u) << r.reason;
  for (const Placement& p : r.placements) {
    expect_frame(p);
    EXPECT_EQ(p.surface, AreaType::Furniture);
    const std::optional<float> top = synth::furniture_top_at(spec, xz(p.center));
    ASSERT_TRUE(top.has_value()) << p.center.x << " " << p.center.z;
    EXPECT_NEAR(p.center.y, spec.floor_y + *top, kVoxel + 0.01f);
    for (const glm::vec3& s : footprint_samples(p, 0.0f)) {
      const std::optional<float> under = synth::furniture_top_at(spec, xz(s));
      ASSERT_TRUE(under.has_value()) << s.x << " " << s.z;
      EXPECT_NEAR(*under, *top, 1e-4f);
    }
  }
}

// The window of default_room (and the rooms made from it): wall 1 (the +Z wall, from outline[1] to outline[2]), u along it from its start.
bool crosses_window(const synth::RoomSpec& spec, const Placement& p) {
  for (const synth::Window& w : spec.windows) {
    const glm::vec2 a = spec.outline[std::size_t(w.wall)], b = spec.outline[(std::size_t(w.wall) + 1) % spec.outline.size()];
    const glm::vec2 along = glm::normalize(b - a);
    float umin = 1e9f, umax = -1e9f, ymin = 1e9f, ymax = -1e9f;
    for (const glm::vec3& c : p.corners()) {
      if (std::abs(glm::dot(xz(c) - a, glm::vec2(-along.y, along.x))) > 0.3f) return false;  // another wall
      umin = std::min(umin, glm::dot(xz(c) - a, along));
      umax = std::max(umax, glm::dot(xz(c) - a, along));
      ymin = std::min(ymin, c.y - spec.floor_y);
      ymax = std::max(ymax, c.y - spec.floor_y);
    }
    // Within a voxel of the opening's edge is the features' resolution.
    if (umax > w.u0 + kVoxel && umin < w.u1 - kVoxel && ymax > w.y0 + kVoxel && ymin < w.y1 - kVoxel) return true;
  }
  return false;
}

TEST(Placements, WallFootprintsLieOnWallsAndFaceTheRoom) {
  for (const synth::RoomSpec& spec : {synth::default_room(), synth::rotated_room(30.0f), synth::pentagon_room()}) {
    SCOPED_TRACE(spec.name);
    PlacementQuery q;
    q.size = {0.6f, 0.4f, 0.05f};
    q.surfaces = kOnWall;
    q.max_count = 10;
    const PlacementResult r = queries_of(spec).find_placements(q);
    ASSERT_EQ(r.placements.size(), 10u) << r.reason;
    for (const Placement& p : r.placements) {
      expect_frame(p);
      EXPECT_EQ(p.surface, AreaType::Wall);
      EXPECT_NEAR(p.normal.y, 0.0f, 1e-5f);
      EXPECT_GT(p.y_axis().y, 0.999f);  // walls: +Y up
      for (const glm::vec3& c : p.corners()) {
        EXPECT_LT(std::abs(synth::distance_to_walls(spec, xz(c))), 0.15f);  // on a wall
        EXPECT_GT(c.y, spec.floor_y);
        EXPECT_LT(c.y, spec.ceiling_y);
      }
      // Into the room: a step along the normal moves away from the wall.
      EXPECT_GT(synth::distance_to_walls(spec, xz(p.center + p.normal * 0.3f)), 0.2f);
      EXPECT_FALSE(crosses_window(spec, p)) << p.center.x << " " << p.center.y << " " << p.center.z;
    }
  }
}

// A wall off the grid's axes is a voxel staircase, often two voxels thick: its faces must still be whole, so that a
// board wider than a staircase step fits (before the fix, at 30° no 0.8 m footprint found a place).
TEST(Placements, WallsOffTheGridAxesHoldWideBoards) {
  for (const synth::RoomSpec& spec : {synth::rotated_room(30.0f), synth::rotated_room(17.0f), synth::pentagon_room()}) {
    SCOPED_TRACE(spec.name);
    PlacementQuery q;
    q.size = {1.2f, 0.8f, 0.05f};
    q.clearance = 0.1f;
    q.surfaces = kOnWall;
    q.max_count = 4;
    const PlacementResult r = queries_of(spec).find_placements(q);
    ASSERT_EQ(r.placements.size(), 4u) << r.reason;
    for (const Placement& p : r.placements) {
      for (const glm::vec3& c : p.corners()) EXPECT_LT(std::abs(synth::distance_to_walls(spec, xz(c))), 0.15f);
      EXPECT_FALSE(crosses_window(spec, p)) << p.center.x << " " << p.center.y << " " << p.center.z;
    }
  }
}

// A wall placement's depth is clear space before the wall, up to what stands in it: the default room's table top
// (0.75 m high) lies 1.2 m before its +X wall. An object 1 m deep stands on that wall at the table's height; one
// 1.5 m deep would run into the top there, and goes higher. The table comes from the room's ground truth.
TEST(Placements, WallDepthStopsAtWhatStandsBeforeTheWall) {
  const synth::RoomSpec spec = synth::default_room();
  ASSERT_FALSE(spec.tables.empty());
  const synth::Table& table = spec.tables.front();
  const float wall_x = 2.5f, top = spec.floor_y + table.height;
  const float gap = wall_x - (table.centre.x + 0.5f * table.size.x);
  ASSERT_NEAR(gap, 1.2f, 1e-4f);
  const glm::vec3 before_the_table(wall_x, top, table.centre.y);
  for (const float depth : {1.0f, 1.5f}) {
    SCOPED_TRACE(depth);
    PlacementQuery q;
    q.size = {0.3f, 0.3f, depth};
    q.surfaces = kOnWall;
    q.near = before_the_table;
    const PlacementResult r = queries_of(spec).find_placements(q);
    ASSERT_EQ(r.placements.size(), 1u) << r.reason;
    const Placement& p = r.placements.front();
    const float y0 = p.center.y - 0.5f * p.footprint.y, y1 = p.center.y + 0.5f * p.footprint.y;
    const float z0 = p.center.z - 0.5f * p.footprint.x, z1 = p.center.z + 0.5f * p.footprint.x;
    const bool before_the_top = z1 > table.centre.y - 0.5f * table.size.y + 1.5f * kVoxel &&
                                z0 < table.centre.y + 0.5f * table.size.y - 1.5f * kVoxel;
    const bool across_the_top = y0 < top - kVoxel && y1 > top + kVoxel;
    if (depth < gap) {
      EXPECT_LT(glm::distance(p.center, before_the_table), 0.2f) << p.center.x << " " << p.center.y << " " << p.center.z;
    } else {
      EXPECT_FALSE(before_the_top && (across_the_top || std::abs(p.center.y - top) < kVoxel))
          << p.center.x << " " << p.center.y << " " << p.center.z;
    }
  }
}

TEST(Placements, CeilingFootprintsHangFromTheCeiling) {
  const synth::RoomSpec spec = synth::default_room();
  PlacementQuery q;
  q.size = {0.5f, 0.5f, 0.3f};
  q.surfaces = kOnCeiling;
  q.max_count = 4;
  const PlacementResult r = queries_of(spec).find_placements(q);
  ASSERT_EQ(r.placements.size(), 4u) << r.reason;
  for (const Placement& p : r.placements) {
    expect_frame(p);
    EXPECT_NEAR(p.center.y, spec.ceiling_y, 0.03f);
    EXPECT_LT(p.normal.y, -0.999f);
    EXPECT_EQ(p.reach, Reach::Distance);
    for (const glm::vec3& s : footprint_samples(p, 0.0f)) EXPECT_TRUE(synth::inside_outline(spec, xz(s)));
  }
}

TEST(Placements, NearPointFaceDirectionAndSeed) {
  const synth::RoomSpec spec = synth::default_room();
  const RoomQueries& rq = queries_of(spec);
  PlacementQuery q;
  q.size = {0.5f, 0.3f, 0.5f};
  q.surfaces = kOnFloor;
  q.max_count = 3;
  q.near = glm::vec3(1.5f, 0.0f, 1.5f);
  const PlacementResult near = rq.find_placements(q);
  ASSERT_EQ(near.placements.size(), 3u);
  for (std::size_t i = 1; i < near.placements.size(); ++i)
    EXPECT_LE(glm::distance(near.placements[i - 1].center, *q.near),
              glm::distance(near.placements[i].center, *q.near) + 0.06f);
  EXPECT_LT(glm::distance(xz(near.placements[0].center), xz(*q.near)), 0.5f);

  q.near.reset();
  q.face_direction = glm::vec3(1.0f, 0.3f, 1.0f);
  const PlacementResult faced = rq.find_placements(q);
  ASSERT_FALSE(faced.placements.empty());
  for (const Placement& p : faced.placements)
    EXPECT_GT(glm::dot(p.y_axis(), glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f))), 0.999f);

  q.face_direction = glm::vec3(0.0f);
  const PlacementResult a = rq.find_placements(q), b = rq.find_placements(q);
  ASSERT_EQ(a.placements.size(), b.placements.size());
  for (std::size_t i = 0; i < a.placements.size(); ++i) EXPECT_EQ(a.placements[i].center, b.placements[i].center);
  // Without a facing direction, footprints follow the walls where they fit.
  for (const Placement& p : a.placements) EXPECT_GT(std::abs(p.x_axis.x), 0.999f);
  bool differs = false;
  for (std::uint64_t seed = 1; seed < 8 && !differs; ++seed) {
    q.seed = seed;
    differs = rq.find_placements(q).placements[0].center != a.placements[0].center;
  }
  EXPECT_TRUE(differs) << "the seed should vary the order of equally good spots";
}

TEST(Placements, ReachFromAUserPosition) {
  const synth::RoomSpec spec = synth::default_room();
  PlacementQuery q;
  q.size = {0.4f, 0.3f, 0.05f};
  q.surfaces = kOnWall;
  q.reach = ReachFilter::Close;
  q.user_position = glm::vec3(2.0f, 1.6f, 0.0f);  // a metre from the +X wall
  q.max_count = 3;
  const PlacementResult r = queries_of(spec).find_placements(q);
  ASSERT_FALSE(r.placements.empty()) << r.reason;
  for (const Placement& p : r.placements) {
    EXPECT_EQ(p.reach, Reach::Close);
    EXPECT_LT(glm::distance(xz(p.center), xz(*q.user_position)), q.user_reach + 0.5f * q.size.x + 1e-3f);
    EXPECT_LE(p.center.y - spec.floor_y, 1.5f + 1e-4f);
  }
  q.user_reach = 0.01f;
  q.user_position = glm::vec3(0.0f, 1.6f, 0.0f);  // the room's middle: no wall within reach
  const PlacementResult none = queries_of(spec).find_placements(q);
  EXPECT_TRUE(none.placements.empty());
  EXPECT_EQ(none.shortfall, PlacementShortfall::NoReach) << none.reason;
}

TEST(Placements, ImpossibleQueriesSayWhy) {
  const RoomQueries& rq = queries_of(synth::default_room());
  PlacementQuery q;
  q.surfaces = kOnFloor;
  q.size = {6.0f, 6.0f, 0.5f};
  PlacementResult r = rq.find_placements(q);
  EXPECT_TRUE(r.placements.empty());
  EXPECT_EQ(r.shortfall, PlacementShortfall::NoSpace);
  EXPECT_NE(r.reason.find("6.00 x 6.00 m"), std::string::npos) << r.reason;

  q.size = {0.3f, 0.3f, 0.3f};
  q.clearance_above = 5.0f;  // the room is 2.6 m high
  r = rq.find_placements(q);
  EXPECT_EQ(r.shortfall, PlacementShortfall::NoHeadroom) << r.reason;

  q.clearance_above = 0.0f;
  q.surfaces = kOnFurniture;
  q.max_count = 500;
  r = rq.find_placements(q);
  EXPECT_FALSE(r.placements.empty());
  EXPECT_LT(r.placements.size(), 500u);
  EXPECT_EQ(r.shortfall, PlacementShortfall::TooFew) << r.reason;

  EXPECT_EQ(RoomQueries().find_placements(q).shortfall, PlacementShortfall::NoSurface);
  AnalysisResult failed;
  failed.status = AnalysisStatus::NoFloorCeiling;
  EXPECT_TRUE(RoomQueries(failed).empty());
}

TEST(Placements, BadQueriesThrow) {
  const RoomQueries& rq = queries_of(synth::default_room());
  const auto throws = [&](auto change) {
    PlacementQuery q;
    change(q);
    try {
      rq.find_placements(q);
    } catch (const Error& e) {
      return e.code() == ErrorCode::BadParameter;
    }
    return false;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.size.x = nan; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.size.z = 0.0f; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.size.y = 1e6f; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.clearance = -0.1f; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.edge_distance = inf; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.max_count = 0; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.max_count = kMaxPlacements + 1; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.surfaces = 0; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.surfaces = 0x100; }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.reach = ReachFilter(7); }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.near = glm::vec3(nan); }));
  EXPECT_TRUE(throws([&](PlacementQuery& q) { q.face_direction = glm::vec3(inf, 0, 0); }));
  EXPECT_FALSE(throws([](PlacementQuery&) {}));
}

TEST(Raycast, HitsWallsFloorCeilingAndFurnitureWhereTheyAre) {
  const synth::RoomSpec spec = synth::default_room();  // 5 x 4 m about the origin, 2.6 m high
  const RoomQueries& rq = queries_of(spec);
  const glm::vec3 centre(0.0f, 1.2f, 0.3f);
  const std::optional<RayHit> east = rq.raycast(centre, {1, 0, 0});
  ASSERT_TRUE(east);
  EXPECT_EQ(east->surface, AreaType::Wall);
  EXPECT_TRUE(east->scanned);
  EXPECT_NEAR(east->position.x, 2.5f, 0.12f);
  EXPECT_NEAR(east->distance, east->position.x - centre.x, 1e-4f);
  EXPECT_EQ(east->normal, glm::vec3(-1, 0, 0));

  const std::optional<RayHit> down = rq.raycast(glm::vec3(-1.0f, 1.2f, 0.8f), {0, -1, 0});
  ASSERT_TRUE(down);
  EXPECT_EQ(down->surface, AreaType::Floor);
  EXPECT_NEAR(down->position.y, spec.floor_y, 0.03f);
  EXPECT_EQ(down->normal, glm::vec3(0, 1, 0));

  const std::optional<RayHit> up = rq.raycast(centre, {0, 1, 0});
  ASSERT_TRUE(up);
  EXPECT_EQ(up->surface, AreaType::Ceiling);
  EXPECT_NEAR(up->position.y, spec.ceiling_y, 0.03f);

  const std::optional<RayHit> table = rq.raycast(glm::vec3(0.6f, 2.0f, 0.4f), {0, -1, 0});  // the table's centre
  ASSERT_TRUE(table);
  EXPECT_EQ(table->surface, AreaType::Furniture);
  EXPECT_NEAR(table->position.y, spec.floor_y + 0.75f, 0.12f);

  // Through the scan's hole in the -X wall (centre (-2.5, 1.6, 1.0), radius 0.25 m): the room's edge.
  const std::optional<RayHit> hole = rq.raycast(glm::vec3(0.0f, 1.6f, 1.0f), {-1, 0, 0});
  ASSERT_TRUE(hole);
  EXPECT_EQ(hole->surface, AreaType::Wall);
  EXPECT_NEAR(hole->position.x, -2.5f, 0.15f);

  // Diagonal, and from outside the grid towards the room: the outside of a wall.
  const std::optional<RayHit> slanted = rq.raycast(centre, {1, 0.2f, 1});
  ASSERT_TRUE(slanted);
  EXPECT_TRUE(std::abs(slanted->position.x - 2.5f) < 0.15f || std::abs(slanted->position.z - 2.0f) < 0.15f);
  const std::optional<RayHit> outside = rq.raycast(glm::vec3(10.0f, 1.2f, 0.0f), {-1, 0, 0});
  ASSERT_TRUE(outside);
  EXPECT_NEAR(outside->position.x, 2.5f, 0.15f);
  EXPECT_EQ(outside->normal, glm::vec3(1, 0, 0));

  EXPECT_FALSE(rq.raycast(centre, {1, 0, 0}, 1.0f));        // the wall is 2.5 m away
  EXPECT_FALSE(rq.raycast(glm::vec3(0, 50, 0), {0, 1, 0}));  // away from the grid
  EXPECT_THROW(rq.raycast(centre, {0, 0, 0}), Error);
  EXPECT_THROW(rq.raycast(glm::vec3(std::nanf("")), {1, 0, 0}), Error);
  EXPECT_FALSE(RoomQueries().raycast(centre, {1, 0, 0}));
}

TEST(Locate, InsideOutsideAndInFurniture) {
  const synth::RoomSpec spec = synth::default_room();
  const RoomQueries& rq = queries_of(spec);
  EXPECT_TRUE(rq.is_inside_room({0.0f, 1.0f, 0.0f}));
  EXPECT_TRUE(rq.locate({0.0f, 1.0f, 0.0f}).free);
  EXPECT_FALSE(rq.is_inside_room({0.0f, 3.5f, 0.0f}));
  EXPECT_FALSE(rq.is_inside_room({0.0f, -0.5f, 0.0f}));
  EXPECT_FALSE(rq.is_inside_room({3.5f, 1.0f, 0.0f}));
  EXPECT_FALSE(rq.is_inside_room({100.0f, 1.0f, 0.0f}));
  EXPECT_FALSE(rq.is_inside_room(glm::vec3(std::nanf(""))));
  // Inside the sofa (centre (-1.3, -1.4), 0.45 m high): in the room, not in free space. Its top voxel holds the
  // scanned surface.
  const RoomLocation sofa = rq.locate({-1.3f, spec.floor_y + 0.43f, -1.4f});
  EXPECT_TRUE(sofa.inside);
  EXPECT_FALSE(sofa.free);
}

TEST(RandomPoints, OnTheAskedSurfacesAndInFreeSpace) {
  const synth::RoomSpec spec = synth::default_room();
  const RoomQueries& rq = queries_of(spec);
  int walls = 0, floors = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const std::optional<SurfacePoint> p = rq.random_point_on_surface(kOnFloor | kOnWall, 0.2f, seed);
    ASSERT_TRUE(p);
    const std::optional<SurfacePoint> again = rq.random_point_on_surface(kOnFloor | kOnWall, 0.2f, seed);
    EXPECT_EQ(p->position, again->position);
    if (p->surface == AreaType::Floor) {
      ++floors;
      EXPECT_NEAR(p->position.y, spec.floor_y, 0.03f);
      EXPECT_GT(synth::distance_to_walls(spec, xz(p->position)), 0.2f - kVoxel);
      EXPECT_GT(synth::distance_to_furniture(spec, xz(p->position)), 0.2f - kVoxel);
    } else {
      ASSERT_EQ(p->surface, AreaType::Wall);
      ++walls;
      EXPECT_LT(std::abs(synth::distance_to_walls(spec, xz(p->position))), 0.15f);
      EXPECT_NEAR(p->normal.y, 0.0f, 1e-5f);
    }
  }
  EXPECT_GT(walls, 20);
  EXPECT_GT(floors, 20);
  EXPECT_FALSE(RoomQueries().random_point_on_surface(kOnFloor, 0.0f, 1));
  EXPECT_THROW(rq.random_point_on_surface(0, 0.0f, 1), Error);

  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    const std::optional<glm::vec3> p = rq.random_point_in_room(0.3f, seed);
    ASSERT_TRUE(p);
    EXPECT_TRUE(rq.locate(*p).free);
    EXPECT_GT(synth::distance_to_walls(spec, xz(*p)), 0.3f - kVoxel);
    EXPECT_GT(p->y, spec.floor_y + 0.3f - kVoxel);
    EXPECT_LT(p->y, spec.ceiling_y - 0.3f + kVoxel);
    const std::optional<float> top = synth::furniture_top_at(spec, xz(*p));
    if (top) {
      EXPECT_GT(p->y, spec.floor_y + *top);
    }
  }
  EXPECT_FALSE(rq.random_point_in_room(3.0f, 1));  // no spot 3 m from everything in a 2.6 m high room
}

}  // namespace
}  // namespace roomsense
