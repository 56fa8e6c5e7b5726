// Planar surfaces (surfaces.h) against the synthetic rooms' ground truth: floors and ceilings at their heights
// over the room's outline, one wall plane per wall of the outline (also off the axes, in an L-shaped room and
// in a second storey), split at doors but not at windows, tables and box tops at their heights.
#include "roomsense/surfaces.h"

#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "roomsense/synthetic.h"
#include "synthetic_fixture.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <stop_token>
#include <string>
#include <vector>

namespace roomsense {
namespace {

std::vector<synth::RoomSpec> rooms() {
  return {synth::default_room(), synth::rotated_room(30.0f), synth::pentagon_room(), synth::large_triangle_room(),
          synth::hall_room()};
}

std::vector<Surface> of_kind(const std::vector<Surface>& all, SurfaceKind kind) {
  std::vector<Surface> out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out), [&](const Surface& s) { return s.kind == kind; });
  return out;
}

float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

float signed_area(const std::vector<glm::vec2>& p) {
  float twice = 0.0f;
  for (std::size_t i = 0; i < p.size(); ++i) twice += cross2(p[i], p[(i + 1) % p.size()]);
  return 0.5f * twice;
}

bool segments_cross(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  const float d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a), d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

bool simple(const std::vector<glm::vec2>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false;
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (glm::distance(p[i], p[j]) < 1e-5f) return false;
  return true;
}

float outline_area(const synth::RoomSpec& spec) {
  float twice = 0.0f;
  for (std::size_t i = 0; i < spec.outline.size(); ++i) twice += cross2(spec.outline[i], spec.outline[(i + 1) % spec.outline.size()]);
  return 0.5f * std::abs(twice);
}

using test::xz;

// A wall of the outline: from a to b, the room on its inward side.
struct TrueWall {
  glm::vec2 a, b, inward;
  float length() const { return glm::distance(a, b); }
  glm::vec2 dir() const { return (b - a) / length(); }
  float distance(glm::vec2 p) const { return std::abs(cross2(dir(), p - a)); }
  float along(glm::vec2 p) const { return glm::dot(p - a, dir()); }
};

TrueWall true_wall(const synth::RoomSpec& spec, std::size_t i) {
  const glm::vec2 a = spec.outline[i], b = spec.outline[(i + 1) % spec.outline.size()];
  const glm::vec2 d = glm::normalize(b - a);
  return {a, b, {d.y, -d.x}};  // counter-clockwise seen from +Y: the room lies to the right in (x, z)
}

float degrees_between(glm::vec2 a, glm::vec2 b) {
  return float(std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)) * 180.0 /
               std::numbers::pi);
}

// The walls of `found` that lie along true wall i.
std::vector<Surface> walls_along(const std::vector<Surface>& found, const TrueWall& w) {
  std::vector<Surface> out;
  for (const Surface& s : of_kind(found, SurfaceKind::Wall))
    if (degrees_between(xz(s.normal), w.inward) < 10.0f && w.distance(xz(s.center)) < 0.15f) out.push_back(s);
  return out;
}

TEST(Surfaces, FloorAndCeilingFollowTheRoom) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    ASSERT_TRUE(room.result.ok()) << spec.name;
    const float voxel = room.result.voxels.grid.spec.voxel_size;
    const std::vector<Surface> all = extract_surfaces(room.result);
    const std::vector<Surface> floors = of_kind(all, SurfaceKind::Floor), ceilings = of_kind(all, SurfaceKind::Ceiling);
    ASSERT_EQ(floors.size(), 1u) << spec.name;
    ASSERT_EQ(ceilings.size(), 1u) << spec.name;
    for (const Surface* s : {&floors[0], &ceilings[0]}) {
      const bool floor = s->kind == SurfaceKind::Floor;
      EXPECT_EQ(s->storey, 0u);
      EXPECT_NEAR(s->center.y, floor ? spec.floor_y : spec.ceiling_y, voxel) << spec.name;
      EXPECT_EQ(s->normal, glm::vec3(0.0f, floor ? 1.0f : -1.0f, 0.0f)) << spec.name;
      EXPECT_NEAR(signed_area(s->polygon), outline_area(spec), 0.15f * outline_area(spec)) << spec.name;
      // Every corner lies on the room's outline, within a voxel and a half.
      const glm::vec3 y_axis = s->y_axis();
      for (glm::vec2 p : s->polygon) {
        const glm::vec3 w = s->center + s->x_axis * p.x + y_axis * p.y;
        EXPECT_NEAR(w.y, s->center.y, 1e-4f);
        EXPECT_LT(synth::distance_to_walls(spec, xz(w)), 1.5f * voxel) << spec.name << " corner " << w.x << ", " << w.z;
      }
    }
    // Axis-aligned rooms get axis-aligned rectangles: x_axis = +X, extents the room's size.
    if (spec.name == "default" || spec.name == "hall") {
      EXPECT_EQ(floors[0].x_axis, glm::vec3(1.0f, 0.0f, 0.0f)) << spec.name;
      EXPECT_EQ(ceilings[0].x_axis, glm::vec3(1.0f, 0.0f, 0.0f)) << spec.name;
    }
  }
}

TEST(Surfaces, OneWallPlanePerWallOfTheRoom) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const std::vector<Surface> all = extract_surfaces(room.result);
    const float voxel = room.result.voxels.grid.spec.voxel_size;
    // The default room's window (in wall 1, 1.6 m wide) is no opening to walk through: it does not split.
    EXPECT_EQ(of_kind(all, SurfaceKind::Wall).size(), spec.outline.size()) << spec.name;
    for (std::size_t i = 0; i < spec.outline.size(); ++i) {
      const TrueWall w = true_wall(spec, i);
      const std::vector<Surface> along = walls_along(all, w);
      ASSERT_EQ(along.size(), 1u) << spec.name << " wall " << i;
      const Surface& s = along[0];
      EXPECT_LT(degrees_between(xz(s.normal), w.inward), 5.0f) << spec.name << " wall " << i;
      EXPECT_NEAR(s.extents.x, w.length(), 4.0f * voxel) << spec.name << " wall " << i;
      EXPECT_NEAR(s.extents.y, spec.ceiling_y - spec.floor_y, 2.0f * voxel) << spec.name << " wall " << i;
      EXPECT_NEAR(s.center.y, 0.5f * (spec.floor_y + spec.ceiling_y), voxel) << spec.name << " wall " << i;
      EXPECT_NEAR(w.along(xz(s.center)), 0.5f * w.length(), 2.0f * voxel) << spec.name << " wall " << i;
      EXPECT_NEAR(s.y_axis().y, 1.0f, 1e-5f) << spec.name << " wall " << i;
      EXPECT_NEAR(s.normal.y, 0.0f, 1e-6f);
    }
  }
}

// An L-shaped room, 6 x 6 m less a 3 x 3 m corner, 2.6 m high, turned by yaw about +Y (the synthetic rooms
// are convex). Floor, ceiling and walls meshed in 5 cm cells.
struct LShapedRoom {
  synth::RoomSpec spec;  // outline and heights only, for TrueWall and outline_area
  Scan scan;
};

LShapedRoom l_shaped_room(float yaw_degrees) {
  LShapedRoom room;
  const float c = std::cos(glm::radians(yaw_degrees)), s = std::sin(glm::radians(yaw_degrees));
  const auto turn = [&](glm::vec2 p) { return glm::vec2(c * p.x - s * p.y, s * p.x + c * p.y); };
  const auto at = [&](float x, float y, float z) { const glm::vec2 p = turn({x, z}); return glm::vec3(p.x, y, p.y); };
  const auto quad = [&](glm::vec3 o, glm::vec3 u, glm::vec3 v) {
    const int nu = int(std::lround(glm::length(u) / 0.05f)), nv = int(std::lround(glm::length(v) / 0.05f));
    const std::uint32_t base = std::uint32_t(room.scan.vertices.size());
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i) room.scan.vertices.push_back(o + u * (float(i) / float(nu)) + v * (float(j) / float(nv)));
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const std::uint32_t a = base + std::uint32_t(j * (nu + 1) + i), b = a + 1, d = a + std::uint32_t(nu + 1), e = d + 1;
        room.scan.indices.insert(room.scan.indices.end(), {a, b, e, a, e, d});
      }
  };
  const float height = 2.6f;
  const glm::vec3 x = at(1, 0, 0) - at(0, 0, 0), z = at(0, 0, 1) - at(0, 0, 0), up(0.0f, height, 0.0f);
  for (float y : {0.0f, height}) {
    quad(at(0, y, 0), x * 6.0f, z * 3.0f);
    quad(at(0, y, 3), x * 3.0f, z * 3.0f);
  }
  room.spec.outline = {{0, 0}, {0, 6}, {3, 6}, {3, 3}, {6, 3}, {6, 0}};  // counter-clockwise seen from +Y
  for (glm::vec2& p : room.spec.outline) p = turn(p);
  room.spec.ceiling_y = height;
  for (std::size_t i = 0; i < room.spec.outline.size(); ++i) {
    const glm::vec2 a = room.spec.outline[i], b = room.spec.outline[(i + 1) % room.spec.outline.size()];
    quad(glm::vec3(a.x, 0.0f, a.y), glm::vec3(b.x - a.x, 0.0f, b.y - a.y), up);
  }
  return room;
}

TEST(Surfaces, AnLShapedRoomHasSixWallsAndAnLShapedFloor) {
  for (float yaw : {0.0f, 30.0f}) {
    const LShapedRoom room = l_shaped_room(yaw);
    const AnalysisResult r = analyze(room.scan);
    ASSERT_TRUE(r.ok());
    const std::vector<Surface> all = extract_surfaces(r);
    const std::vector<Surface> floors = of_kind(all, SurfaceKind::Floor);
    ASSERT_EQ(floors.size(), 1u);
    EXPECT_EQ(floors[0].polygon.size(), 6u) << yaw;
    EXPECT_NEAR(signed_area(floors[0].polygon), outline_area(room.spec), 0.05f * outline_area(room.spec)) << yaw;
    EXPECT_EQ(of_kind(all, SurfaceKind::Wall).size(), 6u) << yaw;
    for (std::size_t i = 0; i < room.spec.outline.size(); ++i) {
      const TrueWall w = true_wall(room.spec, i);
      const std::vector<Surface> along = walls_along(all, w);
      ASSERT_EQ(along.size(), 1u) << yaw << "° wall " << i;
      EXPECT_NEAR(along[0].extents.x, w.length(), 0.3f) << yaw << "° wall " << i;
    }
  }
}

TEST(Surfaces, ADoorOrAnOpeningSplitsAWallAndAWindowDoesNot) {
  synth::RoomSpec spec = synth::default_room();
  spec.name = "default-with-openings";
  spec.windows.push_back({3, 1.0f, 1.9f, 0.0f, 2.0f});  // a door in the -Z wall, 0.9 m wide, 2 m high
  spec.windows.push_back({2, 1.0f, 2.0f, 0.0f, 2.7f});  // floor to ceiling in the +X wall, 1 m wide
  const test::AnalysedRoom& room = test::analysed(spec);
  ASSERT_TRUE(room.result.ok());
  const std::vector<Surface> all = extract_surfaces(room.result);
  EXPECT_EQ(of_kind(all, SurfaceKind::Wall).size(), 6u);
  const std::size_t expected[] = {1, 1, 2, 2};
  for (std::size_t i = 0; i < 4; ++i) {
    const TrueWall w = true_wall(spec, i);
    const std::vector<Surface> along = walls_along(all, w);
    EXPECT_EQ(along.size(), expected[i]) << "wall " << i;
    for (const Surface& s : along) {
      // No segment spans an opening's middle.
      const float mid = w.along(xz(s.center)), half = 0.5f * s.extents.x;
      for (const synth::Window& o : spec.windows)
        if (o.wall == int(i) && o.y0 <= 0.0f) {
          const float middle = 0.5f * (o.u0 + o.u1);
          EXPECT_FALSE(mid - half < middle && middle < mid + half) << "wall " << i << " spans the opening";
        }
    }
  }
}

TEST(Surfaces, TablesAndBoxTopsAreFoundAtTheirHeight) {
  const SurfaceParams params;
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const std::vector<Surface> all = extract_surfaces(room.result, params);
    std::vector<Surface> tops = of_kind(all, SurfaceKind::Table);
    for (const Surface& s : of_kind(all, SurfaceKind::Furniture)) tops.push_back(s);
    const auto top_near = [&](glm::vec2 centre, float height) -> const Surface* {
      for (const Surface& s : tops)
        if (glm::distance(xz(s.center), centre) < 0.1f && std::abs(s.center.y - (spec.floor_y + height)) < 0.1f) return &s;
      return nullptr;
    };
    for (const synth::Table& t : spec.tables) {
      const Surface* s = top_near(t.centre, t.height);
      ASSERT_NE(s, nullptr) << spec.name << " table at " << t.centre.x << ", " << t.centre.y;
      EXPECT_EQ(s->kind, SurfaceKind::Table) << spec.name;
    }
    for (const synth::Box& b : spec.boxes) {
      if (b.height > 1.5f) continue;  // a cabinet reads as wall (§3.2.2): no top
      const Surface* s = top_near(b.centre, b.height);
      ASSERT_NE(s, nullptr) << spec.name << " box at " << b.centre.x << ", " << b.centre.y;
      if (b.height < params.table_min - 0.1f || b.height > params.table_max + 0.1f) {
        EXPECT_EQ(s->kind, SurfaceKind::Furniture) << spec.name;
      } else if (b.height > params.table_min + 0.1f && b.height < params.table_max - 0.1f) {
        EXPECT_EQ(s->kind, SurfaceKind::Table) << spec.name;
      }
    }
    // And nothing else: every top stands over some furniture.
    for (const Surface& s : tops) {
      EXPECT_TRUE(synth::furniture_top_at(spec, xz(s.center)).has_value())
          << spec.name << " a top at " << s.center.x << ", " << s.center.z;
      EXPECT_EQ(s.normal, glm::vec3(0.0f, 1.0f, 0.0f));
    }
    EXPECT_EQ(tops.size(), spec.tables.size() + std::size_t(std::count_if(spec.boxes.begin(), spec.boxes.end(),
                                                                           [](const synth::Box& b) { return b.height <= 1.5f; })))
        << spec.name;
  }
}

TEST(Surfaces, PolygonsAreCounterClockwiseSimpleAndFillTheirRectangle) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    for (const Surface& s : extract_surfaces(room.result)) {
      const std::string what = spec.name + " " + std::string(surface_kind_name(s.kind));
      ASSERT_GE(s.polygon.size(), 3u) << what;
      EXPECT_GT(signed_area(s.polygon), 0.0f) << what << ": not counter-clockwise seen from +Z";
      EXPECT_TRUE(simple(s.polygon)) << what;
      EXPECT_NEAR(glm::length(s.normal), 1.0f, 1e-5f) << what;
      EXPECT_NEAR(glm::length(s.x_axis), 1.0f, 1e-5f) << what;
      EXPECT_NEAR(glm::dot(s.normal, s.x_axis), 0.0f, 1e-5f) << what;
      EXPECT_NEAR(s.x_axis.y, 0.0f, 1e-6f) << what << ": x_axis is horizontal";
      glm::vec2 lo(INFINITY), hi(-INFINITY);
      for (glm::vec2 p : s.polygon) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
      // `extents` is the bounding rectangle about `center`.
      EXPECT_NEAR(hi.x - lo.x, s.extents.x, 1e-3f) << what;
      EXPECT_NEAR(hi.y - lo.y, s.extents.y, 1e-3f) << what;
      EXPECT_NEAR(hi.x + lo.x, 0.0f, 1e-3f) << what;
      EXPECT_NEAR(hi.y + lo.y, 0.0f, 1e-3f) << what;
      // MESH_2D: counter-clockwise triangles of the polygon's own vertices that cover exactly its area.
      ASSERT_EQ(s.triangles.size(), 3 * (s.polygon.size() - 2)) << what;
      float covered = 0.0f;
      for (std::size_t t = 0; t < s.triangles.size(); t += 3) {
        ASSERT_LT(std::max({s.triangles[t], s.triangles[t + 1], s.triangles[t + 2]}), s.polygon.size()) << what;
        const float a = signed_area({s.polygon[s.triangles[t]], s.polygon[s.triangles[t + 1]], s.polygon[s.triangles[t + 2]]});
        EXPECT_GE(a, 0.0f) << what;
        covered += a;
      }
      EXPECT_NEAR(covered, signed_area(s.polygon), 1e-3f * std::max(1.0f, signed_area(s.polygon))) << what;
    }
  }
}

TEST(Surfaces, OrientationTurnsTheAxesOntoThePlane) {
  for (const Surface& s : extract_surfaces(test::analysed(synth::rotated_room(30.0f)).result)) {
    const glm::quat q = s.orientation();
    const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::distance(a, b) < 1e-5f; };
    EXPECT_TRUE(near(q * glm::vec3(0, 0, 1), s.normal)) << surface_kind_name(s.kind);
    EXPECT_TRUE(near(q * glm::vec3(1, 0, 0), s.x_axis)) << surface_kind_name(s.kind);
    EXPECT_TRUE(near(q * glm::vec3(0, 1, 0), s.y_axis())) << surface_kind_name(s.kind);
  }
}

TEST(Surfaces, KindsComeInOrderAndTheResultIsStable) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const std::vector<Surface> a = extract_surfaces(room.result), b = extract_surfaces(room.result);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].kind, b[i].kind);
      EXPECT_EQ(a[i].center, b[i].center);
      EXPECT_EQ(a[i].polygon, b[i].polygon);
      if (i > 0) {
        EXPECT_LE(int(a[i - 1].kind), int(a[i].kind)) << spec.name;
      }
    }
  }
  EXPECT_EQ(surface_kind_name(SurfaceKind::Floor), "floor");
  EXPECT_EQ(surface_kind_name(SurfaceKind::Table), "table");
  EXPECT_EQ(surface_kind_name(SurfaceKind::Furniture), "furniture");
}

TEST(Surfaces, EveryStoreyGetsItsFloorCeilingAndWalls) {
  // A 4 x 3 m room on top of the default room, its floor 0.4 m above the lower ceiling.
  synth::RoomSpec upper;
  upper.name = "upper";
  upper.outline = synth::rectangle(4.0f, 3.0f);
  upper.floor_y = 3.0f;
  upper.ceiling_y = 5.5f;
  upper.noise = 0.004f;
  Scan scan = synth::generate(synth::default_room());
  const Scan top = synth::generate(upper);
  const std::uint32_t base = std::uint32_t(scan.vertices.size());
  scan.vertices.insert(scan.vertices.end(), top.vertices.begin(), top.vertices.end());
  for (std::uint32_t i : top.indices) scan.indices.push_back(base + i);
  const AnalysisResult r = analyze(scan);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.storeys.size(), 2u);
  const std::vector<Surface> all = extract_surfaces(r);
  const float voxel = r.voxels.grid.spec.voxel_size;
  for (SurfaceKind kind : {SurfaceKind::Floor, SurfaceKind::Ceiling}) {
    const std::vector<Surface> found = of_kind(all, kind);
    ASSERT_EQ(found.size(), 2u) << surface_kind_name(kind);
    EXPECT_EQ(found[0].storey, 0u);
    EXPECT_EQ(found[1].storey, 1u);
    EXPECT_NEAR(found[1].center.y, kind == SurfaceKind::Floor ? upper.floor_y : upper.ceiling_y, voxel);
    EXPECT_NEAR(signed_area(found[1].polygon), outline_area(upper), 0.15f * outline_area(upper));
  }
  std::size_t upper_walls = 0;
  for (const Surface& s : of_kind(all, SurfaceKind::Wall)) {
    if (s.storey != 1) continue;
    ++upper_walls;
    EXPECT_NEAR(s.center.y, 0.5f * (upper.floor_y + upper.ceiling_y), voxel);
  }
  EXPECT_EQ(upper_walls, 4u);
  for (std::size_t i = 0; i < upper.outline.size(); ++i) {
    const TrueWall w = true_wall(upper, i);
    std::size_t n = 0;
    for (const Surface& s : walls_along(all, w)) n += s.storey == 1 ? 1 : 0;
    EXPECT_EQ(n, 1u) << "upper wall " << i;
  }
}

TEST(Surfaces, NoRoomNoSurfaces) {
  AnalysisResult r;
  r.status = AnalysisStatus::NoFloorCeiling;
  EXPECT_TRUE(extract_surfaces(r).empty());
}

TEST(Surfaces, AStopRequestCancels) {
  const test::AnalysedRoom& room = test::analysed(synth::default_room());
  std::stop_source source;
  source.request_stop();
  try {
    extract_surfaces(room.result, {}, source.get_token());
    FAIL() << "no Error(Cancelled)";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Cancelled);
  }
}

TEST(Surfaces, TakeLittleTimeNextToTheAnalysis) {
  for (const synth::RoomSpec& spec : {synth::default_room(), synth::thesis_room1()}) {
    const test::AnalysedRoom& room = test::analysed(spec);
    double best = INFINITY;
    for (int run = 0; run < 5; ++run) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<Surface> found = extract_surfaces(room.result);
      best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      EXPECT_FALSE(found.empty());
    }
    std::printf("[ timing   ] %s: extract_surfaces %.2f ms, analysis %.1f ms\n", spec.name.c_str(), best,
                room.result.timings.total);
    EXPECT_LT(best, room.result.timings.total) << spec.name;
  }
}

}  // namespace
}  // namespace roomsense
