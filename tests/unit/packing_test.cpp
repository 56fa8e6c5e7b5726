// SquarePacker (core/src/areas/reduce.h, internal) packs a whole analysis's squares without ranking every one
// (pack_fresh: a square whose middle sample is taken when its alignment step begins is refused without a
// contact). An IncrementalAnalysis packs through the ranked path, which ranks them all. Both must keep the same
// squares, size after size, on rooms off the grid's axes too, at any main direction. A replay finds each
// rectangle's changed-region box from its shape's, exactly the box of its corners. A rotated square's contact
// samples, found once for its shape, fall in the cells its own samples fall in wherever it lies. Deduplication
// (Eq. 3.44) keeps the first rectangle of each centre, to the grid's last column and level.
#include "../../core/src/areas/reduce.h"
#include "../../core/src/areas/search.h"
#include "synthetic_fixture.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace roomsense;
using namespace roomsense::detail;

TEST(Packing, KeepsTheSameSquaresWithoutRankingEverySquare) {
  const AreaParams params;
  std::size_t compared = 0, kept_total = 0;
  for (const std::string name : {"default", "rotated", "thesis-room1"}) {
    const test::AnalysedRoom& room = test::analysed(*synth::builtin(name));
    ASSERT_TRUE(room.result.ok()) << name;
    const RoomFeatures& features = *room.result.features;
    const GridSpec& spec = room.result.voxels.grid.spec;
    for (const Surface surface : {Surface::Floor, Surface::Ceiling, Surface::Furniture})
      for (const double dominant_deg : {0.0, 17.0, 40.0}) {
        const TileMap is_tile{spec,
                              surface == Surface::Floor     ? std::span<const std::uint8_t>(features.free_floor)
                              : surface == Surface::Ceiling ? std::span<const std::uint8_t>(features.free_ceiling)
                                                            : std::span<const std::uint8_t>(),
                              surface == Surface::Furniture ? std::span<const int>(features.furniture)
                                                            : std::span<const int>()};
        const int tolerance = surface == Surface::Furniture ? params.reduction_offset - 1 : 0;
        SquarePacker fresh(spec, tolerance, dominant_deg, is_tile), ranked(spec, tolerance, dominant_deg, is_tile);
        for (std::size_t size = 0; size < 3; ++size) {
          const SizeRange range = size_range(params.square_width[size], params.square_width[size],
                                             params.width_tolerance, spec.voxel_size);
          const Candidates squares =
              search_squares(spec, features, surface, range, params.horizontal_fill, dominant_deg);
          std::vector<std::uint32_t> ranks;
          const std::vector<std::size_t> a = fresh.pack(squares), b = ranked.pack(squares, nullptr, &ranks);
          ASSERT_EQ(a, b) << name << ", surface " << int(surface) << ", " << dominant_deg << " deg, size " << size;
          EXPECT_EQ(ranks.size(), squares.size());
          compared += squares.size(), kept_total += a.size();
        }
      }
  }
  // The comparison means something: many squares, a few kept.
  EXPECT_GT(compared, 100000u);
  EXPECT_GT(kept_total, 100u);
}

// Packing's samples against a count of its own: each half-voxel sample centre strictly inside a square, found by
// an exact integer test over the square's box (no run, no cache). Squares at every rotation of a few sizes, many
// at the same orientation (the packer keeps each shape's runs), scattered so that many overlap by a sample or
// two. Whatever order packing takes them in, no two kept squares share a sample, and every refused square shares
// one with a kept square; moved by whole voxels, the same squares are kept.
TEST(Packing, KeptSquaresShareNoSampleAndEachRefusedOneMeetsAKeptOne) {
  const GridSpec spec = make_grid_spec({0, 0, 0}, {4.0f, 0.4f, 4.0f}, 0.1f);
  const std::vector<std::uint8_t> floor(spec.column_count(), 1);
  const TileMap is_tile{spec, floor, {}};
  // The samples inside a square: centre (sx / 2 + 1/4, sz / 2 + 1/4) voxels, corners at corner + 1/2; in quarter
  // voxels every value is an integer, so the test is exact.
  const auto samples = [](const Candidate& c) {
    std::vector<std::pair<long, long>> inside;
    glm::ivec3 lo = c.corners[0], hi = c.corners[0];
    for (const glm::ivec3& k : c.corners) lo = glm::min(lo, k), hi = glm::max(hi, k);
    const auto side = [&](int i, long px, long pz) {
      const glm::ivec3 a = c.corners[i], b = c.corners[(i + 1) % 4];
      return long(b.x - a.x) * (pz - (4L * a.z + 2)) - long(b.z - a.z) * (px - (4L * a.x + 2));
    };
    for (long sz = 2L * lo.z; sz <= 2L * hi.z + 1; ++sz)
      for (long sx = 2L * lo.x; sx <= 2L * hi.x + 1; ++sx) {
        const long px = 2 * sx + 1, pz = 2 * sz + 1;
        bool positive = true, negative = true;
        for (int i = 0; i < 4; ++i) positive = positive && side(i, px, pz) > 0, negative = negative && side(i, px, pz) < 0;
        if (positive || negative) inside.push_back({sx, sz});
      }
    std::sort(inside.begin(), inside.end());
    return inside;
  };
  std::vector<Candidates::Shape> shapes;
  for (const glm::ivec2 d : {glm::ivec2(6, 0), glm::ivec2(5, 2), glm::ivec2(2, 5), glm::ivec2(4, 4), glm::ivec2(7, 1),
                             glm::ivec2(3, -4), glm::ivec2(1, 3)})
    shapes.push_back({d.x, d.y, PackedCandidate::kSquare});
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> place(10, 28), pick(0, int(shapes.size()) - 1);
  Candidates squares(spec, 2, shapes);
  for (int i = 0; i < 400; ++i) squares.push_back(glm::ivec3(place(rng), 1, place(rng)), std::uint32_t(pick(rng)));
  SquarePacker packer(spec, 0, 0.0, is_tile);
  const std::vector<std::size_t> kept = packer.pack(squares);
  ASSERT_GT(kept.size(), 5u);
  ASSERT_LT(kept.size(), squares.size() / 2);
  std::vector<std::vector<std::pair<long, long>>> of_kept;
  for (const std::size_t i : kept) of_kept.push_back(samples(squares[i].unpack()));
  const auto meet = [](const std::vector<std::pair<long, long>>& a, const std::vector<std::pair<long, long>>& b) {
    std::vector<std::pair<long, long>> both;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
    return !both.empty();
  };
  for (std::size_t a = 0; a < of_kept.size(); ++a)
    for (std::size_t b = a + 1; b < of_kept.size(); ++b)
      EXPECT_FALSE(meet(of_kept[a], of_kept[b])) << "kept squares " << kept[a] << " and " << kept[b];
  for (std::size_t i = 0; i < squares.size(); ++i) {
    if (std::binary_search(kept.begin(), kept.end(), i)) continue;
    const auto mine = samples(squares[i].unpack());
    EXPECT_TRUE(std::any_of(of_kept.begin(), of_kept.end(), [&](const auto& k) { return meet(mine, k); }))
        << "refused square " << i << " meets no kept one";
  }
  // An IncrementalAnalysis's packers share runs from one analysis to the next: the same squares moved by whole
  // voxels, packed with the runs the first packing found, keep the same ones.
  SquareSampleRuns shared;
  SquarePacker(spec, 0, 0.0, is_tile, {}, &shared).pack(squares);
  Candidates moved(spec, 2, shapes);
  for (std::size_t i = 0; i < squares.size(); ++i)
    moved.push_back(squares[i].corner(0) + glm::ivec3(3, 0, -5), squares.item(i).shape);
  const std::vector<std::size_t> kept_moved = SquarePacker(spec, 0, 0.0, is_tile, {}, &shared).pack(moved);
  EXPECT_EQ(kept_moved, kept);
  EXPECT_EQ(kept_moved, SquarePacker(spec, 0, 0.0, is_tile).pack(moved));  // runs found where they now are
}

// The walls' dominant direction: their first edges' degrees (modulo 90, so a wall and the one across the corner
// count alike) weighted by length and smoothed over ±1°. Walls at 27° (and 26° and 28° beside) outweigh longer
// ones along an axis; in any order of the walls, each offset met many times.
TEST(Packing, DominantDirectionWeighsWallsByLengthAndFoldsRightAngles) {
  std::vector<Sized> walls;
  const auto add = [&](int dx, int dz, int count) {
    for (int i = 0; i < count; ++i) walls.push_back({PackedCandidate(glm::ivec3(10 + i, 5, 20), dx, dz, 3), AreaSize::Small});
  };
  add(4, 2, 6);    // 26.6° -> 27, 4.47 each
  add(-2, 4, 4);   // 116.6° folds to 27
  add(41, 20, 1);  // 26.0°, 45.6
  add(15, 8, 3);   // 28.1°, 17 each
  add(3, 0, 20);   // 0°, 60 in all: the most walls, less weight than 26-28° together
  EXPECT_EQ(dominant_direction_deg(walls), 27.0);
  std::reverse(walls.begin(), walls.end());
  EXPECT_EQ(dominant_direction_deg(walls), 27.0);
  add(0, 5, 20);   // 90° folds to 0: 160 there
  EXPECT_EQ(dominant_direction_deg(walls), 0.0);
  walls.erase(walls.end() - 20, walls.end());
  add(4, 0, 30);   // 0° again, along the first walls' dx: 180 there
  EXPECT_EQ(dominant_direction_deg(walls), 0.0);
  EXPECT_EQ(dominant_direction_deg({}), 0.0);
}

// A replay keeps a square's rank (its contact) unless its contact may read a changed column: contact_may_read.
// Squares at many rotations around small boxes of non-tiles (an object set down on the floor), ranked over the
// bare floor and over the floor with the box: where contact_may_read says no, the ranks are equal. The test means
// something: some ranks differ, and many squares whose changed-region box meets the object's are spared.
TEST(Packing, ContactReadsNoColumnWhereContactMayReadSaysNone) {
  const GridSpec spec = make_grid_spec({0, 0, 0}, {4.0f, 0.4f, 4.0f}, 0.1f);
  const std::vector<std::uint8_t> bare(spec.column_count(), 1);
  std::vector<Candidates::Shape> shapes;
  for (const glm::ivec2 d : {glm::ivec2(12, 0), glm::ivec2(9, 5), glm::ivec2(5, 9), glm::ivec2(8, 8), glm::ivec2(11, 2),
                             glm::ivec2(3, -10), glm::ivec2(6, 0), glm::ivec2(4, 3), glm::ivec2(1, 1)})
    shapes.push_back({d.x, d.y, PackedCandidate::kSquare});
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> place(11, 17), pick(0, int(shapes.size()) - 1), corner(4, 32), width(0, 4);
  Candidates squares(spec, 2, shapes);
  for (int i = 0; i < 600; ++i) squares.push_back(glm::ivec3(place(rng), 1, place(rng)), std::uint32_t(pick(rng)));
  std::vector<std::uint32_t> bare_ranks;
  SquarePacker(spec, 0, 0.0, TileMap{spec, bare, {}}).pack(squares, nullptr, &bare_ranks);
  std::size_t differ = 0, spared = 0;
  for (int k = 0; k < 40; ++k) {
    const glm::ivec2 lo(corner(rng), corner(rng));
    const ChangedRegion::Box box{lo, lo + glm::ivec2(width(rng), width(rng))};
    std::vector<std::uint8_t> floor = bare;
    for (int z = box.lo.y; z <= box.hi.y; ++z)
      for (int x = box.lo.x; x <= box.hi.x; ++x) floor[spec.column(x, z)] = 0;
    std::vector<std::uint32_t> ranks;
    SquarePacker(spec, 0, 0.0, TileMap{spec, floor, {}}).pack(squares, nullptr, &ranks);
    ChangedRegion changed({glm::ivec2(0), glm::ivec2(spec.nx - 1, spec.nz - 1)});
    changed.add(box);
    for (std::size_t i = 0; i < squares.size(); ++i) {
      const Candidate c = squares[i].unpack();
      differ += ranks[i] != bare_ranks[i];
      if (contact_may_read(c, box)) continue;
      EXPECT_EQ(ranks[i], bare_ranks[i]) << "square " << i << " around the box from (" << box.lo.x << ", " << box.lo.y << ")";
      spared += changed.touches(ChangedRegion::around(c));
    }
  }
  EXPECT_GT(differ, 500u);
  EXPECT_GT(spared, 1000u);
}

// SquarePacker::contact samples every half voxel along a rotated square's edges, 0.75 voxels outside. The cells
// SquareSampleRuns keeps for a shape, moved to where a square lies, are the cells those samples fall in there,
// each as often, at coordinates up to a million voxels; a shape with a sample on a cell's border has none (there
// rounding at the square's own coordinates decides). Some shapes have (edges of 3-4-5 triangles), most do not.
TEST(Packing, AShapesContactCellsAreTheCellsItsSamplesFallInWhereverItLies) {
  const auto samples_at = [](const Candidate& c) {  // contact's samples, computed where c lies
    std::map<std::pair<int, int>, int> cells;
    const glm::dvec2 mid = glm::dvec2(corner_sum(c).x, corner_sum(c).z) * 0.25 + 0.5;
    for (std::size_t i = 0; i < 4; ++i) {
      const glm::dvec2 a(c.corners[i].x + 0.5, c.corners[i].z + 0.5);
      const glm::dvec2 b(c.corners[(i + 1) % 4].x + 0.5, c.corners[(i + 1) % 4].z + 0.5);
      const double length = glm::distance(a, b);
      const glm::dvec2 dir = (b - a) / length;
      glm::dvec2 out(-dir.y, dir.x);
      if (glm::dot(out, 0.5 * (a + b) - mid) < 0.0) out = -out;
      for (double t = 0.0; t <= length; t += 0.5) {
        const glm::dvec2 p = a + t * dir + 0.75 * out;
        ++cells[{int(std::floor(p.x)), int(std::floor(p.y))}];
      }
    }
    return cells;
  };
  std::mt19937 rng(41);
  std::uniform_int_distribution<int> edge(1, 30), sign(0, 1), coordinate(-1000000, 1000000);
  SquareSampleRuns runs;
  std::size_t with_cells = 0, without = 0;
  for (int k = 0; k < 400; ++k) {
    const int dx = edge(rng), dz = (sign(rng) ? 1 : -1) * edge(rng);
    const glm::ivec2 shape = k % 8 == 0 ? glm::ivec2(4 * (k % 5 + 1), 3 * (k % 5 + 1)) : glm::ivec2(dx, dz);
    for (int n = 0; n < 6; ++n) {
      const glm::ivec3 corner(coordinate(rng), 2, coordinate(rng));
      const Candidate c = PackedCandidate(corner, shape.x, shape.y, PackedCandidate::kSquare).unpack();
      const auto cells = runs.contact_cells(c);
      if (n == 0) ++(cells ? with_cells : without);
      if (!cells) continue;
      std::map<std::pair<int, int>, int> moved;
      for (const SquareSampleRuns::ContactCell& cell : *cells) moved[{corner.x + cell.dx, corner.z + cell.dz}] += cell.samples;
      EXPECT_EQ(moved, samples_at(c)) << "shape (" << shape.x << ", " << shape.y << ") at (" << corner.x << ", " << corner.z << ")";
    }
  }
  EXPECT_GT(with_cells, 300u);
  EXPECT_GT(without, 10u);
}

TEST(Packing, AReplaysBoxFromTheShapeIsTheBoxOfTheCorners) {
  std::mt19937 random(19);
  std::uniform_int_distribution<int> offset(-40, 40), place(0, 300), height(0, 60);
  std::vector<Candidates::Shape> shapes;
  for (int k = 0; k < 200; ++k)
    shapes.push_back({offset(random), offset(random), k % 2 == 0 ? PackedCandidate::kSquare : height(random)});
  const std::vector<ChangedRegion::Box> boxes = ChangedRegion::around_shapes(shapes);
  ASSERT_EQ(boxes.size(), shapes.size());
  for (int k = 0; k < 2000; ++k) {
    const std::size_t s = std::size_t(k) % shapes.size();
    const PackedCandidate c(glm::ivec3(place(random), place(random) % 40, place(random)), shapes[s].dx, shapes[s].dz,
                            shapes[s].side);
    const ChangedRegion::Box expected = ChangedRegion::around(c.unpack()), got = ChangedRegion::around(c, boxes[s]);
    EXPECT_EQ(got.lo, expected.lo) << "shape " << s;
    EXPECT_EQ(got.hi, expected.hi) << "shape " << s;
  }
}

// Eq. 3.42-3.44 on hand-made rectangles of an 8 x 4 x 8 grid: a centre on one voxel or between two (the box of
// voxels it marks), at the grid's first and last columns and levels (a top's y_Actual one level above the grid,
// a wall's centre half a level below it), each kept once; a centre past the grid is an error, not a write.
TEST(Deduplication, KeepsTheFirstRectangleOfEachCentreToTheGridsEdges) {
  GridSpec spec;
  spec.nx = 8, spec.ny = 4, spec.nz = 8;
  constexpr int kSquare = PackedCandidate::kSquare;
  // Shapes: a 2-voxel square (centre on corner 1 + (1, 0, 1)), a 1-voxel square (centre between two voxels in x
  // and z), and a wall 2 voxels wide and 1 high (centre between two levels).
  const std::vector<Candidates::Shape> shapes = {{2, 0, kSquare}, {1, 0, kSquare}, {2, 0, 1}};
  Candidates squares(spec, spec.ny + 1, {shapes[0], shapes[1]});
  squares.push_back({0, 0, 0}, 0);  // centre voxel (1, 0, 1): kept
  squares.push_back({0, 0, 0}, 1);  // voxels x, z in [0, 1]: (1, 0, 1) is marked, dropped
  squares.push_back({1, 0, 1}, 1);  // x, z in [1, 2]: (1, 0, 1) marked, dropped
  squares.push_back({2, 0, 2}, 1);  // x, z in [2, 3]: kept
  squares.push_back({6, 4, 6}, 1);  // x, z in [6, 7] at level 4 = ny (y_Actual): kept
  squares.push_back({6, 4, 6}, 0);  // voxel (7, 4, 7): marked, dropped
  squares.push_back({5, 3, 5}, 0);  // voxel (6, 3, 6), a level below: kept
  std::vector<glm::ivec3> kept;
  const auto keep = [&](const Sized& s) { kept.push_back(s.packed.corner(0)); };
  CentreDeduplicator dedup(spec);
  EXPECT_EQ(dedup.add(squares, AreaSize::Large, keep), 4u);
  EXPECT_EQ(kept, (std::vector<glm::ivec3>{{0, 0, 0}, {2, 0, 2}, {6, 4, 6}, {5, 3, 5}}));

  // A later size's rectangles are dropped where an earlier size's centres are.
  Candidates smaller(spec, spec.ny + 1, {shapes[1]});
  smaller.push_back({2, 0, 2}, 0);  // as a kept one: dropped
  smaller.push_back({3, 0, 3}, 0);  // x, z in [3, 4]: (3, 0, 3) marked, dropped
  smaller.push_back({4, 0, 4}, 0);  // kept
  kept.clear();
  EXPECT_EQ(dedup.add(smaller, AreaSize::Medium, keep), 1u);
  EXPECT_EQ(kept, (std::vector<glm::ivec3>{{4, 0, 4}}));

  // A wall whose top is at level 0 has its centre between levels -1 and 0: kept, and the same centre once.
  Candidates walls(spec, spec.ny, {shapes[2]});
  walls.push_back({0, 0, 7}, 0);
  walls.push_back({0, 0, 7}, 0);
  walls.push_back({0, 3, 7}, 0);  // levels 2 and 3, the grid's last
  kept.clear();
  CentreDeduplicator wall_dedup(spec);
  EXPECT_EQ(wall_dedup.add(walls, AreaSize::Large, keep), 2u);

  // Centres past the grid: a square whose centre lies in column 8, a wall whose centre lies below level -1.
  Candidates past_x(spec, spec.ny, {shapes[0]});
  past_x.push_back({7, 0, 0}, 0);
  EXPECT_THROW(CentreDeduplicator(spec).add(past_x, AreaSize::Large, keep), std::logic_error);
  Candidates past_y(spec, spec.ny, {{2, 0, 5}});
  past_y.push_back({0, 0, 0}, 0);
  EXPECT_THROW(CentreDeduplicator(spec).add(past_y, AreaSize::Large, keep), std::logic_error);
}

}  // namespace
