// What an IncrementalAnalysis's SearchCache (core/src/areas/search_cache.h, internal) takes from the previous
// analysis besides the searches: the reach lists' areas in metres, growth replayed area by area (grow.h), and
// each area's reach (classify.h's ReachMemo).
// Each must be taken only where nothing it read changed; the chunk-by-chunk replay tests check whole rooms, these
// the edges of each rule on purpose-made features.
#include "../../core/src/areas/grow.h"
#include "../../core/src/key_table.h"
#include "../../core/src/areas/search_cache.h"
#include "../../core/src/areas/search.h"
#include "roomsense/analysis.h"
#include "roomsense/synthetic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <random>
#include <tuple>
#include <vector>

namespace {

using namespace roomsense;
using namespace roomsense::detail;

GridSpec grid(int nx = 48, int ny = 8, int nz = 48) {
  GridSpec s;
  s.nx = nx, s.ny = ny, s.nz = nz;
  s.voxel_size = 0.1f;
  return s;
}

// The same rectangles in the same order: a replayed search's list against a search from nothing.
::testing::AssertionResult same_items(const Candidates& got, const Candidates& want) {
  if (got.size() != want.size()) return ::testing::AssertionFailure() << got.size() << " rectangles, not " << want.size();
  for (std::size_t i = 0; i < want.size(); ++i)
    if (!(got.item(i) == want.item(i))) return ::testing::AssertionFailure() << "rectangle " << i << " differs";
  return ::testing::AssertionSuccess();
}

RoomFeatures empty_features(const GridSpec& s) {
  RoomFeatures f;
  f.levels.floor = 1, f.levels.ceiling = 6;
  f.walls.assign(s.column_count(), 0);
  f.normals.assign(s.voxel_count(), 0);
  f.free_floor.assign(s.column_count(), 1);
  return f;
}

Sized wall_at(int x, int z) { return {PackedCandidate(glm::ivec3(x, 4, z), 4, 0, 2), AreaSize::Large}; }
Sized floor_at(int x, int z) { return {PackedCandidate(glm::ivec3(x, 1, z), 4, 0, PackedCandidate::kSquare), AreaSize::Large}; }

TEST(FirstIndex, KeepsEachValuesFirstIndexWhereHashesCollide) {
  // Values 0..9 with 3 hashes among them: unequal values of one hash each keep their own index, equal ones the
  // first's.
  const std::vector<int> values = {5, 7, 5, 9, 7, 11, 5, 13, 9, 15};
  const auto hash = [](int v) { return std::uint64_t(v % 3) << 40; };
  FirstIndex first;
  std::vector<std::uint32_t> got;
  for (std::uint32_t i = 0; i < values.size(); ++i)
    got.push_back(first.insert(hash(values[i]), i, [&](std::uint32_t j) { return values[j] == values[i]; }));
  EXPECT_EQ(got, (std::vector<std::uint32_t>{0, 1, 0, 3, 1, 5, 0, 7, 3, 9}));
  for (const int v : {5, 7, 9, 11, 13, 15})
    EXPECT_EQ(values[first.find(hash(v), [&](std::uint32_t j) { return values[j] == v; })], v);
  EXPECT_EQ(first.find(hash(8), [&](std::uint32_t j) { return values[j] == 8; }), FirstIndex::kAbsent);
}

// A place that tells which call made it: its centre's x is `mark`, its half width the rectangle's corner x.
template <class Reach>
struct Marked {
  float mark = 0.0f;
  std::size_t calls = 0;
  Reach operator()(const Sized& s) {
    ++calls;
    Area a;
    a.center = glm::vec3(mark, 0.0f, 0.0f);
    a.half_width = float(s.c().corners[0].x);
    return Reach(a);
  }
};

TEST(SearchCache, AWallsReachPlaceIsKeptOnlyFarFromChangedWallFeatures) {
  const GridSpec s = grid();
  SearchCache cache;
  RoomFeatures features = empty_features(s);
  const std::vector<Sized> walls = {wall_at(4, 4), wall_at(30, 30), wall_at(40, 10)};
  cache.begin(s, features);
  Marked<ReachWall> first{1.0f};
  EXPECT_EQ(cache.reach_walls(walls, std::ref(first)).size(), 3u);
  EXPECT_EQ(first.calls, 3u);  // nothing known before

  // A wall normal changes next to the second wall: its place is made again, the others kept.
  features.normals[s.index(31, 4, 31)] = kNormalForward;
  cache.begin(s, features);
  Marked<ReachWall> second{2.0f};
  const std::vector<ReachWall> placed = cache.reach_walls(walls, std::ref(second));
  ASSERT_EQ(placed.size(), 3u);
  EXPECT_EQ(second.calls, 1u);
  EXPECT_EQ(placed[0].center.x, 1.0f);
  EXPECT_EQ(placed[1].center.x, 2.0f);
  EXPECT_EQ(placed[2].center.x, 1.0f);

  // Nothing changed: every place kept, in the list's order, the first analysis's where the second kept them.
  cache.begin(s, features);
  Marked<ReachWall> third{3.0f};
  const std::vector<ReachWall> again = cache.reach_walls({walls[2], walls[0], walls[1]}, std::ref(third));
  EXPECT_EQ(third.calls, 0u);
  EXPECT_EQ(again[0].center.x, 1.0f);
  EXPECT_EQ(again[0].half_width, 40.0f);
  EXPECT_EQ(again[2].center.x, 2.0f);
}

TEST(SearchCache, AFloorsReachPlaceIsKeptWhileTheGridIs) {
  const GridSpec s = grid();
  SearchCache cache;
  RoomFeatures features = empty_features(s);
  cache.begin(s, features);
  Marked<ReachFloor> first{1.0f};
  cache.reach_floors({floor_at(2, 2), floor_at(10, 2), floor_at(20, 2), floor_at(30, 2)}, std::ref(first));
  EXPECT_EQ(first.calls, 4u);

  // The free floor changes under every rectangle, one is gone and one new: only the new one is placed (a floor's
  // place reads its rectangle alone).
  std::fill(features.free_floor.begin(), features.free_floor.end(), std::uint8_t{0});
  cache.begin(s, features);
  Marked<ReachFloor> second{2.0f};
  const std::vector<ReachFloor> placed =
      cache.reach_floors({floor_at(2, 2), floor_at(12, 6), floor_at(20, 2), floor_at(30, 2)}, std::ref(second));
  EXPECT_EQ(second.calls, 1u);
  EXPECT_EQ(placed[0].center.x, 1.0f);
  EXPECT_EQ(placed[1].center.x, 2.0f);
  EXPECT_EQ(placed[1].half_width, 12.0f);
  EXPECT_EQ(placed[3].center.x, 1.0f);

  // Another grid: every place made again.
  GridSpec moved = s;
  moved.origin.x += 0.05f;
  cache.begin(moved, empty_features(moved));
  Marked<ReachFloor> third{3.0f};
  cache.reach_floors({floor_at(2, 2), floor_at(20, 2)}, std::ref(third));
  EXPECT_EQ(third.calls, 2u);
}

TEST(SearchCache, AReachListAsItWasIsTheCachesOwnAndCanChangeAgain) {
  const GridSpec s = grid();
  SearchCache cache;
  RoomFeatures features = empty_features(s);
  const std::vector<Sized> walls = {wall_at(4, 4), wall_at(30, 30)};
  cache.begin(s, features);
  Marked<ReachWall> first{1.0f};
  const std::vector<ReachWall>* before = &cache.reach_walls(walls, std::ref(first));

  // Nothing changed, the same list: the list kept, neither placed nor copied again.
  cache.begin(s, features);
  Marked<ReachWall> second{2.0f};
  const std::vector<ReachWall>& same = cache.reach_walls(walls, std::ref(second));
  EXPECT_EQ(&same, before);
  EXPECT_EQ(second.calls, 0u);
  ASSERT_EQ(same.size(), 2u);
  EXPECT_EQ(same[1].center.x, 1.0f);

  // The next analysis after that one still knows the list: a wall added is the only one placed.
  cache.begin(s, features);
  Marked<ReachWall> third{3.0f};
  const std::vector<ReachWall> grown = cache.reach_walls({walls[0], walls[1], wall_at(40, 10)}, std::ref(third));
  EXPECT_EQ(third.calls, 1u);
  ASSERT_EQ(grown.size(), 3u);
  EXPECT_EQ(grown[0].center.x, 1.0f);
  EXPECT_EQ(grown[2].center.x, 3.0f);

  // A wall normal changes next to the first wall: that wall is placed again though the list is the same.
  features.normals[s.index(5, 4, 4)] = kNormalForward;
  cache.begin(s, features);
  Marked<ReachWall> fourth{4.0f};
  const std::vector<ReachWall> near = cache.reach_walls({walls[0], walls[1], wall_at(40, 10)}, std::ref(fourth));
  EXPECT_EQ(fourth.calls, 1u);
  EXPECT_EQ(near[0].center.x, 4.0f);
  EXPECT_EQ(near[1].center.x, 1.0f);
}

// Floor squares on a free-floor mask (a column's cell Usable where its mask is set, Forbidden off the grid).
GrowthRule rule_over(const GridSpec& s, const std::vector<std::uint8_t>& free, std::size_t* reads) {
  GrowthRule rule;
  rule.step = 0.5f * s.voxel_size;
  rule.max_length = 10.0f;
  rule.fill = 0.95f;
  rule.strip_fill = 0.8f;
  rule.cell_at = [&s, &free, reads](const glm::vec3& p, const Area&) {
    ++*reads;
    const int x = int(std::floor((p.x - s.origin.x) / s.voxel_size)), z = int(std::floor((p.z - s.origin.z) / s.voxel_size));
    if (x < 0 || z < 0 || x >= s.nx || z >= s.nz) return SurfaceCell::Forbidden;
    return free[s.column(x, z)] ? SurfaceCell::Usable : SurfaceCell::Unusable;
  };
  return rule;
}

Area floor_square(const GridSpec& s, float x, float z, float side) {
  Area a;
  a.type = AreaType::Floor;
  a.size = AreaSize::Small;
  a.normal = glm::vec3(0, 1, 0);
  const float y = s.origin.y;
  // Corner 0 to 1 along -x, so that the second axis (normal x first edge) runs along +z.
  a.corners = {glm::vec3(x + side, y, z), glm::vec3(x, y, z), glm::vec3(x, y, z + side), glm::vec3(x + side, y, z + side)};
  a.center = glm::vec3(x + 0.5f * side, y, z + 0.5f * side);
  a.half_width = a.half_height = 0.5f * side;
  return a;
}

bool same_areas(const std::vector<Area>& a, const std::vector<Area>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same_bits(a[i], b[i])) return false;
  return true;
}

TEST(GrowthReplay, EqualsGrowingAgainAfterChangesAnywhere) {
  // Squares on a free floor with blocked strips between them, so that they grow until they meet each other or
  // a strip. Then, each time: a patch of 3 x 3 columns blocks or opens, a square comes or goes. Growing with the
  // previous growth's record must equal growing from nothing, and read the floor less often (the squares away
  // from the change move as they did; in a room this small a change reaches many).
  const GridSpec s = grid();
  std::vector<std::uint8_t> free(s.column_count(), 1);
  for (int z = 0; z < s.nz; ++z) free[s.column(24, z)] = 0;
  for (int x = 0; x < s.nx; ++x) free[s.column(x, 16)] = 0;
  std::vector<Area> squares;
  for (float x : {0.4f, 1.4f, 2.9f, 3.9f})
    for (float z : {0.3f, 2.2f, 3.6f}) squares.push_back(floor_square(s, x, z, 0.4f));
  const AreaParams params;

  GrowthRecord record;
  std::vector<Area> grown = squares;
  std::size_t reads = 0;
  grow_areas(grown, rule_over(s, free, &reads), params, {}, {}, &record);

  struct Change {
    glm::ivec2 patch{-1};  // its first column: toggled
    int removed = -1;      // a square gone
    bool add = false;      // a square new
  };
  const std::vector<Change> changes = {{{8, 8}},  {{8, 8}},          {{22, 30}},      {{5, 40}},
                                       {{-1, -1}, 3}, {{-1, -1}, -1, true}, {{40, 5}}, {{30, 20}, 7}};
  std::size_t all_fresh_reads = 0, all_replay_reads = 0;
  for (const Change& change : changes) {
    std::vector<glm::ivec2> rows(std::size_t(s.nz), glm::ivec2(s.nx, -1));
    if (change.patch.x >= 0)
      for (int z = change.patch.y; z < change.patch.y + 3; ++z) {
        for (int x = change.patch.x; x < change.patch.x + 3; ++x) free[s.column(x, z)] ^= 1;
        rows[std::size_t(z)] = glm::ivec2(change.patch.x, change.patch.x + 2);
      }
    if (change.removed >= 0) squares.erase(squares.begin() + change.removed);
    if (change.add) squares.insert(squares.begin() + 2, floor_square(s, 1.9f, 1.0f, 0.4f));

    std::vector<Area> expected = squares;
    std::size_t fresh_reads = 0, replay_reads = 0;
    grow_areas(expected, rule_over(s, free, &fresh_reads), params);
    GrowthRecord next;
    std::vector<Area> replayed = squares;
    grow_areas(replayed, rule_over(s, free, &replay_reads), params, {}, {&record, &s, rows}, &next);
    ASSERT_TRUE(same_areas(replayed, expected)) << "patch " << change.patch.x << ", " << change.patch.y;
    EXPECT_TRUE(same_areas(next.after, expected));
    EXPECT_LT(replay_reads, fresh_reads) << "patch " << change.patch.x << ", " << change.patch.y;
    all_fresh_reads += fresh_reads, all_replay_reads += replay_reads;
    record = std::move(next);
  }
  EXPECT_LT(double(all_replay_reads), 0.6 * double(all_fresh_reads));
}

// Floors and ceilings whose height a re-sent chunk refined grow as they did (their cells are columns), so a replay
// takes their growth where their samples stay in the same layers of sample cells; where a height moves areas into
// the layer of others they meet, they now conflict, and grow afresh. Each time, equal to growing from nothing.
TEST(GrowthReplay, TakesGrowthAcrossARefinedHeightWhileSamplesKeepTheirLayers) {
  const GridSpec s = grid();
  std::vector<std::uint8_t> free(s.column_count(), 1);
  for (int z = 0; z < s.nz; ++z) free[s.column(30, z)] = 0;
  for (int x = 0; x < s.nx; ++x) free[s.column(x, 20)] = 0;
  // Group a at a height that changes, group b at 0.2 m, over the same columns (b's squares overlap a's).
  const auto squares_at = [&](float a_height) {
    std::vector<Area> out;
    for (const glm::vec2 at : {glm::vec2(0.4f, 0.3f), glm::vec2(1.9f, 1.2f), glm::vec2(0.5f, 2.6f)}) {
      out.push_back(floor_square(s, at.x, at.y, 0.4f));
      for (glm::vec3& c : out.back().corners) c.y = a_height;
      out.back().center.y = a_height;
    }
    for (const glm::vec2 at : {glm::vec2(0.6f, 0.5f), glm::vec2(2.1f, 1.0f)}) {
      out.push_back(floor_square(s, at.x, at.y, 0.4f));
      for (glm::vec3& c : out.back().corners) c.y = 0.2f;
      out.back().center.y = 0.2f;
    }
    return out;
  };
  const AreaParams params;
  const auto rule = [&](std::size_t* reads) {
    GrowthRule r = rule_over(s, free, reads);
    r.cells_read_height = false;
    return r;
  };
  GrowthRecord record;
  std::vector<Area> grown = squares_at(0.0f);
  std::size_t reads = 0;
  grow_areas(grown, rule(&reads), params, {}, {}, &record);
  const std::vector<glm::ivec2> rows(std::size_t(s.nz), glm::ivec2(s.nx, -1));  // no column changed
  // 0.0003 m: the same layer; 0.2 m: b's layer, where a and b meet; back below.
  for (const float height : {0.0003f, 0.2f, 0.0002f, -0.0004f}) {
    const std::vector<Area> squares = squares_at(height);
    std::vector<Area> expected = squares;
    std::size_t fresh_reads = 0, replay_reads = 0;
    grow_areas(expected, rule(&fresh_reads), params);
    GrowthRecord next;
    std::vector<Area> replayed = squares;
    grow_areas(replayed, rule(&replay_reads), params, {}, {&record, &s, rows}, &next);
    ASSERT_TRUE(same_areas(replayed, expected)) << "height " << height;
    if (height == 0.0003f) EXPECT_EQ(replay_reads, 0u);  // every square moved as before
    else EXPECT_GT(replay_reads, 0u) << "height " << height;
    record = std::move(next);
  }
  // At b's layer a's squares stop at b's: their growth differs from that at 0.
  std::vector<Area> apart = squares_at(0.0f), met = squares_at(0.2f);
  grow_areas(apart, rule(&reads), params);
  grow_areas(met, rule(&reads), params);
  EXPECT_NE(apart[0].half_width + apart[0].half_height, met[0].half_width + met[0].half_height);
}

// A rule that gives its cells as its voxels' (GrowthRule::voxel_at, cell_of) grows exactly as the same rule sample by
// sample: growth counts an area along the grid's axes by runs of samples in one voxel. Squares along the axes and
// turned ones, and walls, over a floor with specks missing and a fill that the counts decide.
TEST(Growth, CountsCellsByVoxelRunsAsSampleBySample) {
  const GridSpec s = grid();
  std::vector<std::uint8_t> free(s.column_count(), 1);
  std::mt19937 random(5);
  std::bernoulli_distribution speck(0.06);
  for (std::uint8_t& f : free) f = speck(random) ? 0 : 1;
  std::vector<Area> areas;
  for (float x : {0.3f, 1.33f, 2.6f, 3.72f})
    for (float z : {0.25f, 1.5f, 2.77f, 3.9f}) areas.push_back(floor_square(s, x, z, 0.5f));
  Area turned = floor_square(s, 2.0f, 2.0f, 0.4f);  // 30° about its centre: along no axis
  for (glm::vec3& c : turned.corners) {
    const glm::vec3 d = c - turned.center;
    c = turned.center + glm::vec3(0.866f * d.x - 0.5f * d.z, 0.0f, 0.5f * d.x + 0.866f * d.z);
  }
  areas.push_back(turned);
  std::vector<Area> walls;
  for (float z : {0.5f, 2.5f}) {  // facing +x, along z, 0.6 m wide and 0.5 m high
    Area w;
    w.type = AreaType::Wall;
    w.size = AreaSize::Small;
    w.normal = glm::vec3(1, 0, 0);
    w.corners = {glm::vec3(1.05f, 0.1f, z + 0.6f), glm::vec3(1.05f, 0.1f, z), glm::vec3(1.05f, 0.6f, z),
                 glm::vec3(1.05f, 0.6f, z + 0.6f)};
    w.center = glm::vec3(1.05f, 0.35f, z + 0.3f);
    w.half_width = 0.3f, w.half_height = 0.25f;
    walls.push_back(w);
  }
  const AreaParams params;
  for (std::vector<Area>* group : {&areas, &walls}) {
    std::size_t reads = 0;
    GrowthRule by_sample = rule_over(s, free, &reads);
    by_sample.fill = 0.95f;  // an area's own count decides whether it grows
    by_sample.strip_fill = 0.6f;
    GrowthRule by_voxel = by_sample;
    by_voxel.voxel_at = [&s](const glm::vec3& p, const Area&) {
      return glm::ivec3(glm::floor((p - s.origin) / s.voxel_size));
    };
    by_voxel.cell_of = [&s, &free](const glm::ivec3& v, const Area&) {
      if (v.x < 0 || v.z < 0 || v.x >= s.nx || v.z >= s.nz) return SurfaceCell::Forbidden;
      return free[s.column(v.x, v.z)] ? SurfaceCell::Usable : SurfaceCell::Unusable;
    };
    std::vector<Area> expected = *group, grown = *group;
    grow_areas(expected, by_sample, params);
    grow_areas(grown, by_voxel, params);
    EXPECT_TRUE(same_areas(grown, expected));
    EXPECT_FALSE(same_areas(grown, *group));  // they grew
  }
}

// Reach from the memo equals reach searched afresh, after every change of V_Floor (floors removed, added,
// reordered), of V_Wall, of the areas and of the floor's height, on a room split by a partition wall, so that
// areas see floors near (Close), only far (Distance) or none (None); and where only floors or the floor's height
// changed (a re-sent chunk refines the height), most areas are not searched.
TEST(ReachMemo, EqualsReachSearchedAfreshAsFloorsComeAndGo) {
  const auto area = [](AreaType type, glm::vec3 center, float half_width, glm::vec3 normal) {
    Area a;
    a.type = type, a.center = center, a.half_width = half_width, a.normal = normal;
    return a;
  };
  // A wall area along a-b (in X-Z, a to b its top edge), centred at height y, facing `normal`.
  const auto wall = [&](glm::vec2 a, glm::vec2 b, float y, glm::vec3 normal) {
    const glm::vec2 mid = 0.5f * (a + b);
    Area w = area(AreaType::Wall, {mid.x, y, mid.y}, 0.5f * glm::length(b - a), normal);
    w.corners[3] = {a.x, y + 0.3f, a.y}, w.corners[2] = {b.x, y + 0.3f, b.y};
    return w;
  };
  std::vector<Area> wall_areas;
  for (float x = 0.0f; x < 10.0f; x += 2.0f) {
    wall_areas.push_back(wall({x, 0.0f}, {x + 2.0f, 0.0f}, 1.2f, {0, 0, 1}));
    wall_areas.push_back(wall({x + 2.0f, 8.0f}, {x, 8.0f}, 0.8f, {0, 0, -1}));
  }
  for (float z = 0.0f; z < 8.0f; z += 2.0f) {
    wall_areas.push_back(wall({0.0f, z + 2.0f}, {0.0f, z}, 2.0f, {1, 0, 0}));
    wall_areas.push_back(wall({10.0f, z}, {10.0f, z + 2.0f}, 1.0f, {-1, 0, 0}));
  }
  wall_areas.push_back(wall({5.0f, 0.0f}, {5.0f, 5.5f}, 1.2f, {1, 0, 0}));   // the partition, facing +x
  wall_areas.push_back(wall({5.0f, 5.5f}, {5.0f, 0.0f}, 1.2f, {-1, 0, 0}));  // and -x
  wall_areas.push_back(wall({3.0f, 0.0f}, {1.0f, 0.0f}, 1.0f, {0, 0, -1}));  // facing out of the room: None
  // A closet in the corner x > 8, z < 1.6: what stands in it sees only its floors, of which there is one or
  // none at every step (so its reach moves between Close, Distance and None).
  wall_areas.push_back(wall({8.0f, 0.0f}, {8.0f, 1.6f}, 1.2f, {-1, 0, 0}));
  wall_areas.push_back(wall({8.0f, 1.6f}, {10.0f, 1.6f}, 1.2f, {0, 0, 1}));
  const auto in_closet = [](const Area& a) { return a.center.x > 8.0f && a.center.z < 1.6f; };

  std::mt19937 random(7);
  // Floor areas on a lattice, half of them there at first, none at first in a corner behind the partition.
  std::vector<Area> pool;
  for (float z = 0.3f; z < 7.8f; z += 0.4f)
    for (float x = 0.3f; x < 9.8f; x += 0.4f) pool.push_back(area(AreaType::Floor, {x, 0.0f, z}, 0.12f, {0, 1, 0}));
  std::vector<std::uint8_t> present(pool.size());
  for (std::size_t i = 0; i < pool.size(); ++i)
    present[i] = std::uint8_t(random() % 2 == 0 && !(pool[i].center.x > 5.5f && pool[i].center.z > 3.0f));
  std::vector<std::size_t> closet;
  for (std::size_t i = 0; i < pool.size(); ++i)
    if (in_closet(pool[i])) closet.push_back(i), present[i] = i % 5 == 0;
  std::vector<Area> areas = wall_areas;
  areas.push_back(area(AreaType::Furniture, {9.7f, 0.7f, 0.2f}, 0.05f, {0, 1, 0}));
  areas.push_back(area(AreaType::Floor, {8.2f, 0.0f, 1.4f}, 0.05f, {0, 1, 0}));
  const std::size_t fixed = areas.size();
  std::uniform_real_distribution<float> x_of(0.2f, 9.8f), z_of(0.2f, 7.8f);
  for (int i = 0; i < 60; ++i) {
    const AreaType type = i % 3 == 0 ? AreaType::Ceiling : i % 3 == 1 ? AreaType::Furniture : AreaType::Floor;
    areas.push_back(area(type, {x_of(random), type == AreaType::Ceiling ? 2.6f : 0.7f, z_of(random)}, 0.1f, {0, 1, 0}));
  }

  AreaParams params;
  ReachMemo memo, by_type;
  std::array<std::size_t, 4> reaches{};
  std::size_t kept_steps = 0, decided_by_height = 0;
  for (int step = 0; step < 30; ++step) {
    bool walls_changed = false;
    const bool only_height = step % 6 == 1;  // as a re-sent chunk that moved no area
    if (step > 0 && !only_height) {
      for (int k = 0; k < 6; ++k) present[random() % pool.size()] ^= 1;
      for (const std::size_t i : closet) present[i] = 0;
      if (random() % 3 != 0) present[closet[random() % closet.size()]] = 1;
      if (step % 9 == 4) wall_areas[3].corners[2].x += 0.05f, walls_changed = true;
      if (step % 5 == 2) areas.push_back(area(AreaType::Furniture, {x_of(random), 0.7f, z_of(random)}, 0.2f, {0, 1, 0}));
      if (step % 7 == 5)  // one of the areas on the lattice's floor, ceiling or furniture
        areas.erase(areas.begin() + std::ptrdiff_t(fixed + random() % (areas.size() - fixed)));
    }
    std::vector<ReachFloor> floors;
    for (std::size_t i = 0; i < pool.size(); ++i)
      if (present[i]) floors.emplace_back(pool[i]);
    if (step % 4 == 3) std::shuffle(floors.begin(), floors.end(), random);
    std::vector<ReachWall> walls;
    for (const Area& w : wall_areas) walls.emplace_back(w);

    // The floor's height, and the floor areas' with it: low walls within reach of a hand at one, not another.
    const float floor_y = step % 3 == 0 ? 0.0f : step % 3 == 1 ? 0.45f : -0.35f;
    for (Area& a : areas)
      if (a.type == AreaType::Floor) a.center.y = floor_y;

    std::vector<Area> fresh = areas, from_memo = areas, at_zero = areas;
    assign_reach(fresh, floors, walls, floor_y, params, 1);
    // Every other step with the wall segments made ahead, as the area search makes them (the memo's own where
    // its walls are these: else every area would be searched again).
    assign_reach(from_memo, floors, walls, floor_y, params, 2, &memo,
                 step % 2 == 0 ? reach_segments(walls, &memo) : nullptr);
    assign_reach(at_zero, floors, walls, 0.0f, params, 1);
    for (std::size_t i = 0; i < areas.size(); ++i) {
      ASSERT_EQ(from_memo[i].reach, fresh[i].reach) << "step " << step << ", area " << i;
      ASSERT_EQ(from_memo[i].flags, fresh[i].flags) << "step " << step << ", area " << i;
      ++reaches[std::size_t(fresh[i].reach)];
      decided_by_height += fresh[i].reach != at_zero[i].reach;
    }
    // The area search's way: a list per area type, each assigned on its own against one view, the memo kept once
    // all are done. Every other step the lists go in another order.
    {
      const ReachView view(floors, walls, params, &by_type, step % 2 == 0 ? reach_segments(walls, &by_type) : nullptr);
      std::array<std::vector<Area>, 4> lists;
      const auto list_of = [](const Area& a) { return std::size_t(a.type) - 1; };  // kAreaTypes' order
      for (const Area& a : areas) lists[list_of(a)].push_back(a);
      std::array<ReachMemo::Seen, 4> seen;
      for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t type = step % 2 == 0 ? k : 3 - k;
        assign_reach(lists[type], view, floor_y, params, 2, type, &seen[type]);
      }
      view.keep(by_type, seen);
      std::array<std::size_t, 4> next{};
      std::size_t searched = 0;
      for (std::size_t i = 0; i < areas.size(); ++i) {
        const Area& a = lists[list_of(areas[i])][next[list_of(areas[i])]++];
        ASSERT_EQ(a.reach, fresh[i].reach) << "by type: step " << step << ", area " << i;
        ASSERT_EQ(a.flags, fresh[i].flags) << "by type: step " << step << ", area " << i;
      }
      for (const ReachMemo::Seen& list : by_type.lists) searched += list.searched;
      EXPECT_EQ(searched, memo.lists[0].searched) << "by type: step " << step;
    }
    if (only_height) {
      EXPECT_EQ(memo.lists[0].searched, 0u) << "step " << step;
    }
    if (step > 0 && !walls_changed) {
      EXPECT_LT(memo.lists[0].searched, areas.size() / 2) << "step " << step;
      ++kept_steps;
    } else {
      EXPECT_EQ(memo.lists[0].searched, areas.size()) << "step " << step;
    }
  }
  EXPECT_GT(kept_steps, 20u);
  EXPECT_GE(decided_by_height, 20u);
  for (const Reach r : {Reach::Close, Reach::Distance, Reach::None}) EXPECT_GE(reaches[std::size_t(r)], 30u) << int(r);
}

// A floor's or a ceiling's square search after objects were only set down (tiles lost, walls added) or only taken
// away starts each centre from its previous square (search_squares's BandedSearch::previous). Each time, it must
// find what a search from nothing finds; so must the searches after a mixed change, which search as before.
TEST(SearchCache, SquaresStartedFromThePreviousSearchEqualSearchingAfresh) {
  const GridSpec s = grid(64, 8, 56);
  const SizeRange range{9.0, 13.0};
  for (const Surface surface : {Surface::Floor, Surface::Ceiling}) {
    const std::size_t type = surface == Surface::Floor ? 1 : 2;
    RoomFeatures f = empty_features(s);
    f.free_ceiling.assign(s.column_count(), 1);
    std::vector<std::uint8_t>& tiles = surface == Surface::Floor ? f.free_floor : f.free_ceiling;
    // Objects: boxes of non-tiles, some with a wall along one side; a column is a tile where no object covers it.
    struct Object {
      glm::ivec2 lo, hi;
      bool wall;
    };
    std::vector<Object> objects;
    const auto paint = [&] {
      std::fill(tiles.begin(), tiles.end(), std::uint8_t{1});
      std::fill(f.walls.begin(), f.walls.end(), std::uint8_t{0});
      for (const Object& o : objects)
        for (int z = o.lo.y; z <= o.hi.y; ++z)
          for (int x = o.lo.x; x <= o.hi.x; ++x) {
            tiles[s.column(x, z)] = 0;
            if (o.wall && x == o.lo.x) f.walls[s.column(x, z)] = 1;
          }
    };
    std::mt19937 rng(surface == Surface::Floor ? 5 : 6);
    const auto random_object = [&] {
      const glm::ivec2 lo(int(rng() % 58), int(rng() % 50));
      return Object{lo, lo + glm::ivec2(1 + int(rng() % 5), 1 + int(rng() % 5)), rng() % 3 == 0};
    };
    for (int k = 0; k < 6; ++k) objects.push_back(random_object());
    SearchCache cache;
    std::array<std::size_t, 3> steps{};  // set down, taken away, both
    std::size_t squares = 0;
    for (int step = 0; step < 40; ++step) {
      const std::size_t kind = step == 0 ? 0 : rng() % 3;
      if (step > 0 && (kind == 1 || kind == 2) && !objects.empty()) objects.erase(objects.begin() + rng() % objects.size());
      if (step > 0 && (kind == 0 || kind == 2)) objects.push_back(random_object());
      paint();
      ++steps[kind];
      cache.begin(s, f);
      const Candidates got = cache.squares(type, 0, s, f, range, 0.95f, 12.0, {});
      const Candidates want = search_squares(s, f, surface, range, 0.95f, 12.0);
      ASSERT_TRUE(same_items(got, want)) << "step " << step;
      squares += want.size();
    }
    for (const std::size_t n : steps) EXPECT_GE(n, 8u);
    EXPECT_GE(squares, 40u * 100u);
  }
}

// A wall search after its features changed takes a rectangle that reads no changed column from its band's previous
// rectangles (search_walls's BandedSearch::previous). Each time, its list must equal a fresh cache's, which searches
// every band anew, and a whole search's. Packing's replay of the list (SearchCache::replay) must know the decision
// recorded for every rectangle the previous list held, and none other, and list as gone each packed rectangle the
// list lost: a replaced band's rectangles are matched to those they replaced.
TEST(SearchCache, WallsFoundFromThePreviousSearchEqualSearchingAfresh) {
  const GridSpec s = grid(56, 12, 48);
  RoomFeatures f = empty_features(s);
  f.levels.ceiling = 10;
  // Panels of wall normals: vertical rectangles along x or z, some with a gap; a voxel's normals are its panels'.
  struct Panel {
    glm::ivec2 from;
    int length, top;
    bool along_x, gap;
  };
  std::vector<Panel> panels;
  const auto paint = [&] {
    std::fill(f.normals.begin(), f.normals.end(), std::uint8_t{0});
    for (const Panel& p : panels)
      for (int k = 0; k < p.length; ++k) {
        if (p.gap && k % 7 == 3) continue;
        const int x = p.from.x + (p.along_x ? k : 0), z = p.from.y + (p.along_x ? 0 : k);
        for (int y = 1; y <= p.top; ++y) f.normals[s.index(x, y, z)] |= p.along_x ? kNormalForward : kNormalLeft;
      }
  };
  std::mt19937 rng(11);
  const auto random_panel = [&] {
    const bool along_x = rng() % 2 == 0;
    const int length = 6 + int(rng() % 20);
    const glm::ivec2 from(int(rng() % std::uint32_t(along_x ? s.nx - length : s.nx)),
                          int(rng() % std::uint32_t(along_x ? s.nz : s.nz - length)));
    return Panel{from, length, 3 + int(rng() % 8), along_x, rng() % 3 == 0};
  };
  // The room's walls, and panels that come and go.
  panels = {{{0, 0}, 56, 10, true, false}, {{0, 47}, 56, 10, true, false}, {{0, 0}, 48, 10, false, false},
            {{55, 0}, 48, 10, false, false}};
  for (int k = 0; k < 5; ++k) panels.push_back(random_panel());
  const SizeRange range{8.0, 12.0, 0.5};
  SearchCache cache;
  std::size_t rectangles = 0, matched = 0;
  using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
  const auto key = [](const Candidates::Item& item) { return Key{item.cell_lo, item.cell_hi, item.shape}; };
  std::map<Key, std::int8_t> decided;  // the previous list's rectangles, each with the decision recorded for it
  const auto corners = [](const Candidate& c) {
    std::array<int, 12> out{};
    for (std::size_t k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) out[3 * k + std::size_t(a)] = c.corners[k][a];
    return out;
  };
  for (int step = 0; step < 30; ++step) {
    if (step > 0) {
      if (rng() % 2 == 0 && panels.size() > 4) panels.erase(panels.begin() + 4 + std::ptrdiff_t(rng() % (panels.size() - 4)));
      if (rng() % 3 != 0) panels.push_back(random_panel());
    }
    paint();
    const NormalCounts normals = count_normals(s, f);
    cache.begin(s, f);
    const Candidates got = cache.walls(0, s, f, normals, range, 0.9f, {});
    SearchCache fresh;
    fresh.begin(s, f);
    const Candidates want = fresh.walls(0, s, f, normals, range, 0.9f, {});
    const Candidates whole = search_walls(s, f, normals, range, 0.9f);
    ASSERT_TRUE(same_items(got, want)) << "step " << step;
    ASSERT_TRUE(same_items(whole, want)) << "step " << step;
    rectangles += want.size();
    const PackReplay* replay = cache.replay(0, 0);
    ASSERT_TRUE(replay != nullptr || step == 0) << "step " << step;
    if (replay != nullptr) {  // before the first packing, no rectangle has a decision
      ASSERT_EQ(replay->previous.size(), got.size());
      std::map<Key, std::int8_t> lost = decided;
      for (std::size_t i = 0; i < got.size(); ++i) {
        const auto it = decided.find(key(got.item(i)));
        EXPECT_EQ(replay->previous[i], it == decided.end() ? -1 : it->second) << "step " << step << ", rectangle " << i;
        if (it != decided.end()) lost.erase(key(got.item(i))), ++matched;
      }
      std::vector<std::array<int, 12>> want_gone, gone;
      for (const auto& [k, state] : lost)
        if (state == 1) want_gone.push_back(corners(got.decode({std::get<0>(k), std::get<1>(k), std::get<2>(k)}).unpack()));
      for (const Candidate& c : replay->gone) gone.push_back(corners(c));
      std::sort(want_gone.begin(), want_gone.end());
      std::sort(gone.begin(), gone.end());
      EXPECT_EQ(gone, want_gone) << "step " << step;
    }
    // This step's packing, recorded for the next: every third rectangle packed.
    std::vector<std::size_t> packed;
    decided.clear();
    for (std::size_t i = 0; i < got.size(); ++i) {
      if (i % 3 == 0) packed.push_back(i);
      decided[key(got.item(i))] = i % 3 == 0 ? 1 : 0;
    }
    cache.record_packing(0, 0, packed);
  }
  EXPECT_GE(rectangles, 30u * 50u);
  EXPECT_GE(matched, 29u * 30u);  // most of each list was the previous one's
}

// A furniture search after tops changed takes a layer's previous squares where its tiles are as they were and the
// layer below found what it found (search_squares's BandedSearch::levels_changed). Each time, its list must equal
// a whole search's. Tables with an island one level up and another on that, and tops of the upper levels and the
// one above coming and going. Squares rise (Eq. 3.41) into the next level, whose own squares then skip their
// centres, so a level's changes reach the level above without changing its tiles, and a level taken whole still
// takes centres from the next.
TEST(SearchCache, FurnitureLayersTakenFromThePreviousSearchEqualSearchingAfresh) {
  const GridSpec s = grid(64, 16, 56);
  RoomFeatures f = empty_features(s);
  f.levels.ceiling = 14, f.y_end = 9;
  f.furniture.assign(s.column_count(), kNoFurniture);
  struct Top {
    glm::ivec2 lo, hi;
    int level;
  };
  std::vector<Top> tops;  // later ones over earlier ones
  const auto paint = [&] {
    std::fill(f.furniture.begin(), f.furniture.end(), kNoFurniture);
    for (const Top& t : tops)
      for (int z = t.lo.y; z <= t.hi.y; ++z)
        for (int x = t.lo.x; x <= t.hi.x; ++x) f.furniture[s.column(x, z)] = t.level;
  };
  std::mt19937 rng(17);
  const auto random_top = [&](int side_from, int side_to, int level) {
    const int side = side_from + int(rng() % std::uint32_t(side_to - side_from + 1));
    const glm::ivec2 lo(int(rng() % std::uint32_t(s.nx - side)), int(rng() % std::uint32_t(s.nz - side)));
    return Top{lo, lo + glm::ivec2(side - 1, side - 1 - int(rng() % 3)), level};
  };
  for (int k = 0; k < 4; ++k) tops.push_back(random_top(20, 28, 4));
  for (int k = 0; k < 8; ++k) {  // islands one level up, and on them one more
    const Top& under = tops[std::size_t(k)];
    tops.push_back({under.lo + 3, under.hi - 3, under.level + 1});
  }
  const std::size_t fixed = tops.size();
  const SizeRange range{5.0, 7.0};
  SearchCache cache;
  std::size_t squares = 0, rising = 0;
  for (int step = 0; step < 60; ++step) {
    if (step > 0) {
      if (rng() % 2 == 0 && tops.size() > fixed) tops.erase(tops.begin() + std::ptrdiff_t(fixed + rng() % (tops.size() - fixed)));
      else tops.push_back(random_top(3, 10, 5 + int(rng() % 3)));
    }
    paint();
    cache.begin(s, f);
    const Candidates got = cache.squares(3, 0, s, f, range, 0.95f, 12.0, {});
    const Candidates want = search_squares(s, f, Surface::Furniture, range, 0.95f, 12.0);
    ASSERT_TRUE(same_items(got, want)) << "step " << step;
    for (std::size_t i = 0; i < want.size(); ++i)
      rising += f.furniture[s.column(want[i].corner(0).x, want[i].corner(0).z)] != want[i].corner(0).y;
    squares += want.size();
  }
  EXPECT_GE(squares, 60u * 100u);
  EXPECT_GE(rising, 60u);
}

// A square type's reduction is taken from the previous analysis only where that analysis searched it in the room's
// main direction as it is now (unchanged_type). Walls that turn the direction, over the same wall columns and the
// same tiles, leave every square type's features as they were: each must still be searched again, in the new
// direction, as a search without the cache does.
TEST(SearchCache, SquareTypesAreSearchedAgainWhereTheWallsTurnTheMainDirection) {
  AnalysisOptions options;
  options.find_areas = false;
  options.build_bounds = false;
  const AnalysisResult room = analyze(synth::generate_builtin_source("synthetic:rotated"), options);
  ASSERT_TRUE(room.ok());
  const SurfaceLevels surfaces{room.storeys[0].floor_y, room.storeys[0].ceiling_y, {}};
  // The room's walls, turned 30 degrees, give about 30; without wall normals there is no wall rectangle, and 0.
  RoomFeatures turned = *room.features;
  std::fill(turned.normals.begin(), turned.normals.end(), std::uint8_t{0});
  const auto same_areas = [](const AreaResult& got, const AreaResult& want) {
    if (got.areas.size() != want.areas.size())
      return ::testing::AssertionFailure() << got.areas.size() << " areas, not " << want.areas.size();
    for (std::size_t i = 0; i < want.areas.size(); ++i)
      if (!same_bits(got.areas[i], want.areas[i])) return ::testing::AssertionFailure() << "area " << i << " differs";
    return ::testing::AssertionSuccess();
  };
  const AreaResult walls_at_30 = find_areas(room.voxels.grid, *room.features, surfaces, {}, {}, 2);
  const AreaResult walls_gone = find_areas(room.voxels.grid, turned, surfaces, {}, {}, 2);
  ASSERT_FALSE(same_areas(walls_gone, walls_at_30));
  // The squares differ too, not only the walls: the direction changes what the square searches find.
  const auto squares = [](AreaResult r) {
    std::erase_if(r.areas, [](const Area& a) { return a.type == AreaType::Wall; });
    return r;
  };
  ASSERT_FALSE(same_areas(squares(walls_gone), squares(walls_at_30)));
  SearchCache cache;
  EXPECT_TRUE(same_areas(detail::find_areas(room.voxels.grid, *room.features, surfaces, {}, {}, 2, {}, &cache), walls_at_30));
  EXPECT_TRUE(same_areas(detail::find_areas(room.voxels.grid, turned, surfaces, {}, {}, 2, {}, &cache), walls_gone));
  EXPECT_TRUE(same_areas(detail::find_areas(room.voxels.grid, *room.features, surfaces, {}, {}, 2, {}, &cache), walls_at_30));
}

}  // namespace
