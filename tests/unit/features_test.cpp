// Room features of §3.2 against the synthetic rooms' ground truth.
#include "roomsense/analysis.h"
#include "roomsense/features.h"
#include "roomsense/synthetic.h"
#include "synthetic_fixture.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>

namespace roomsense {
namespace {

using test::column_centre;

// The rooms whose walls are plain (the pentagon and rotated ones have walls off the axes).
std::vector<synth::RoomSpec> rooms() {
  return {synth::default_room(), synth::rotated_room(30.0f), synth::pentagon_room(), synth::large_triangle_room(),
          synth::hall_room()};
}

float voxel(const test::AnalysedRoom& r) { return r.result.voxels.grid.spec.voxel_size; }

// Furniture taller than 1.5 m within `reach` of p: such a cabinet reads as wall (thesis §3.2.2).
bool near_tall_furniture(const synth::RoomSpec& spec, glm::vec2 p, float reach) {
  for (float dz = -reach; dz <= reach; dz += reach / 3.0f)
    for (float dx = -reach; dx <= reach; dx += reach / 3.0f)
      if (const auto top = synth::furniture_top_at(spec, p + glm::vec2(dx, dz)); top && *top > 1.5f) return true;
  return false;
}

TEST(Walls, WallColumnsLieOnWallsOrTallFurniture) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const GridSpec& s = room.result.voxels.grid.spec;
    const RoomFeatures& f = *room.result.features;
    std::size_t walls = 0, near_wall = 0;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        if (!f.walls[s.column(x, z)]) continue;
        ++walls;
        const glm::vec2 p = column_centre(s, x, z);
        if (synth::distance_to_walls(spec, p) < 1.5f * voxel(room) || near_tall_furniture(spec, p, 1.5f * voxel(room)))
          ++near_wall;
      }
    EXPECT_GT(walls, 0u) << spec.name;
    EXPECT_EQ(near_wall, walls) << spec.name << ": wall columns away from every wall";
  }
}

TEST(Walls, MostOfEveryWallIsFound) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const GridSpec& s = room.result.voxels.grid.spec;
    const RoomFeatures& f = *room.result.features;
    // Sample each wall every 5 cm; a sample is found if a wall column lies within one voxel of it.
    std::size_t samples = 0, found = 0;
    for (std::size_t w = 0; w < spec.outline.size(); ++w) {
      const glm::vec2 a = spec.outline[w], b = spec.outline[(w + 1) % spec.outline.size()];
      const int n = int(glm::length(b - a) / 0.05f);
      for (int i = 1; i < n; ++i) {
        const glm::vec2 p = a + (b - a) * (float(i) / float(n));
        ++samples;
        bool hit = false;
        const int cx = int((p.x - s.origin.x) / s.voxel_size), cz = int((p.y - s.origin.z) / s.voxel_size);
        for (int dz = -1; dz <= 1 && !hit; ++dz)
          for (int dx = -1; dx <= 1 && !hit; ++dx) {
            const int x = cx + dx, z = cz + dz;
            hit = x >= 0 && z >= 0 && x < s.nx && z < s.nz && f.walls[s.column(x, z)];
          }
        found += hit ? 1 : 0;
      }
    }
    EXPECT_GT(double(found), 0.9 * double(samples)) << spec.name;
  }
}

TEST(Room, TheInsideIsRoomAndFarOutsideIsNot) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const GridSpec& s = room.result.voxels.grid.spec;
    const RoomFeatures& f = *room.result.features;
    std::size_t inside = 0, inside_room = 0;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const glm::vec2 p = column_centre(s, x, z);
        const bool in = synth::inside_outline(spec, p);
        if (in) {
          ++inside;
          inside_room += f.room[s.column(x, z)];
        } else if (synth::distance_to_walls(spec, p) > 2.0f * s.voxel_size) {
          EXPECT_EQ(f.room[s.column(x, z)], 0) << spec.name;
        }
      }
    EXPECT_EQ(inside_room, inside) << spec.name;
  }
}

TEST(Furniture, TopsAreFoundAtTheirHeightAndNowhereElse) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const GridSpec& s = room.result.voxels.grid.spec;
    const RoomFeatures& f = *room.result.features;
    const float margin = 1.5f * s.voxel_size;
    std::size_t on_top = 0, found = 0;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const glm::vec2 p = column_centre(s, x, z);
        const int c = f.furniture[s.column(x, z)];
        const bool clear_of_furniture = synth::distance_to_furniture(spec, p) > margin;
        if (clear_of_furniture && synth::distance_to_walls(spec, p) > margin && synth::inside_outline(spec, p)) {
          EXPECT_EQ(c, kNoFurniture) << spec.name << " furniture where there is none";
        }
        const auto top = synth::furniture_top_at(spec, p);
        if (!top || *top > 1.5f || synth::distance_to_walls(spec, p) < margin) continue;
        // Inside a footprint, away from its edges: C is the level just above the top (Eq. 3.13).
        bool deep = true;
        for (glm::vec2 d : {glm::vec2(margin, 0), glm::vec2(-margin, 0), glm::vec2(0, margin), glm::vec2(0, -margin)})
          deep = deep && synth::furniture_top_at(spec, p + d).has_value();
        if (!deep) continue;
        ++on_top;
        if (c == kNoFurniture) continue;
        ++found;
        const float surface = s.origin.y + float(c) * s.voxel_size;  // bottom of the level above the top
        EXPECT_NEAR(surface, spec.floor_y + *top, 1.5f * s.voxel_size) << spec.name;
      }
    if (!spec.tables.empty()) {
      EXPECT_GT(on_top, 0u) << spec.name;
      EXPECT_GT(double(found), 0.95 * double(on_top)) << spec.name;
    }
  }
}

TEST(FreeTiles, FreeFloorIsClearAndCoversTheOpenFloor) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const GridSpec& s = room.result.voxels.grid.spec;
    const RoomFeatures& f = *room.result.features;
    std::size_t open = 0, open_found = 0;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const glm::vec2 p = column_centre(s, x, z);
        const bool d = f.free_floor[s.column(x, z)] != 0;
        if (d) {
          // Inside, or on a wall's voxel line where a slanted wall fills too little of a column.
          EXPECT_TRUE(synth::inside_outline(spec, p) || synth::distance_to_walls(spec, p) < s.voxel_size)
              << spec.name << ": free floor outside the room";
          // Not deep inside the footprint of furniture up to 1.5 m tall. (A taller, hollow cabinet's inside
          // counts as free under Eq. 3.14, as it would in a real scan; no area fits there.)
          const auto top = synth::furniture_top_at(spec, p);
          bool deep = top.has_value() && *top <= 1.5f;
          for (glm::vec2 dd : {glm::vec2(0.15f, 0), glm::vec2(-0.15f, 0), glm::vec2(0, 0.15f), glm::vec2(0, -0.15f)})
            deep = deep && synth::furniture_top_at(spec, p + dd).has_value();
          EXPECT_FALSE(deep)
              << spec.name << ": free floor under furniture";
        }
        if (synth::inside_outline(spec, p) && synth::distance_to_walls(spec, p) > 0.2f &&
            synth::distance_to_furniture(spec, p) > 0.2f) {
          ++open;
          open_found += d ? 1 : 0;
        }
      }
    EXPECT_GT(double(open_found), 0.95 * double(open)) << spec.name;
  }
}

TEST(FreeTiles, FreeCeilingAvoidsTallFurniture) {
  const test::AnalysedRoom& room = test::analysed(synth::default_room());
  const GridSpec& s = room.result.voxels.grid.spec;
  const RoomFeatures& f = *room.result.features;
  std::size_t open = 0, found = 0;
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const glm::vec2 p = column_centre(s, x, z);
      const auto top = synth::furniture_top_at(room.spec, p);
      if (top && *top > 1.6f) {
        EXPECT_EQ(f.free_ceiling[s.column(x, z)], 0);  // the 2 m cabinet
      }
      if (synth::inside_outline(room.spec, p) && synth::distance_to_walls(room.spec, p) > 0.2f &&
          synth::distance_to_furniture(room.spec, p) > 0.2f) {
        ++open;
        found += f.free_ceiling[s.column(x, z)];
      }
    }
  EXPECT_GT(double(found), 0.95 * double(open));
}

TEST(WallNormals, PointIntoTheRoom) {
  for (const synth::RoomSpec& spec : rooms()) {
    const test::AnalysedRoom& room = test::analysed(spec);
    const GridSpec& s = room.result.voxels.grid.spec;
    const RoomFeatures& f = *room.result.features;
    std::size_t marked = 0;
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x)
        for (int y = f.levels.floor; y <= f.levels.ceiling; ++y) {
          const std::uint8_t n = f.normals[s.index(x, y, z)];
          if (n == 0) continue;
          ++marked;
          const glm::vec2 p = column_centre(s, x, z);
          EXPECT_TRUE(synth::inside_outline(spec, p) || synth::distance_to_walls(spec, p) < s.voxel_size) << spec.name;
          // The normal points away from the wall it was found on: one voxel against it lies a wall column.
          for (auto [bit, dx, dz] : {std::tuple{kNormalLeft, 1, 0}, std::tuple{kNormalRight, -1, 0},
                                     std::tuple{kNormalForward, 0, -1}, std::tuple{kNormalBackward, 0, 1}})
            if (n & bit) { EXPECT_EQ(f.walls[s.column(x + dx, z + dz)], 1) << spec.name; }
        }
    EXPECT_GT(marked, 100u) << spec.name;
  }
}

// Alg. 1 as the thesis writes it, level by level and step by step: the reference the detector's bit-parallel
// runs must equal.
std::vector<std::uint8_t> wall_normals_by_levels(const VoxelGrid& grid, const FloorCeiling& levels,
                                                 const std::vector<int>& ceiling, int reach,
                                                 const std::vector<std::uint8_t>& walls,
                                                 const std::vector<std::uint8_t>& room, const std::vector<int>& furniture) {
  const GridSpec& s = grid.spec;
  std::vector<std::uint8_t> normals(s.voxel_count(), 0);
  const auto free_at = [&](int x, int y, int z) {
    if (!s.contains(x, 0, z)) return false;
    const std::size_t col = s.column(x, z);
    return !walls[col] && !grid.at(x, y, z) && room[col] && furniture[col] < y &&
           (ceiling[col] >= levels.ceiling || y < ceiling[col]);
  };
  const auto ends_room = [&](int x, int z) { return !s.contains(x, 0, z) || walls[s.column(x, z)] || !room[s.column(x, z)]; };
  const auto clear_run = [&](int x, int y, int z, int dx, int dz) {
    for (int i = 1; i <= reach; ++i)
      if (!free_at(x + i * dx, y, z + i * dz)) return 2 * (i - 1) >= reach && ends_room(x + i * dx, z + i * dz);
    return true;
  };
  for (int z = 0; z < s.nz; ++z)
    for (int x = 0; x < s.nx; ++x) {
      if (!walls[s.column(x, z)]) continue;
      for (auto [dx, dz, bit] : {std::tuple{-1, 0, kNormalLeft}, std::tuple{1, 0, kNormalRight},
                                 std::tuple{0, -1, kNormalBackward}, std::tuple{0, 1, kNormalForward}})
        for (int y = levels.floor; y <= levels.ceiling; ++y)
          if (s.contains(x + dx, 0, z + dz) && clear_run(x, y, z, dx, dz)) normals[s.index(x + dx, y, z + dz)] |= bit;
    }
  return normals;
}

TEST(WallNormals, EqualAlgorithmOneLevelByLevel) {
  // Random walls, room, voxels, furniture tops and column ceilings, with level spans under, at and over 64 (the
  // detector's word) and reaches from none to past the grid.
  std::mt19937 random(19);
  std::size_t marked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    GridSpec s;
    s.nx = 6 + int(random() % 30), s.ny = 8 + int(random() % 150), s.nz = 6 + int(random() % 30);
    s.voxel_size = 0.05f;
    VoxelGrid grid(s);
    for (std::uint8_t& c : grid.cells) c = random() % 9 == 0;
    FloorCeiling levels;
    levels.floor = int(random() % 4);
    levels.ceiling = trial % 3 == 0 ? levels.floor + 63 + int(random() % 3) : levels.floor + int(random() % std::uint32_t(s.ny - levels.floor));
    levels.ceiling = std::min(levels.ceiling, s.ny - 1);
    std::vector<std::uint8_t> walls(s.column_count()), room(s.column_count());
    std::vector<int> ceiling(s.column_count()), furniture(s.column_count());
    for (std::size_t c = 0; c < walls.size(); ++c) {
      walls[c] = random() % 4 == 0;
      room[c] = random() % 8 != 0;
      ceiling[c] = random() % 3 == 0 ? levels.floor + int(random() % std::uint32_t(s.ny)) : levels.ceiling;
      furniture[c] = random() % 3 == 0 ? levels.floor + int(random() % std::uint32_t(levels.ceiling - levels.floor + 1)) : kNoFurniture;
    }
    const int reach = trial % 10 == 0 ? 0 : 1 + int(random() % 40);
    const std::vector<std::uint8_t> expected = wall_normals_by_levels(grid, levels, ceiling, reach, walls, room, furniture);
    ASSERT_EQ(detect_wall_normals(grid, levels, ceiling, reach, walls, room, furniture), expected)
        << "trial " << trial << ", " << s.nx << " x " << s.ny << " x " << s.nz << ", levels " << levels.floor << ".."
        << levels.ceiling << ", reach " << reach;
    marked += std::size_t(std::count_if(expected.begin(), expected.end(), [](std::uint8_t n) { return n != 0; }));
  }
  EXPECT_GT(marked, 1000u);  // the runs do end clear, both ways
}

TEST(WallOpenings, DoorsAreGapsOfAtMostTheOpeningBetweenWallColumnsOpenDownToTheFloor) {
  // Random wall columns, room and voxels: a voxel before a non-wall column is blocked as a door exactly where,
  // walking from that column along the wall's face both ways, wall columns lie within the opening's width and
  // the column is empty in the room's lower half (the definition, by walking, against the detector's scans).
  std::mt19937 rng(3);
  const GridSpec spec = make_grid_spec({0, 0, 0}, {2.4f, 2.0f, 1.9f}, 0.1f);
  const FloorCeiling levels{1, 18, 1, 18};
  const int max_opening = 6, y_from = levels.floor + 1, y_to = levels.ceiling - 1;
  const int low_top = std::min(y_to, levels.floor + (levels.ceiling - levels.floor) / 2);
  for (int trial = 0; trial < 30; ++trial) {
    std::bernoulli_distribution wall_at(0.1 + 0.02 * trial), filled(0.02);
    VoxelGrid grid(spec);
    std::vector<std::uint8_t> walls(spec.column_count()), room(spec.column_count(), 1);
    for (std::size_t c = 0; c < walls.size(); ++c) walls[c] = wall_at(rng) ? 1 : 0;
    for (std::uint8_t& v : grid.cells) v = filled(rng) ? 1 : 0;
    const std::vector<std::uint8_t> blocked = detect_wall_openings(grid, levels, walls, room, 0, max_opening, {});
    const auto is_wall = [&](int x, int z) { return spec.contains(x, 0, z) && walls[spec.column(x, z)] != 0; };
    const auto door = [&](int x, int z, int ax, int az) {
      if (!spec.contains(x, 0, z) || is_wall(x, z)) return false;
      for (int y = y_from; y <= low_top; ++y)
        if (grid.at(x, y, z)) return false;
      int a = 1, b = 1;
      while (spec.contains(x - a * ax, 0, z - a * az) && !is_wall(x - a * ax, z - a * az)) ++a;
      while (spec.contains(x + b * ax, 0, z + b * az) && !is_wall(x + b * ax, z + b * az)) ++b;
      return is_wall(x - a * ax, z - a * az) && is_wall(x + b * ax, z + b * az) && a + b - 1 <= max_opening;
    };
    int doors = 0;
    for (int z = 0; z < spec.nz; ++z)
      for (int x = 0; x < spec.nx; ++x) {
        if (is_wall(x, z)) continue;
        bool want = false;  // behind (x, z) along a step d, with the face along (d.z, d.x); no wall behind
        for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)})
          want = want || (!is_wall(x - d.x, z - d.y) && door(x - d.x, z - d.y, d.y, d.x));
        // Where a wall lies behind, the wall's own test decides: only columns with no wall beside them here.
        bool wall_beside = false;
        for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)})
          wall_beside = wall_beside || is_wall(x - d.x, z - d.y);
        if (wall_beside) continue;
        doors += want ? 1 : 0;
        const bool got = !blocked.empty() && blocked[spec.index(x, y_from, z)] != 0;
        ASSERT_EQ(got, want) << "trial " << trial << " column " << x << ", " << z;
      }
    if (trial == 0) {
      EXPECT_GT(doors, 0);
    }
  }
}

TEST(WallOpenings, LevelsOfNoHeightFindNoDoorAndReadNothingOutsideTheGrid) {
  // detect_wall_openings is public: levels with the ceiling at or below the floor, or past the grid, are input
  // it must survive (ASan checks the reads), finding no door where the room has no height.
  const GridSpec spec = make_grid_spec({0, 0, 0}, {1.0f, 0.5f, 1.0f}, 0.1f);
  VoxelGrid grid(spec);
  std::vector<std::uint8_t> walls(spec.column_count(), 0), room(spec.column_count(), 0);
  for (int z = 0; z < spec.nz; ++z) walls[spec.column(0, z)] = walls[spec.column(4, z)] = 1;
  for (const FloorCeiling levels : {FloorCeiling{3, 3, 3, 3}, FloorCeiling{4, 1, 4, 1}, FloorCeiling{spec.ny + 5, spec.ny + 9, spec.ny + 5, spec.ny + 9}}) {
    const std::vector<std::uint8_t> blocked = detect_wall_openings(grid, levels, walls, room, 0, 6, {});
    EXPECT_TRUE(blocked.empty() || std::count(blocked.begin(), blocked.end(), 1) == 0);
  }
}

TEST(WallNormals, NoneFaceAWindowOpening) {
  // Wall columns need > 50 % of the height: the default room's window (1.2 m of 2.6 m) leaves its columns
  // short of that, so no wall, and no normal, stands in the opening.
  const test::AnalysedRoom& room = test::analysed(synth::default_room());
  const GridSpec& s = room.result.voxels.grid.spec;
  const RoomFeatures& f = *room.result.features;
  const synth::Window& w = room.spec.windows.front();
  const glm::vec2 a = room.spec.outline[std::size_t(w.wall)], b = room.spec.outline[std::size_t(w.wall) + 1];
  const glm::vec2 dir = glm::normalize(b - a);
  for (float u = w.u0 + 0.25f; u < w.u1 - 0.25f; u += 0.05f) {  // clear of the jambs
    const glm::vec2 p = a + dir * u;
    const int x = int((p.x - s.origin.x) / s.voxel_size), z = int((p.y - s.origin.z) / s.voxel_size);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dx = -1; dx <= 1; ++dx)
        if (x + dx >= 0 && z + dz >= 0 && x + dx < s.nx && z + dz < s.nz) {
          EXPECT_EQ(f.walls[s.column(x + dx, z + dz)], 0) << "wall column in the window at u = " << u;
        }
  }
}

TEST(Levels, PointCloudFloorAndCeilingAtTheirSurfaces) {
  // Vertex mode (the thesis's input) has no normals: the wall points in the floor and ceiling bands must not
  // pull the measured heights off the surfaces.
  synth::RoomSpec spec = synth::default_room();
  spec.floor_y = -1.3f;
  spec.ceiling_y = 1.3f;
  Scan cloud = synth::generate(spec);
  cloud.indices.clear();
  const AnalysisResult r = analyze(cloud);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.floor_y, spec.floor_y, 0.02f);
  EXPECT_NEAR(r.ceiling_y, spec.ceiling_y, 0.02f);
}

// A 10 x 6 room (columns) whose right end (x >= 7) is an alcove beyond a wall the runtime labels at x = 6, from
// the floor to the ceiling; the scan's walls run round the whole grid's edge.
struct LabelledAlcove {
  GridSpec spec{glm::vec3(0.0f), 0.1f, 10, 30, 6};
  FloorCeiling levels{};
  std::vector<std::uint8_t> room = std::vector<std::uint8_t>(spec.column_count(), 1);
  std::vector<std::uint8_t> enclosed = std::vector<std::uint8_t>(spec.column_count(), 1);
  LabelGrid labels;
  LabelledAlcove() {
    levels.floor = 1;
    levels.ceiling = 28;
    labels.masks.assign(spec.voxel_count(), 0);
  }
  void label_column(int x, int z, int y_from, int y_to) {
    for (int y = y_from; y <= y_to; ++y) labels.masks[spec.index(x, y, z)] = label_bit(SurfaceLabel::Wall);
    labels.present = label_bit(SurfaceLabel::Wall);
  }
};

TEST(LabelledWalls, CloseOffAnAlcoveBeyondThem) {
  LabelledAlcove a;
  for (int z = 0; z < a.spec.nz; ++z) a.label_column(6, z, 2, 27);
  // The grid's edge columns are the scan's walls: not enclosed.
  for (int z = 0; z < a.spec.nz; ++z)
    for (int x = 0; x < a.spec.nx; ++x)
      if (x == 0 || z == 0 || x == a.spec.nx - 1 || z == a.spec.nz - 1) a.enclosed[a.spec.column(x, z)] = 0;
  const int y_end = a.levels.floor + 15;
  cut_at_labelled_walls(a.spec, a.levels, y_end, a.labels, a.room, a.enclosed);
  EXPECT_EQ(a.enclosed[a.spec.column(3, 3)], 1);  // the room
  EXPECT_EQ(a.enclosed[a.spec.column(6, 3)], 1);  // the labelled wall itself
  EXPECT_EQ(a.enclosed[a.spec.column(8, 3)], 0);  // the alcove beyond it
}

TEST(LabelledWalls, FurnitureSidesAndOpenLabelsCloseNothing) {
  for (const bool low_only : {true, false}) {
    LabelledAlcove a;
    // low_only: a couch's sides labelled wall, up to 0.5 m, round columns 2..4; else a wall label that leaves
    // the grid's edge open, so that no closed part holds half the room.
    if (low_only) {
      for (int x = 2; x <= 4; ++x) a.label_column(x, 2, 2, 6), a.label_column(x, 4, 2, 6);
      a.label_column(2, 3, 2, 6), a.label_column(4, 3, 2, 6);
    } else {
      for (int z = 0; z < a.spec.nz; ++z) a.label_column(8, z, 2, 27);
    }
    const std::vector<std::uint8_t> before = a.enclosed;
    cut_at_labelled_walls(a.spec, a.levels, a.levels.floor + 15, a.labels, a.room, a.enclosed);
    EXPECT_EQ(a.enclosed, before) << (low_only ? "couch" : "open");
  }
}

// Ceilings per column (issue 15) on hand-made grids: a room of 20 x 20 columns, floor at level 0, ceiling at
// level 20, walls round it.
struct BoxRoom {
  VoxelGrid grid;
  FloorCeiling levels{0, 20, 0, 20};
  std::vector<std::uint8_t> room;
  explicit BoxRoom(int ny = 21) : grid(GridSpec{glm::vec3(0.0f), 0.1f, 20, ny, 20}), room(grid.spec.column_count(), 1) {
    for (int z = 0; z < 20; ++z)
      for (int x = 0; x < 20; ++x) {
        grid.set(x, 0, z);
        grid.set(x, 20, z);
        if (x == 0 || z == 0 || x == 19 || z == 19)
          for (int y = 0; y <= 20; ++y) grid.set(x, y, z);
      }
  }
  // The shell of a box of voxels [x0, x1] x [y0, y1] x [z0, z1], hollow inside.
  void box(int x0, int x1, int y0, int y1, int z0, int z1) {
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
          if (x == x0 || x == x1 || y == y0 || y == y1 || z == z0 || z == z1) grid.set(x, y, z);
  }
  int at(const std::vector<int>& c, int x, int z) const { return c[grid.spec.column(x, z)]; }
};

TEST(Ceilings, AColumnsCeilingIsTheFirstSurfaceAboveTheFreeSpace) {
  BoxRoom r;
  r.box(3, 8, 0, 6, 3, 8);      // a hollow chest on the floor, its inside shut in
  r.box(1, 18, 15, 20, 1, 4);   // a soffit along one wall, hollow, from level 15 up to the ceiling
  r.box(10, 14, 8, 8, 10, 14);  // a shelf board in the air at level 8
  const std::vector<int> c = column_ceilings(r.grid, r.levels, r.room, r.levels.ceiling);
  EXPECT_EQ(r.at(c, 5, 5), 20) << "over the chest: the flood passes above it";
  EXPECT_EQ(r.at(c, 12, 12), 20) << "over the shelf board";
  EXPECT_EQ(r.at(c, 10, 2), 15) << "under the soffit: its underside";
  EXPECT_EQ(r.at(c, 10, 10), 20);
  EXPECT_EQ(r.at(c, 0, 10), 20) << "a wall column takes its neighbours'";
  // Nothing lies above I_Ceiling here: the storey is not raised.
  EXPECT_FALSE(raised_ceiling(r.grid, r.levels, r.room, r.grid.spec.ny).has_value());
  // A room filled by one hollow chest: the floor's flood is shut inside it, which is no ceiling at its lid.
  BoxRoom crammed;
  crammed.box(1, 18, 0, 6, 1, 18);
  const std::vector<int> shut = column_ceilings(crammed.grid, crammed.levels, crammed.room, crammed.levels.ceiling);
  EXPECT_EQ(crammed.at(shut, 10, 10), 20);
}

TEST(Ceilings, AStoreyIsRaisedToAHigherCeilingButNotThroughAHole) {
  // Half the room (z >= 10) rises to level 30: I_Ceiling at 20 is part way up; the storey reaches 30.
  BoxRoom high(32);
  for (int z = 10; z < 20; ++z)
    for (int x = 0; x < 20; ++x) {
      high.grid.cells[high.grid.spec.index(x, 20, z)] = x == 0 || x == 19 || z == 19 ? 1 : 0;
      for (int y = 20; y <= 30; ++y)
        if (x == 0 || x == 19 || z == 19 || z == 10) high.grid.set(x, y, z);
      high.grid.set(x, 30, z);
    }
  for (int x = 1; x < 19; ++x)
    for (int y = 20; y <= 30; ++y) high.grid.cells[high.grid.spec.index(x, y, 10)] = y >= 21 ? 1 : 0;  // the step's face
  const auto raised = raised_ceiling(high.grid, high.levels, high.room, high.grid.spec.ny);
  ASSERT_TRUE(raised.has_value());
  EXPECT_EQ(raised->ceiling, 30);
  const std::vector<int> c = column_ceilings(high.grid, *raised, high.room, raised->ceiling);
  EXPECT_EQ(high.at(c, 10, 5), 20);
  EXPECT_EQ(high.at(c, 10, 15), 30);
  // A flat ceiling with a hole and empty levels above it: the flood leaks through the hole to the grid's top
  // everywhere, which is no higher ceiling.
  BoxRoom holed(32);
  holed.grid.cells[holed.grid.spec.index(10, 20, 10)] = 0;
  EXPECT_FALSE(raised_ceiling(holed.grid, holed.levels, holed.room, holed.grid.spec.ny).has_value());
}

}  // namespace
}  // namespace roomsense
