// FeatureMemo (core/src/features/feature_memo.h, internal): detect_features through an IncrementalAnalysis's
// memo of its whole-storey steps, column steps, wall normals and openings equals detect_features on its own,
// over a run of grids that add and take away furniture, a window, a wall and a door, and with a memo whose grid
// is not the one before; a local change derives no whole-storey step again, and few columns.
#include "../../core/src/features/feature_memo.h"
#include "../../core/src/grid/changed_columns.h"
#include "roomsense/synthetic.h"
#include "same_features.h"
#include "synthetic_fixture.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace roomsense {
namespace {

void expect_same(const RoomFeatures& a, const RoomFeatures& b, const std::string& step) {
  SCOPED_TRACE(step);
  test::expect_same_features(a, b);
}

// Sets the voxels of columns [x0, x1] x [z0, z1] at levels [y0, y1] to `value`.
void fill(VoxelGrid& grid, glm::ivec3 lo, glm::ivec3 hi, std::uint8_t value) {
  for (int z = lo.z; z <= hi.z; ++z)
    for (int x = lo.x; x <= hi.x; ++x)
      for (int y = lo.y; y <= hi.y; ++y) grid.cells[grid.spec.index(x, y, z)] = value;
}

class Memoized {
 public:
  explicit Memoized(const FloorCeiling& levels) : levels_(levels) {}
  // The features of `grid` through the memo, `before` the serial the memo is told the previous grid had.
  RoomFeatures features(const VoxelGrid& grid, std::uint64_t before) {
    std::vector<std::uint32_t> counts;
    std::vector<std::uint8_t> any;
    count_columns(grid, levels_, counts, any);
    const std::vector<std::uint8_t> changed =
        previous_ ? detail::changed_columns(*previous_, grid) : std::vector<std::uint8_t>();
    const detail::GridChange change{before, serial_ + 1, previous_ ? &changed : nullptr};
    RoomFeatures f = detail::detect_features(grid, levels_, counts, any, {}, 2, {}, {}, &memo_, change,
                                             features_ ? &*features_ : nullptr);
    ++serial_;
    previous_ = grid;
    features_ = f;
    expect_same(f, detect_features(grid, levels_, counts, any, {}, 2), "serial " + std::to_string(serial_));
    return f;
  }
  // Compares the next grid against `grid`, not the one the memo read.
  void compare_against(const VoxelGrid& grid) { previous_ = grid; }
  std::uint64_t serial() const { return serial_; }
  const detail::FeatureMemo& memo() const { return memo_; }

 private:
  FloorCeiling levels_;
  detail::FeatureMemo memo_;
  std::uint64_t serial_ = 0;
  std::optional<VoxelGrid> previous_;
  std::optional<RoomFeatures> features_;  // of the previous grid
};

TEST(FeatureMemo, EqualsTheFeaturesDerivedWholeAsFurnitureAndWallsComeAndGo) {
  const test::AnalysedRoom& room = test::analysed(synth::default_room());
  const VoxelGrid& original = room.result.voxels.grid;
  const GridSpec& s = original.spec;
  const FloorCeiling levels = room.result.features->levels;
  Memoized m(levels);
  m.features(original, 0);
  const std::size_t columns = s.column_count();
  EXPECT_EQ(m.memo().columns.inputs.derived(), columns);

  // A 0.4 m box on the floor in the middle of the room: furniture, no wall.
  VoxelGrid boxed = original;
  const int cx = s.nx / 2, cz = s.nz / 2;
  fill(boxed, {cx - 2, levels.floor + 1, cz - 2}, {cx + 1, levels.floor + 4, cz + 1}, 1);
  const detail::FeatureMemo& memo = m.memo();
  const std::size_t rooms = memo.rooms.derived(), enclosed = memo.enclosed.derived();
  const RoomFeatures with_box = m.features(boxed, m.serial());
  EXPECT_NE(with_box.furniture, room.result.features->furniture);
  EXPECT_EQ(memo.rooms.derived(), rooms);
  EXPECT_EQ(memo.enclosed.derived(), enclosed);
  EXPECT_GT(memo.columns.inputs.derived(), 0u);
  EXPECT_LT(memo.columns.inputs.derived(), columns / 10);

  m.features(original, m.serial());  // taken away again

  // A cabinet eight voxels from the wall at the grid's low x end: the wall's runs end at it, the normals change
  // there, and are derived again near it alone.
  int wall_x = 0;
  while (wall_x < s.nx && !room.result.features->walls[s.column(wall_x, cz)]) ++wall_x;
  ASSERT_LT(wall_x + 10, s.nx);
  VoxelGrid cabinet = original;
  fill(cabinet, {wall_x + 8, levels.floor + 1, cz - 2}, {wall_x + 9, levels.floor + 8, cz + 1}, 1);
  const RoomFeatures with_cabinet = m.features(cabinet, m.serial());
  EXPECT_NE(with_cabinet.normals, room.result.features->normals);
  EXPECT_GT(memo.normals.inputs.derived(), 0u);
  EXPECT_LT(memo.normals.inputs.derived(), columns / 10);
  m.features(original, m.serial());

  // A window in that wall: the voxels before it are blocked, derived again near it alone.
  VoxelGrid window = original;
  fill(window, {0, levels.floor + 10, cz}, {wall_x, levels.floor + 13, cz + 2}, 0);
  const RoomFeatures with_window = m.features(window, m.serial());
  EXPECT_EQ(with_window.walls, room.result.features->walls);
  EXPECT_NE(with_window.wall_blocked, room.result.features->wall_blocked);
  EXPECT_GT(memo.openings.inputs.derived(), 0u);
  EXPECT_LT(memo.openings.inputs.derived(), columns / 10);
  m.features(original, m.serial());

  // A wall across half the room: the walls change, and every step that reads them runs again.
  VoxelGrid walled = original;
  fill(walled, {1, levels.floor, cz}, {s.nx / 2, levels.ceiling, cz}, 1);
  const RoomFeatures with_wall = m.features(walled, m.serial());
  EXPECT_NE(with_wall.walls, room.result.features->walls);
  EXPECT_GT(memo.enclosed.derived(), enclosed);
  EXPECT_GT(memo.rooms.derived(), rooms);

  // A hole through that wall, then a cabinet behind the hole: the voxels in front of the hole are blocked until
  // the cabinet closes it two columns behind them (the wall's face and its recess).
  VoxelGrid holed = walled;
  fill(holed, {5, levels.floor + 10, cz}, {7, levels.floor + 13, cz}, 0);
  const RoomFeatures with_hole = m.features(holed, m.serial());
  VoxelGrid closed = holed;
  fill(closed, {5, levels.floor + 10, cz - 1}, {7, levels.floor + 13, cz - 1}, 1);
  const RoomFeatures behind = m.features(closed, m.serial());
  EXPECT_EQ(behind.walls, with_hole.walls);
  EXPECT_NE(behind.wall_blocked, with_hole.wall_blocked);
  EXPECT_LT(memo.openings.inputs.derived(), columns / 10);

  // A door through that wall, 0.6 m wide and open to the floor: the wall columns on either side of it are blocked
  // beside the gap. A box in the doorway closes it; taken away, the door is open again. The memo finds the doors
  // of the lines near the change alone (update_wall_openings), which must be every door the columns done again read.
  VoxelGrid door = closed;
  fill(door, {12, levels.floor + 1, cz}, {17, levels.floor + 20, cz}, 0);
  const RoomFeatures with_door = m.features(door, m.serial());
  EXPECT_NE(with_door.wall_blocked, behind.wall_blocked);
  VoxelGrid boxed_door = door;
  fill(boxed_door, {13, levels.floor + 1, cz - 1}, {16, levels.floor + 4, cz + 1}, 1);
  const RoomFeatures with_box_in_door = m.features(boxed_door, m.serial());
  EXPECT_NE(with_box_in_door.wall_blocked, with_door.wall_blocked);
  EXPECT_EQ(m.features(door, m.serial()).wall_blocked, with_door.wall_blocked);
  // A box two columns in front of the door: the columns done again reach the row before the door, whose blocked
  // voxels come from the door's line, which holds no change.
  VoxelGrid box_before_door = door;
  fill(box_before_door, {13, levels.floor + 1, cz - 3}, {16, levels.floor + 3, cz - 2}, 1);
  m.features(box_before_door, m.serial());
  m.features(door, m.serial());
  EXPECT_LT(memo.openings.inputs.derived(), columns / 10);

  // A grid compared against one the memo did not read (an analysis between them failed), as the serials say:
  // every column again. The comparison finds no change, so trusting it would keep the walled grid's results.
  m.compare_against(boxed);
  m.features(boxed, m.serial() + 7);
  EXPECT_EQ(memo.columns.inputs.derived(), columns);
}

// The ceiling's flood through the memo (CeilingSteps: only the clusters of columns a change reaches flooded again)
// equals the whole flood, over random boxes that come and go: furniture on the floor, hollow boxes (shut in: no
// part of the flood), soffits and beams that lower the ceiling, shelves in mid-air, and columns leaving the room.
TEST(FeatureMemo, CeilingFloodEqualsTheWholeFloodAsBoxesComeAndGo) {
  const test::AnalysedRoom& analysed = test::analysed(synth::default_room());
  const VoxelGrid& original = analysed.result.voxels.grid;
  const GridSpec& s = original.spec;
  const FloorCeiling levels = analysed.result.features->levels;
  const std::vector<std::uint8_t> original_room = analysed.result.features->room;
  const int cap = levels.ceiling;
  detail::CeilingSteps memo;
  VoxelGrid grid = original, previous = original;
  std::vector<std::uint8_t> room = original_room;
  std::uint64_t serial = 0;
  std::size_t lowered = 0;  // steps whose ceiling differs from the room's own
  const std::vector<int> plain = column_ceilings(original, levels, original_room, cap);
  const auto check = [&](const std::string& step) {
    SCOPED_TRACE(step);
    const std::vector<std::uint8_t> changed = detail::changed_columns(previous, grid);
    const detail::GridChange change{serial, serial + 1, serial > 0 ? &changed : nullptr};
    const std::vector<int> got = detail::column_ceilings(grid, levels, room, cap, &memo, change);
    const std::vector<int> want = column_ceilings(grid, levels, room, cap);
    ASSERT_EQ(got, want);
    if (got != plain) ++lowered;
    ++serial;
    previous = grid;
  };
  check("the room");
  std::mt19937 random(19);
  const auto between = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  struct Box {
    glm::ivec3 lo, hi;
  };
  std::vector<Box> boxes;  // added, not yet taken away
  const auto restore = [&](const Box& b) {
    for (int z = b.lo.z; z <= b.hi.z; ++z)
      for (int x = b.lo.x; x <= b.hi.x; ++x)
        for (int y = b.lo.y; y <= b.hi.y; ++y) grid.cells[s.index(x, y, z)] = original.cells[s.index(x, y, z)];
  };
  for (int step = 0; step < 80; ++step) {
    const int kind = between(0, 5);
    if (kind == 0 && !boxes.empty()) {  // one taken away (the voxels of the room as they were)
      const std::size_t k = std::size_t(between(0, int(boxes.size()) - 1));
      restore(boxes[k]);
      boxes.erase(boxes.begin() + std::ptrdiff_t(k));
      check("step " + std::to_string(step) + ": a box taken away");
      continue;
    }
    if (kind == 1) {  // columns leave the room, or come back
      const int x = between(0, s.nx - 4), z = between(0, s.nz - 4);
      for (int dz = 0; dz < 3; ++dz)
        for (int dx = 0; dx < 3; ++dx) {
          const std::size_t col = s.column(x + dx, z + dz);
          room[col] = room[col] == original_room[col] ? std::uint8_t(!original_room[col]) : original_room[col];
        }
      check("step " + std::to_string(step) + ": the room changed");
      continue;
    }
    const int w = between(1, 8), d = between(1, 8);
    const int x = between(0, s.nx - w - 1), z = between(0, s.nz - d - 1);
    Box b{{x, 0, z}, {x + w, 0, z + d}};
    if (kind == 2) b.lo.y = levels.floor + 1, b.hi.y = levels.floor + between(1, 12);            // furniture
    if (kind == 3) b.lo.y = cap - between(2, 10), b.hi.y = cap;                                 // a soffit or beam
    if (kind == 4) b.lo.y = levels.floor + between(4, 20), b.hi.y = b.lo.y + between(0, 3);     // a shelf
    if (kind == 5 || kind == 0) b.lo.y = levels.floor + 1, b.hi.y = levels.floor + between(4, 12);  // hollow
    b.hi.y = std::min(b.hi.y, s.ny - 1);
    for (int zz = b.lo.z; zz <= b.hi.z; ++zz)
      for (int xx = b.lo.x; xx <= b.hi.x; ++xx)
        for (int y = b.lo.y; y <= b.hi.y; ++y) {
          const bool shell = xx == b.lo.x || xx == b.hi.x || zz == b.lo.z || zz == b.hi.z || y == b.lo.y || y == b.hi.y;
          if (kind != 5 && kind != 0) grid.cells[s.index(xx, y, zz)] = 1;
          else if (shell) grid.cells[s.index(xx, y, zz)] = 1;
        }
    boxes.push_back(b);
    check("step " + std::to_string(step) + ": a box of kind " + std::to_string(kind) + " added");
  }
  EXPECT_GT(lowered, 10u);  // the boxes reached the ceiling: the flood's result changed, not only its runs
  // Two columns A and D, each with furniture below and a beam above, walled in by pillars two deep: the runs
  // between are shut in. D cleared opens them: A, which did not change, now reaches to its beam, as a neighbour of
  // a change; and the pillar before A, which the flood does not reach, takes its ceiling from A's.
  for (const Box& b : boxes) restore(b);
  boxes.clear();
  room = original_room;
  check("the room again");
  const int ax = s.nx / 2, az = s.nz / 2, lo = levels.floor + 1, hi = cap - 1;
  for (int x = ax - 2; x <= ax + 3; ++x)
    for (int z = az - 2; z <= az + 2; ++z)
      for (int y = lo; y <= hi; ++y) {
        const bool inner = z == az && (x == ax || x == ax + 1);
        grid.cells[s.index(x, y, z)] = !inner || y <= lo + 3 || y >= hi - 3 ? 1 : 0;
      }
  check("A and D shut in");
  const std::vector<int> shut = memo.ceiling;
  for (int y = lo; y <= hi; ++y) grid.cells[s.index(ax + 1, y, az)] = 0;
  check("D cleared");
  EXPECT_EQ(memo.ceiling[s.column(ax, az)], hi - 3);
  EXPECT_NE(memo.ceiling[s.column(ax, az)], shut[s.column(ax, az)]);
  EXPECT_EQ(memo.ceiling[s.column(ax, az - 1)], hi - 3);
  EXPECT_EQ(shut[s.column(ax, az - 1)], cap);
  // A grid the memo did not read before this one (an analysis between them failed): flooded whole, and equal.
  previous = original;
  serial += 5;
  check("after a gap");
}

TEST(FeatureMemo, KeepsNoResultADeriveFailedFor) {
  detail::StepMemo<int, int> step;
  EXPECT_EQ(step.get([] { return 1; }, 5), 1);
  EXPECT_EQ(step.get([] { return 2; }, 5), 1);  // the same input: kept
  EXPECT_EQ(step.get([] { return 3; }, 6), 3);
  EXPECT_THROW(step.get([]() -> int { throw std::runtime_error("failed"); }, 7), std::runtime_error);
  EXPECT_EQ(step.get([] { return 4; }, 6), 4);  // the failure left nothing kept, not even 6's
  EXPECT_EQ(step.derived(), 3u);
}

}  // namespace
}  // namespace roomsense
