// Whole homes (issue 15): every storey found and analysed, and a storey split into rooms, against the ground
// truth of the synthetic house and flat.
#include "roomsense/analysis.h"
#include "roomsense/bounds.h"
#include "roomsense/export.h"
#include "roomsense/surfaces.h"
#include "roomsense/synthetic.h"
#include "../../core/src/pipeline/storeys.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <span>
#include <cmath>
#include <cstdio>
#include <random>

namespace roomsense {
namespace {

struct AnalysedHouse {
  synth::HouseSpec spec;
  AnalysisResult result;
};

const AnalysedHouse& house() {
  static const AnalysedHouse h = [] {
    AnalysedHouse out{synth::two_storey_house(), {}};
    out.result = analyze(synth::generate(out.spec));
    return out;
  }();
  return h;
}

// Free space as a bounds volume sees it: the voxels outside the volume reached from `seed` through voxels
// outside it, 6-connected, within the grid (a window leads out of it, as in the thesis).
std::vector<std::uint8_t> free_space_from(const GridSpec& s, const std::vector<std::uint8_t>& volume, glm::ivec3 seed) {
  std::vector<std::uint8_t> reached(volume.size(), 0);
  std::vector<glm::ivec3> stack{seed};
  reached[s.index(seed.x, seed.y, seed.z)] = 1;
  while (!stack.empty()) {
    const glm::ivec3 v = stack.back();
    stack.pop_back();
    for (const glm::ivec3 d : {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, -1, 0),
                               glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)}) {
      const glm::ivec3 n = v + d;
      if (!s.contains(n.x, n.y, n.z)) continue;
      const std::size_t i = s.index(n.x, n.y, n.z);
      if (volume[i] || reached[i]) continue;
      reached[i] = 1;
      stack.push_back(n);
    }
  }
  return reached;
}

// The storey of the result whose floor is nearest the spec's.
std::size_t storey_index(const AnalysisResult& r, const synth::RoomSpec& spec) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < r.storeys.size(); ++i)
    if (std::fabs(r.storeys[i].floor_y - spec.floor_y) < std::fabs(r.storeys[best].floor_y - spec.floor_y)) best = i;
  return best;
}

bool in_rect(const synth::Rect& rect, glm::vec2 p, float margin) {
  return p.x > rect.lo.x - margin && p.x < rect.hi.x + margin && p.y > rect.lo.y - margin && p.y < rect.hi.y + margin;
}

// An IncrementalAnalysis counts the horizontal surfaces per level (which find the storeys' slabs) again only in
// the columns that changed: equal to counting the whole grid, step after step of random changes.
TEST(Storeys, HorizontalCountsUpdatedInChangedColumnsEqualTheWholeCount) {
  GridSpec spec;
  spec.nx = 20, spec.ny = 16, spec.nz = 18;
  std::mt19937 random(3);
  VoxelGrid grid(spec);
  for (std::uint8_t& cell : grid.cells) cell = random() % 3 == 0;
  std::vector<std::uint32_t> counts = detail::horizontal_counts(grid);
  for (int step = 0; step < 20; ++step) {
    VoxelGrid next = grid;
    std::vector<std::uint8_t> changed(spec.column_count(), 0);
    for (int k = 0; k < 12; ++k) {
      const std::size_t col = random() % spec.column_count();
      changed[col] = 1;
      for (int n = 0; n < 4; ++n) next.cells[col * std::size_t(spec.ny) + random() % std::size_t(spec.ny)] ^= 1;
    }
    counts = detail::horizontal_counts(next, grid, counts, changed);
    ASSERT_EQ(counts, detail::horizontal_counts(next)) << "step " << step;
    grid = std::move(next);
  }
}

// The whole count (its loop without branches) equals the columns' counts one by one (the update's own loop, from
// an empty grid) for grids of any height and any nonzero voxel byte.
TEST(Storeys, HorizontalCountsOfAWholeGridAreEachColumnsCounts) {
  std::mt19937 random(11);
  for (const int ny : {1, 2, 3, 4, 9, 29}) {
    GridSpec spec;
    spec.nx = 7, spec.ny = ny, spec.nz = 5;
    VoxelGrid grid(spec);
    for (std::uint8_t& cell : grid.cells) cell = random() % 2 == 0 ? 0 : std::uint8_t(1 + random() % 255);
    const std::vector<std::uint8_t> all(spec.column_count(), 1);
    const std::vector<std::uint32_t> by_column =
        detail::horizontal_counts(grid, VoxelGrid(spec), std::vector<std::uint32_t>(std::size_t(ny), 0), all);
    EXPECT_EQ(detail::horizontal_counts(grid), by_column) << ny << " levels";
  }
}

TEST(Storeys, EveryStoreyOfTheHouseAtItsHeights) {
  const AnalysedHouse& h = house();
  const AnalysisResult& r = h.result;
  ASSERT_TRUE(r.ok()) << r.status_message;
  ASSERT_EQ(r.storeys.size(), h.spec.storeys.size());
  for (const synth::RoomSpec& spec : h.spec.storeys) {
    const Storey& s = r.storeys[storey_index(r, spec)];
    EXPECT_NEAR(s.floor_y, spec.floor_y, 0.05f);
    EXPECT_NEAR(s.ceiling_y, spec.ceiling_y, 0.05f);
    std::printf("[ figures  ] house storey at %.2f m: floor %.3f, ceiling %.3f\n", double(spec.floor_y),
                double(s.floor_y), double(s.ceiling_y));
  }
  // The thesis's pair (the two fullest levels) is the ground floor and the top ceiling: the main storey is the
  // ground floor's, not both at once.
  EXPECT_NEAR(r.ceiling_y - r.floor_y, 2.5f, 0.05f);
}

TEST(Storeys, AreasOnEveryStoreyAndNoneOverTheStairwellOrHalfwayUp) {
  const AnalysedHouse& h = house();
  const AnalysisResult& r = h.result;
  ASSERT_TRUE(r.ok());
  const synth::Rect well = h.spec.storeys[1].floor_openings.at(0);
  for (const synth::RoomSpec& spec : h.spec.storeys) {
    const std::size_t index = storey_index(r, spec);
    const Storey& storey = r.storeys[index];
    std::array<int, 4> by_type{};
    for (const Area& a : r.areas) {
      if (a.storey != index) continue;
      ++by_type[std::size_t(a.type) - 1];
      const glm::vec2 c{a.center.x, a.center.z};
      for (const glm::vec3& corner : a.corners)
        EXPECT_TRUE(synth::inside_outline(spec, {corner.x, corner.z})) << to_string(a.type);
      switch (a.type) {
        case AreaType::Floor:
          EXPECT_NEAR(a.center.y, storey.floor_y, 1e-4f);
          break;
        case AreaType::Ceiling:
          EXPECT_NEAR(a.center.y, storey.ceiling_y, 1e-4f);
          break;
        case AreaType::Furniture: {
          // On a piece of furniture of its own storey, or on the stair's treads: at 0.1 m voxels two treads
          // 0.18 m apart read as one top straddling a level boundary (a weakness the note names).
          const auto top = synth::furniture_top_at(spec, c);
          if (top) EXPECT_NEAR(a.center.y, spec.floor_y + *top, 0.11f);
          else EXPECT_TRUE(spec.floor_y == 0.0f && in_rect({{-2.8f, -2.45f}, {0.84f, -1.55f}}, c, 0.0f))
                   << "furniture area at " << c.x << ", " << c.y << " on neither furniture nor the stair";
          break;
        }
        case AreaType::Wall:
          EXPECT_GE(a.center.y - a.half_height, storey.floor_y - 0.05f);
          EXPECT_LE(a.center.y + a.half_height, storey.ceiling_y + 0.05f);
          break;
      }
      // The upper storey's floor has a hole: nothing may lie over it, to within the voxel its edge cuts.
      if (spec.floor_y > 0.0f && (a.type == AreaType::Floor || a.type == AreaType::Furniture)) {
        for (const glm::vec3& corner : a.corners) EXPECT_FALSE(in_rect(well, {corner.x, corner.z}, -0.1f));
      }
    }
    std::printf("[ figures  ] house storey at %.2f m: %d wall, %d floor, %d ceiling, %d furniture areas\n",
                double(spec.floor_y), by_type[0], by_type[1], by_type[2], by_type[3]);
    for (int count : by_type) EXPECT_GT(count, 0);
  }
  // No floor area at a height other than a storey's floor: the stair's treads are none.
  for (const Area& a : r.areas) {
    if (a.type != AreaType::Floor) continue;
    EXPECT_NEAR(a.center.y, r.storeys[a.storey].floor_y, 1e-4f);
  }
}

TEST(Storeys, OneClosedBoundsMeshKeepsEveryStoreysFreeSpaceAndEnclosesTheFurniture) {
  const AnalysedHouse& h = house();
  const AnalysisResult& r = h.result;
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(check_closure(r.bounds).closed());
  std::vector<std::uint8_t> volume = bounds_volume(r.voxels.grid, bounds_storeys(r));
  fill_edge_contacts(r.voxels.grid.spec, volume);
  const GridSpec& s = r.voxels.grid.spec;
  const auto voxel_of = [&](glm::vec3 p) { return glm::ivec3(glm::floor((p - s.origin) / s.voxel_size)); };
  for (const synth::RoomSpec& spec : h.spec.storeys) {
    // The storey's free space as the bounds see it, from the middle of the room.
    const glm::ivec3 seed = voxel_of({0.0f, spec.floor_y + 1.7f, 0.3f});
    ASSERT_EQ(volume[s.index(seed.x, seed.y, seed.z)], 0);
    const std::vector<std::uint8_t> reached = free_space_from(s, volume, seed);
    const auto free_in_bounds = [&](glm::vec3 p) {
      const glm::ivec3 v = voxel_of(p);
      return s.contains(v.x, v.y, v.z) && reached[s.index(v.x, v.y, v.z)] != 0;
    };
    // Free space: inside the outline, 0.15 m clear of walls, furniture and the stair and its well, from 0.2 m
    // above the floor to 0.2 m below the ceiling, on a 0.1 m lattice off the voxel boundaries.
    std::size_t free = 0, kept = 0;
    for (float y = spec.floor_y + 0.23f; y < spec.ceiling_y - 0.2f; y += 0.1f)
      for (float z = -2.5f; z < 2.5f; z += 0.1f)
        for (float x = -3.5f; x < 3.5f; x += 0.1f) {
          const glm::vec2 p{x + 0.033f, z + 0.027f};
          if (!synth::inside_outline(spec, p) || synth::distance_to_walls(spec, p) < 0.15f) continue;
          if (synth::distance_to_furniture(spec, p) < 0.15f) continue;
          const synth::Rect stair_box{{-2.95f, -2.6f}, {1.0f, -1.4f}};  // the stair, the well above it
          if (in_rect(stair_box, p, 0.0f)) continue;
          if (const auto top = synth::furniture_top_at(spec, p); top && y < spec.floor_y + *top + 0.15f) continue;
          ++free;
          kept += free_in_bounds({p.x, y, p.y}) ? 1 : 0;
        }
    ASSERT_GT(free, 10000u);
    const double share = double(kept) / double(free);
    std::printf("[ figures  ] house storey at %.2f m: %.2f %% of %zu free points kept\n", double(spec.floor_y),
                100.0 * share, free);
    EXPECT_GE(share, 0.99);
    // Every piece of furniture is enclosed: no part of it is free space.
    for (const synth::Box& b : spec.boxes)
      for (float y = spec.floor_y + 0.05f; y < spec.floor_y + b.height - 0.05f; y += 0.1f)
        EXPECT_FALSE(free_in_bounds({b.centre.x, y, b.centre.y})) << "box at " << b.centre.x << ", " << b.centre.y;
  }
}

TEST(Storeys, TheJsonSaysEachAreasStorey) {
  const AnalysisResult& r = house().result;
  const nlohmann::json doc = nlohmann::json::parse(analysis_json(r, {"synthetic:house", 0.0}));
  ASSERT_EQ(doc.at("storeys").size(), r.storeys.size());
  ASSERT_EQ(doc.at("areas").size(), r.areas.size());
  for (std::size_t i = 0; i < r.areas.size(); ++i) EXPECT_EQ(doc["areas"][i].at("storey"), r.areas[i].storey);
  for (const auto& storey : doc["storeys"]) EXPECT_GT(storey.at("room_m2").get<double>(), 30.0);
}

TEST(Storeys, SingleRoomsKeepOneStoreyEvenUnderAHighCeiling) {
  synth::RoomSpec tall = synth::hall_room(8.0f, 6.0f);
  tall.name = "tall";
  tall.ceiling_y = 4.5f;
  const AnalysisResult r = analyze(synth::generate(tall));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.storeys.size(), 1u);
  EXPECT_NEAR(r.ceiling_y, 4.5f, 0.05f);
}

// The flat's room containing p (ground truth), or -1.
int true_room(glm::vec2 p, float margin) {
  const std::vector<synth::Rect> rooms = synth::three_room_flat_rooms();
  for (std::size_t i = 0; i < rooms.size(); ++i)
    if (in_rect(rooms[i], p, margin)) return int(i);
  return -1;
}

// Per room of the result, the flat's true room its centre lies in (-1: none).
std::vector<int> true_rooms(const AnalysisResult& r) {
  std::vector<int> out;
  for (const Room& room : r.rooms) out.push_back(true_room({room.center.x, room.center.z}, 0.0f));
  return out;
}

const AnalysisResult& flat() {
  static const AnalysisResult r = analyze(synth::generate(synth::three_room_flat()));
  return r;
}

TEST(Rooms, TheFlatHasItsThreeRoomsAtTheirPlacesAndSizes) {
  const synth::RoomSpec spec = synth::three_room_flat();
  const AnalysisResult& r = flat();
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.storeys.size(), 1u);
  const std::vector<synth::Rect> truth = synth::three_room_flat_rooms();
  ASSERT_EQ(r.rooms.size(), truth.size());
  std::vector<int> matched(truth.size(), 0);
  for (const Room& room : r.rooms) {
    const int t = true_room({room.center.x, room.center.z}, 0.0f);
    ASSERT_GE(t, 0) << "a room centred at " << room.center.x << ", " << room.center.z;
    ++matched[std::size_t(t)];
    const synth::Rect& rect = truth[std::size_t(t)];
    const float area = (rect.hi.x - rect.lo.x) * (rect.hi.y - rect.lo.y);
    std::printf("[ figures  ] flat room %d: %.1f m2 of %.1f m2 inside its walls, floor %.3f, ceiling %.3f\n", t,
                double(room.floor_area), double(area), double(room.floor_y), double(room.ceiling_y));
    EXPECT_GT(room.floor_area, 0.85f * area);
    EXPECT_LE(room.floor_area, 1.02f * area);
    EXPECT_NEAR(room.floor_y, spec.floor_y, 0.05f);
    EXPECT_NEAR(room.ceiling_y, spec.ceiling_y, 0.05f);
  }
  for (const int m : matched) EXPECT_EQ(m, 1);
  // Largest first.
  for (std::size_t k = 1; k < r.rooms.size(); ++k) EXPECT_GE(r.rooms[k - 1].floor_area, r.rooms[k].floor_area);
}

TEST(Rooms, EveryAreaOfTheFlatLiesInTheRoomItNamesAndTheFloorIsCovered) {
  const synth::RoomSpec spec = synth::three_room_flat();
  const AnalysisResult& r = flat();
  ASSERT_TRUE(r.ok());
  const std::vector<synth::Rect> truth = synth::three_room_flat_rooms();
  const std::vector<int> truth_of_room = true_rooms(r);
  std::vector<std::array<int, 4>> by_type(r.rooms.size());
  for (const Area& a : r.areas) {
    ASSERT_NE(a.room, kNoRoom) << to_string(a.type) << " area at " << a.center.x << ", " << a.center.z;
    ASSERT_LT(std::size_t(a.room), r.rooms.size());
    ++by_type[std::size_t(a.room)][std::size_t(a.type) - 1];
    const int t = truth_of_room[std::size_t(a.room)];
    // Horizontal areas lie wholly in their room (to within a voxel); a wall area faces into it.
    if (a.type == AreaType::Wall) {
      const glm::vec3 front = a.center + 0.15f * a.normal;
      EXPECT_EQ(true_room({front.x, front.z}, 0.1f), t) << "wall area at " << a.center.x << ", " << a.center.z;
    } else {
      for (const glm::vec3& c : a.corners) EXPECT_TRUE(in_rect(truth[std::size_t(t)], {c.x, c.z}, 0.1f))
          << to_string(a.type) << " area at " << a.center.x << ", " << a.center.z;
    }
  }
  for (std::size_t k = 0; k < r.rooms.size(); ++k) {
    std::printf("[ figures  ] flat room %d: %d wall, %d floor, %d ceiling, %d furniture areas\n", truth_of_room[k],
                by_type[k][0], by_type[k][1], by_type[k][2], by_type[k][3]);
    EXPECT_GT(by_type[k][0], 0);
    EXPECT_GT(by_type[k][1], 0);
    EXPECT_GT(by_type[k][2], 0);
  }
  // Coverage of each room's free floor by its floor areas, on a 5 cm raster.
  for (std::size_t k = 0; k < r.rooms.size(); ++k) {
    const synth::Rect& rect = truth[std::size_t(truth_of_room[k])];
    int free = 0, covered = 0;
    for (float z = rect.lo.y + 0.025f; z < rect.hi.y; z += 0.05f)
      for (float x = rect.lo.x + 0.025f; x < rect.hi.x; x += 0.05f) {
        const glm::vec2 p{x, z};
        if (synth::distance_to_walls(spec, p) <= 0.1f || synth::distance_to_furniture(spec, p) <= 0.1f) continue;
        ++free;
        for (const Area& a : r.areas) {
          if (a.type != AreaType::Floor || a.room != int(k)) continue;
          const glm::vec3 d = glm::vec3(x, a.center.y, z) - a.center;
          if (std::fabs(glm::dot(d, a.x_axis())) <= a.half_width && std::fabs(glm::dot(d, a.y_axis())) <= a.half_height) {
            ++covered;
            break;
          }
        }
      }
    const double share = double(covered) / double(std::max(free, 1));
    std::printf("[ figures  ] flat room %d: floor areas cover %.1f %% of its free floor\n", truth_of_room[k], 100.0 * share);
    EXPECT_GE(share, 0.5);
  }
}

}  // namespace
}  // namespace roomsense

namespace roomsense {
namespace {

// Issue 15: a closed bounds mesh per room. Each keeps its room's free space (as the house's storeys, on the
// room's volume) and none of the other rooms' beyond their doorways, and its mesh spans its room.
TEST(Rooms, EachRoomHasAClosedBoundsMeshAroundItsOwnFreeSpace) {
  const synth::RoomSpec spec = synth::three_room_flat();
  const AnalysisResult& r = flat();
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.room_bounds.size(), r.rooms.size());
  const std::vector<synth::Rect> truth = synth::three_room_flat_rooms();
  const GridSpec& s = r.voxels.grid.spec;
  const int reach = int(std::lround(0.3f / s.voxel_size));
  const auto voxel_of = [&](glm::vec3 p) { return glm::ivec3(glm::floor((p - s.origin) / s.voxel_size)); };
  for (std::size_t k = 0; k < r.rooms.size(); ++k) {
    const BoundsMesh& mesh = r.room_bounds[k];
    EXPECT_TRUE(check_closure(mesh).closed()) << "room " << k;
    ASSERT_FALSE(mesh.indices.empty());
    const int t = true_room({r.rooms[k].center.x, r.rooms[k].center.z}, 0.0f);
    ASSERT_GE(t, 0);
    // The room's volume, as analyze() built the mesh from it; its free space is what the room's centre reaches.
    const std::vector<std::uint8_t> mask = room_mask(s, r.features->room, r.features->rooms, int(k), reach);
    const BoundsStorey storey = bounds_storeys(r)[0];
    std::vector<std::uint8_t> volume = room_bounds_volume(r.voxels.grid, storey, mask);
    fill_edge_contacts(s, volume);
    EXPECT_EQ(mesh.indices, build_room_bounds(r.voxels.grid, storey, mask).indices);
    const glm::ivec3 seed = voxel_of({r.rooms[k].center.x, 1.2f, r.rooms[k].center.z});
    ASSERT_EQ(volume[s.index(seed.x, seed.y, seed.z)], 0) << "room " << k << "'s centre is solid";
    const std::vector<std::uint8_t> reached = free_space_from(s, volume, seed);
    std::array<std::size_t, 3> free{}, kept{};
    for (float y = 0.23f; y < spec.ceiling_y - 0.2f; y += 0.1f)
      for (float z = -3.0f; z < 3.0f; z += 0.1f)
        for (float x = -4.5f; x < 4.5f; x += 0.1f) {
          const glm::vec2 p{x + 0.033f, z + 0.027f};
          if (synth::distance_to_walls(spec, p) < 0.15f || synth::distance_to_furniture(spec, p) < 0.15f) continue;
          if (const auto top = synth::furniture_top_at(spec, p); top && y < *top + 0.15f) continue;
          const int owner = true_room(p, 0.0f);
          if (owner < 0) continue;
          // 0.7 m either side of a doorway belongs to both rooms: the split runs somewhere through it.
          bool near_door = false;
          for (const synth::Partition& w : spec.partitions)
            for (const synth::Doorway& d : w.doorways) {
              const glm::vec2 dir = glm::normalize(w.b - w.a);
              const glm::vec2 lo = w.a + dir * d.u0, hi = w.a + dir * d.u1;
              const glm::vec2 mid = 0.5f * (lo + hi);
              near_door = near_door || glm::distance(p, mid) < 0.5f * glm::distance(lo, hi) + 0.7f;
            }
          if (near_door) continue;
          const glm::ivec3 v = voxel_of({p.x, y, p.y});
          ++free[std::size_t(owner)];
          kept[std::size_t(owner)] += s.contains(v.x, v.y, v.z) && reached[s.index(v.x, v.y, v.z)] ? 1 : 0;
        }
    for (int o = 0; o < 3; ++o) {
      const double share = double(kept[std::size_t(o)]) / double(std::max<std::size_t>(free[std::size_t(o)], 1));
      if (o == t) {
        std::printf("[ figures  ] flat room %d: bounds of %zu triangles keep %.2f %% of its %zu free points\n", t,
                    mesh.indices.size() / 3, 100.0 * share, free[std::size_t(o)]);
        EXPECT_GE(share, 0.99) << "room " << t;
      } else {
        EXPECT_EQ(kept[std::size_t(o)], 0u) << "room " << t << "'s bounds hold free space of room " << o;
      }
    }
    // Its furniture is enclosed: no part of it is free space.
    for (const synth::Box& b : spec.boxes)
      for (float y = 0.05f; y < b.height - 0.05f; y += 0.1f) {
        const glm::ivec3 v = voxel_of({b.centre.x, y, b.centre.y});
        EXPECT_FALSE(s.contains(v.x, v.y, v.z) && reached[s.index(v.x, v.y, v.z)]) << "box at " << b.centre.x;
      }
  }
}

}  // namespace
}  // namespace roomsense

namespace roomsense {
namespace {

double polygon_area(const std::vector<glm::vec2>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::vec2 a = p[i], b = p[(i + 1) % p.size()];
    twice += double(a.x) * double(b.y) - double(b.x) * double(a.y);
  }
  return 0.5 * twice;
}

// Issue 15: each plane says its room. The flat has a floor and a ceiling per room, over that room; each wall
// faces the room it names; each furniture top stands in the room it names.
TEST(Rooms, EveryPlaneOfTheFlatSaysItsRoom) {
  const AnalysisResult& r = flat();
  ASSERT_TRUE(r.ok());
  const std::vector<synth::Rect> truth = synth::three_room_flat_rooms();
  const std::vector<int> truth_of_room = true_rooms(r);
  std::array<std::vector<int>, 2> horizontal_rooms;  // floors, ceilings
  std::size_t walls = 0, tops = 0;
  for (const Surface& s : extract_surfaces(r)) {
    ASSERT_NE(s.room, kNoRoom) << surface_kind_name(s.kind) << " at " << s.center.x << ", " << s.center.z;
    ASSERT_LT(std::size_t(s.room), r.rooms.size());
    const int t = truth_of_room[std::size_t(s.room)];
    const synth::Rect& rect = truth[std::size_t(t)];
    if (s.kind == SurfaceKind::Floor || s.kind == SurfaceKind::Ceiling) {
      horizontal_rooms[s.kind == SurfaceKind::Floor ? 0 : 1].push_back(s.room);
      const double area = polygon_area(s.polygon), want = double(rect.hi.x - rect.lo.x) * double(rect.hi.y - rect.lo.y);
      std::printf("[ figures  ] flat room %d: %s plane of %.1f m2 (%.1f m2 inside its walls)\n", t,
                  std::string(surface_kind_name(s.kind)).c_str(), area, want);
      EXPECT_NEAR(area, want, 0.15 * want) << surface_kind_name(s.kind) << " of room " << t;
      const glm::vec3 y_axis = s.y_axis();
      for (const glm::vec2& p : s.polygon) {
        const glm::vec3 w = s.center + s.x_axis * p.x + y_axis * p.y;
        EXPECT_TRUE(in_rect(rect, {w.x, w.z}, 0.2f)) << surface_kind_name(s.kind) << " of room " << t << " reaches "
                                                     << w.x << ", " << w.z;
      }
    } else if (s.kind == SurfaceKind::Wall) {
      ++walls;
      const glm::vec3 front = s.center + 0.15f * s.normal;
      EXPECT_EQ(true_room({front.x, front.z}, 0.1f), t) << "wall at " << s.center.x << ", " << s.center.z;
    } else {
      ++tops;
      EXPECT_TRUE(in_rect(rect, {s.center.x, s.center.z}, 0.0f)) << "top at " << s.center.x << ", " << s.center.z;
    }
  }
  for (std::vector<int>& rooms : horizontal_rooms) {
    std::sort(rooms.begin(), rooms.end());
    EXPECT_EQ(rooms, (std::vector<int>{0, 1, 2}));
  }
  EXPECT_GE(walls, 10u);
  EXPECT_GE(tops, 3u);
}

}  // namespace
}  // namespace roomsense

namespace roomsense {
namespace {

// Issue 15, ceilings that are not one level: a loft under a pitched roof, a soffit along a wall and a beam
// across the room. Against the generator's ground truth (synth::ceiling_at): the floor and the ceiling (the
// loft's ridge) within 0.05 m; ceiling areas lie on the ceiling's surface, the loft's on both slopes with their
// normals along the slope; wall areas end below the ceiling above them (not up in a soffit or through the
// roof); floor areas have the headroom free floor asks (1 m); the closed bounds keep the free space under the
// true ceiling and enclose the furniture, and hold the soffit and the beam solid.
TEST(Ceilings, PitchedSteppedAndBeamedCeilingsKeepAreasOnTheSurfacesAndTheBoundsAroundTheFreeSpace) {
  for (const synth::RoomSpec& spec : {synth::pitched_loft(), synth::soffit_room(), synth::beam_room()}) {
    SCOPED_TRACE(spec.name);
    const AnalysisResult r = analyze(synth::generate(spec));
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.storeys.size(), 1u);
    EXPECT_NEAR(r.floor_y, spec.floor_y, 0.05f);
    EXPECT_NEAR(r.ceiling_y, spec.ceiling_y, 0.05f);
    const auto truth_normal = [&](glm::vec2 p) {  // downwards, from the ceiling's slope around p
      constexpr float h = 0.05f;
      const float dx = (synth::ceiling_at(spec, p + glm::vec2(h, 0)) - synth::ceiling_at(spec, p - glm::vec2(h, 0))) / (2 * h);
      const float dz = (synth::ceiling_at(spec, p + glm::vec2(0, h)) - synth::ceiling_at(spec, p - glm::vec2(0, h))) / (2 * h);
      return glm::normalize(glm::vec3(dx, -1.0f, dz));
    };
    std::size_t ceilings = 0, rising_z = 0, falling_z = 0, walls = 0, floors = 0;
    for (const Area& a : r.areas) {
      if (a.type == AreaType::Ceiling) {
        ++ceilings;
        for (const glm::vec3& c : a.corners)
          EXPECT_NEAR(c.y, synth::ceiling_at(spec, {c.x, c.z}), 0.06f) << "ceiling area corner at " << c.x << ", " << c.z;
        EXPECT_GT(glm::dot(a.normal, truth_normal({a.center.x, a.center.z})), 0.99f) << "at " << a.center.x << ", " << a.center.z;
        rising_z += a.normal.z > 0.1f ? 1 : 0;
        falling_z += a.normal.z < -0.1f ? 1 : 0;
      }
      if (a.type == AreaType::Wall) {
        ++walls;
        for (const glm::vec3& c : {a.corners[2], a.corners[3]}) {  // the top edge, a little into the room
          const glm::vec2 p = glm::vec2(c.x, c.z) + 0.1f * glm::vec2(a.normal.x, a.normal.z);
          EXPECT_LE(c.y, synth::ceiling_at(spec, p) + 0.05f) << "wall area top at " << c.x << ", " << c.y << ", " << c.z;
        }
      }
      if (a.type == AreaType::Floor) {
        ++floors;
        for (const glm::vec3& c : a.corners)
          EXPECT_GE(synth::ceiling_at(spec, {c.x, c.z}) - spec.floor_y, 0.95f) << "floor area corner at " << c.x << ", " << c.z;
      }
    }
    EXPECT_GT(ceilings, 5u);
    EXPECT_GT(walls, 20u);
    EXPECT_GT(floors, 5u);
    if (spec.pitch) {
      EXPECT_GE(rising_z, 3u);
      EXPECT_GE(falling_z, 3u);
    }
    // Coverage, on a 5 cm raster clear of walls and furniture by 0.1 m: of the floor with at least 1.1 m of
    // headroom by floor areas, and of the ceiling with at least 1.1 m clear below it by ceiling areas (each
    // point of the true surface within a voxel of an area's plane and inside its rectangle).
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec2& v : spec.outline) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const auto covered_by = [&](AreaType type, const glm::vec3& p) {
      return std::any_of(r.areas.begin(), r.areas.end(), [&](const Area& a) {
        const glm::vec3 d = p - a.center;
        return a.type == type && std::fabs(glm::dot(d, a.normal)) <= 0.1f &&
               std::fabs(glm::dot(d, a.x_axis())) <= a.half_width && std::fabs(glm::dot(d, a.y_axis())) <= a.half_height;
      });
    };
    std::array<int, 2> surface{}, covered{};
    for (float z = lo.y + 0.025f; z < hi.y; z += 0.05f)
      for (float x = lo.x + 0.025f; x < hi.x; x += 0.05f) {
        const glm::vec2 p{x, z};
        if (!synth::inside_outline(spec, p) || synth::distance_to_walls(spec, p) <= 0.1f ||
            synth::distance_to_furniture(spec, p) <= 0.1f)
          continue;
        const float ceiling = synth::ceiling_at(spec, p);
        if (ceiling - spec.floor_y < 1.1f) continue;
        ++surface[0];
        covered[0] += covered_by(AreaType::Floor, {x, spec.floor_y, z}) ? 1 : 0;
        ++surface[1];
        covered[1] += covered_by(AreaType::Ceiling, {x, ceiling, z}) ? 1 : 0;
      }
    const double floor_share = double(covered[0]) / std::max(surface[0], 1), ceiling_share = double(covered[1]) / std::max(surface[1], 1);
    std::printf("[ figures  ] %s: floor areas cover %.1f %%, ceiling areas %.1f %% of the surface with 1.1 m clear\n",
                spec.name.c_str(), 100.0 * floor_share, 100.0 * ceiling_share);
    EXPECT_GE(floor_share, 0.8);
    EXPECT_GE(ceiling_share, 0.8);
    EXPECT_TRUE(check_closure(r.bounds).closed());
    std::vector<std::uint8_t> volume = bounds_volume(r.voxels.grid, bounds_storeys(r));
    const GridSpec& s = r.voxels.grid.spec;
    fill_edge_contacts(s, volume);
    const auto voxel_of = [&](glm::vec3 p) { return glm::ivec3(glm::floor((p - s.origin) / s.voxel_size)); };
    const glm::ivec3 seed = voxel_of({0.3f, 1.2f, 0.5f});
    ASSERT_EQ(volume[s.index(seed.x, seed.y, seed.z)], 0);
    const std::vector<std::uint8_t> reached = free_space_from(s, volume, seed);
    std::size_t free = 0, kept = 0;
    for (float y = spec.floor_y + 0.23f; y < spec.ceiling_y; y += 0.1f)
      for (float z = lo.y; z < hi.y; z += 0.1f)
        for (float x = lo.x; x < hi.x; x += 0.1f) {
          const glm::vec2 p{x + 0.033f, z + 0.027f};
          if (!synth::inside_outline(spec, p) || synth::distance_to_walls(spec, p) < 0.15f ||
              synth::distance_to_furniture(spec, p) < 0.15f)
            continue;
          if (const auto top = synth::furniture_top_at(spec, p); top && y < *top + 0.15f) continue;
          if (y > synth::ceiling_at(spec, p) - 0.2f) continue;
          ++free;
          const glm::ivec3 v = voxel_of({p.x, y, p.y});
          kept += s.contains(v.x, v.y, v.z) && reached[s.index(v.x, v.y, v.z)] ? 1 : 0;
        }
    const double share = double(kept) / double(std::max<std::size_t>(free, 1));
    std::printf("[ figures  ] %s: ceiling %.3f m (truth %.2f); %zu ceiling areas (%zu/%zu with normals toward +z/-z), "
                "%zu wall, %zu floor; bounds %zu triangles, keep %.2f %% of %zu free points under the ceiling\n",
                spec.name.c_str(), r.ceiling_y, spec.ceiling_y, ceilings, rising_z, falling_z, walls, floors,
                r.bounds.indices.size() / 3, 100.0 * share, free);
    EXPECT_GE(share, 0.99);
    // Furniture lies inside the bounds' solid: no free space at the middle of a top's surface.
    for (const synth::Box& b : spec.boxes) {
      const glm::ivec3 v = voxel_of({b.centre.x, spec.floor_y + 0.5f * b.height, b.centre.y});
      EXPECT_FALSE(s.contains(v.x, v.y, v.z) && reached[s.index(v.x, v.y, v.z)]) << "inside a box";
    }
    // The soffit and the beam are solid in the bounds: no free space inside them.
    for (const synth::Box& b : spec.hanging) {
      const glm::ivec3 v = voxel_of({b.centre.x, spec.ceiling_y - 0.5f * b.height, b.centre.y});
      EXPECT_FALSE(s.contains(v.x, v.y, v.z) && reached[s.index(v.x, v.y, v.z)]) << "inside the hanging box";
    }
  }
}

// The planes of a pitched loft and a soffit room (the spatial-entity API's): a ceiling plane per slope and one
// on the soffit's underside, each lying on the true ceiling with its normal along the slope; the gable walls'
// polygons end at the roof and the knee walls at the eaves; the polygons hold the generic checks (simple,
// counter-clockwise, the bounding rectangle centred).
TEST(Ceilings, PlanesFollowTheRoofAndTheSoffit) {
  for (const synth::RoomSpec& spec : {synth::pitched_loft(), synth::soffit_room()}) {
    SCOPED_TRACE(spec.name);
    const AnalysisResult r = analyze(synth::generate(spec));
    ASSERT_TRUE(r.ok());
    std::size_t tilted = 0, level = 0, lowered = 0, gable_vertices = 0;
    for (const Surface& s : extract_surfaces(r)) {
      glm::vec2 lo(INFINITY), hi(-INFINITY);
      for (const glm::vec2& p : s.polygon) lo = glm::min(lo, p), hi = glm::max(hi, p);
      EXPECT_NEAR(hi.x + lo.x, 0.0f, 1e-3f);
      EXPECT_NEAR(hi.y + lo.y, 0.0f, 1e-3f);
      EXPECT_NEAR(hi.x - lo.x, s.extents.x, 1e-3f);
      EXPECT_NEAR(hi.y - lo.y, s.extents.y, 1e-3f);
      ASSERT_EQ(s.triangles.size(), 3 * (s.polygon.size() - 2));
      const auto world = [&](glm::vec2 p) { return s.center + p.x * s.x_axis + p.y * s.y_axis(); };
      if (s.kind == SurfaceKind::Ceiling) {
        const bool flat = s.normal.y < -0.999f;
        tilted += flat ? 0 : 1;
        for (const glm::vec2& p : s.polygon) {
          const glm::vec3 w = world(p);
          // Vertices lie on the outline's raster, up to a voxel outside the tiles: compare half a voxel in.
          const glm::vec2 in = glm::vec2(w.x, w.z) + 0.05f * glm::normalize(glm::vec2(s.center.x - w.x, s.center.z - w.z));
          EXPECT_NEAR(w.y, synth::ceiling_at(spec, in), flat ? 0.06f : 0.1f) << "ceiling vertex at " << w.x << ", " << w.z;
        }
        if (flat && std::fabs(s.center.y - spec.ceiling_y) < 0.06f) ++level;
        if (flat && std::fabs(s.center.y - spec.ceiling_y) >= 0.06f) ++lowered;
      }
      if (s.kind == SurfaceKind::Wall && spec.pitch) {
        // The top edge: every vertex above the floor's half height lies on the roof over the wall.
        for (const glm::vec2& p : s.polygon) {
          const glm::vec3 w = world(p);
          if (w.y < spec.floor_y + 0.5f) continue;
          ++gable_vertices;
          const glm::vec2 in = glm::vec2(w.x, w.z) + 0.1f * glm::vec2(s.normal.x, s.normal.z);
          EXPECT_NEAR(w.y, synth::ceiling_at(spec, in), 0.15f) << "wall top at " << w.x << ", " << w.z;
        }
      }
    }
    std::printf("[ figures  ] %s planes: %zu sloped ceilings, %zu at the ceiling, %zu lower; %zu wall top vertices\n",
                spec.name.c_str(), tilted, level, lowered, gable_vertices);
    if (spec.pitch) {
      EXPECT_EQ(tilted, 2u);
      EXPECT_GE(gable_vertices, 10u);
    } else {
      EXPECT_EQ(level, 1u);
      EXPECT_EQ(lowered, 1u);
    }
  }
}

// The loft's generator (the ground truth of the next step): every vertex lies on or under the roof, the walls
// reach it, and the roof's own vertices follow it from the eaves to the ridge.
TEST(Ceilings, ThePitchedLoftIsMeshedUnderItsRoof) {
  synth::RoomSpec spec = synth::pitched_loft();
  spec.noise = 0.0f;
  const Scan scan = synth::generate(spec);
  float lowest_roof = INFINITY, highest_roof = -INFINITY;
  std::size_t on_roof = 0;
  for (const glm::vec3& v : scan.vertices) {
    const float roof = synth::ceiling_at(spec, {v.x, v.z});
    ASSERT_LE(v.y, roof + 1e-4f) << v.x << ", " << v.y << ", " << v.z;
    if (v.y > roof - 1e-4f && v.y > spec.floor_y + 0.5f) {
      ++on_roof;
      lowest_roof = std::min(lowest_roof, v.y);
      highest_roof = std::max(highest_roof, v.y);
    }
  }
  EXPECT_GT(on_roof, 1000u);
  EXPECT_NEAR(lowest_roof, spec.pitch->eave_y, 1e-3f);
  EXPECT_NEAR(highest_roof, spec.ceiling_y, 0.05f);
}

}  // namespace
}  // namespace roomsense
