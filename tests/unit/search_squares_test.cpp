// search_squares (core/src/areas/search_squares.cpp, internal) against a literal reading of Alg. 3 on a floor
// (Eq. 3.28-3.38): every centre of the half-voxel lattice in the search's order (row by row, along each row), each
// trying the orientations of its parity most nearly aligned with the room's main direction first; corner 1 a free
// tile and the other corners tiles; the cells the square covers (RingOffset::runs) holding no wall and no more
// cells that are not tiles than its fill allows; the first valid orientation kept. The search reads those cells
// through bits of 64 centres, boxes of summed counts and runs of columns; the lists must be equal, item for item.
//
// It also skips a layer of several (furniture's levels) where
// no centre can hold a square: where no run of rows (or of columns) as long as a square's cells span holds the tiles
// the fewest-tiled valid square needs (Eq. 3.30-3.38: all but the cells its fill may miss), or no run as long as the
// inner box every square holds spans holds that box's. Skipping must never lose a square: a top is searched alone,
// where the rule may skip its layer, and beside a large top at the same level far off, which keeps every run full
// and the layer searched; the small top's squares must be the same in both.
#include "../../core/src/areas/ring_offsets.h"
#include "../../core/src/areas/search.h"

#include "roomsense/features.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

namespace {

using namespace roomsense;
using namespace roomsense::detail;

// An empty room of nx x ny x nz voxels at 0.1 m: no wall, normal, tile or top; levels as given.
struct Room {
  GridSpec spec;
  RoomFeatures features;
};
Room empty_room(int nx, int ny, int nz, int floor, int ceiling, int y_end) {
  GridSpec s;
  s.nx = nx, s.ny = ny, s.nz = nz;
  s.voxel_size = 0.1f;
  RoomFeatures f;
  f.levels.floor = floor, f.levels.ceiling = ceiling, f.y_end = y_end;
  f.walls.assign(s.column_count(), 0);
  f.normals.assign(s.voxel_count(), 0);
  f.free_floor.assign(s.column_count(), 0);
  f.free_ceiling.assign(s.column_count(), 0);
  f.furniture.assign(s.column_count(), kNoFurniture);
  return {s, f};
}

// Each square found: its first corner and its offset (dx, dz), in the order found.
using Found = std::vector<std::tuple<glm::ivec3, int, int>>;
Found listed(const Candidates& c) {
  Found out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Candidates::Shape& shape = c.shapes()[c.item(i).shape];
    out.emplace_back(c[i].corner(0), shape.dx, shape.dz);
  }
  return out;
}

Found literal_floor_squares(const GridSpec& s, const RoomFeatures& f, const SizeRange& size, float fill,
                            double dominant_deg) {
  const std::vector<RingOffset> ring = ring_offsets(size, Shape::Square);
  const auto misalignment = [&](const RingOffset& o) {
    const double a = std::fmod(std::atan2(double(o.dz), double(o.dx)) * 180.0 / std::numbers::pi + 360.0, 90.0);
    const double d = std::fabs(a - dominant_deg);
    return std::min(d, 90.0 - d);
  };
  std::vector<const RingOffset*> order;
  for (const RingOffset& o : ring) order.push_back(&o);
  std::stable_sort(order.begin(), order.end(),
                   [&](const RingOffset* a, const RingOffset* b) { return misalignment(*a) < misalignment(*b); });
  const auto inside = [&](int x, int z) { return x >= 0 && z >= 0 && x < s.nx && z < s.nz; };
  const auto tile = [&](int x, int z) { return inside(x, z) && f.free_floor[s.column(x, z)] != 0; };
  const auto valid = [&](int x1, int z1, const RingOffset& o) {
    const double may_miss = double(o.cells) - double(fill) * (o.d + 1.0) * (o.d + 1.0);
    if (may_miss < 0.0) return false;
    long missing = 0;
    for (const CellRun& run : o.runs)
      for (int z = z1 + run.dz_lo; z <= z1 + run.dz_hi; ++z) {
        const int x = x1 + run.dx;
        if (inside(x, z) && f.walls[s.column(x, z)]) return false;
        missing += tile(x, z) ? 0 : 1;
      }
    return double(missing) <= may_miss;
  };
  Found out;
  const int y = f.levels.floor + 1;
  for (int cz = 0; cz <= 2 * (s.nz - 1); ++cz) {
    const int p = cz & 1, hz = cz / 2;
    for (int hx = 0; 2 * hx + p <= 2 * (s.nx - 1); ++hx)
      for (const RingOffset* o : order) {
        if (((o->dx - o->dz) & 1) != p) continue;  // the centre's parity: cx - cz is even
        const int x1 = hx + (p - o->dx + o->dz) / 2, z1 = hz + (p - o->dx - o->dz) / 2;
        if (!tile(x1, z1) || !tile(x1 + o->dx, z1 + o->dz) || !tile(x1 + o->dx - o->dz, z1 + o->dz + o->dx) ||
            !tile(x1 - o->dz, z1 + o->dx) || !valid(x1, z1, *o))
          continue;
        out.emplace_back(glm::ivec3(x1, y, z1), o->dx, o->dz);
        break;
      }
  }
  return out;
}

TEST(SquareSearch, EqualsALiteralReadingOfAlgorithm3OnAFloor) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t compared = 0;
  for (int room = 0; room < 10; ++room) {
    const int nx = 24 + int(rng() % 40), nz = 24 + int(rng() % 40);
    Room made = empty_room(nx, 8, nz, 1, 6, 1);
    const GridSpec& s = made.spec;
    RoomFeatures& f = made.features;
    std::fill(f.free_floor.begin(), f.free_floor.end(), std::uint8_t{1});
    // Walls round the room and a few inside, some cells missed by the scan, and a block of furniture: squares
    // beside walls and across gaps, the cases the search's boxes and runs decide.
    for (int z = 0; z < s.nz; ++z)
      for (int x = 0; x < s.nx; ++x) {
        const std::size_t col = s.column(x, z);
        const bool wall = x == 0 || z == 0 || x == s.nx - 1 || z == s.nz - 1 || rng() % 150 == 0;
        if (wall) f.walls[col] = 1, f.free_floor[col] = 0;
        else if (rng() % 25 == 0) f.free_floor[col] = 0;
      }
    const int bx = int(rng() % std::uint32_t(s.nx - 8)), bz = int(rng() % std::uint32_t(s.nz - 8));
    for (int z = bz; z < bz + 6; ++z)
      for (int x = bx; x < bx + 6; ++x) f.free_floor[s.column(x, z)] = 0;
    const double dominant = room % 2 == 0 ? 0.0 : unit(rng) * 90.0;
    for (const SizeRange& size : {SizeRange{4.0, 6.0}, SizeRange{9.0, 11.0}, SizeRange{14.0, 16.0}}) {
      const Found got = listed(search_squares(s, f, Surface::Floor, size, 0.95f, dominant));
      const Found want = literal_floor_squares(s, f, size, 0.95f, dominant);
      ASSERT_EQ(got.size(), want.size()) << "room " << room << ", sides from " << size.min_d;
      for (std::size_t i = 0; i < want.size(); ++i)
        ASSERT_TRUE(got[i] == want[i]) << "room " << room << ", sides from " << size.min_d << ", square " << i;
      compared += want.size();
    }
  }
  EXPECT_GE(compared, 2000u);  // the comparison means something
}

TEST(SquareSearch, ALayerIsSkippedOnlyWhereItHoldsNoSquare) {
  Room made = empty_room(96, 16, 96, 1, 14, 9);
  const GridSpec& s = made.spec;
  RoomFeatures& f = made.features;
  const auto paint = [&](glm::ivec2 lo, glm::ivec2 hi, int level) {
    for (int z = lo.y; z <= hi.y; ++z)
      for (int x = lo.x; x <= hi.x; ++x) f.furniture[s.column(x, z)] = level;
  };
  // Squares 10 to 12 voxels a side: the fewest-tiled valid one needs about 0.95 x 11² tiles; the inner box is
  // floor(2 (10 / 2 sqrt 2 - 0.5)) = 6 cells a side.
  const SizeRange range{10.0, 12.0};
  const glm::ivec2 small_lo(8, 8);
  std::size_t found_on_small = 0;
  // Tops from too small for any square to large enough for several, square and long, some with holes.
  for (int w = 6; w <= 14; ++w)
    for (int h : {w, w + 3}) {
      for (const bool holes : {false, true}) {
        std::fill(f.furniture.begin(), f.furniture.end(), kNoFurniture);
        const glm::ivec2 small_hi = small_lo + glm::ivec2(w - 1, h - 1);
        paint(small_lo, small_hi, 4);
        if (holes)
          for (int z = small_lo.y + 1; z <= small_hi.y; z += 3) f.furniture[s.column(small_lo.x + (z % w), z)] = kNoFurniture;
        const auto on_small = [&](const Candidates& found) {
          std::vector<Candidates::Item> items;
          for (std::size_t i = 0; i < found.size(); ++i) {
            const glm::ivec3 c = found[i].corner(0);
            if (c.x <= small_hi.x + 1 && c.z <= small_hi.y + 1) items.push_back(found.item(i));
          }
          return items;
        };
        const std::vector<Candidates::Item> alone = on_small(search_squares(s, f, Surface::Furniture, range, 0.95f, 0.0));
        paint({60, 60}, {90, 90}, 4);  // far from the small top in both rows and columns
        const std::vector<Candidates::Item> beside = on_small(search_squares(s, f, Surface::Furniture, range, 0.95f, 0.0));
        ASSERT_EQ(alone.size(), beside.size()) << w << " x " << h << (holes ? " with holes" : "");
        for (std::size_t i = 0; i < alone.size(); ++i) ASSERT_TRUE(alone[i] == beside[i]) << w << " x " << h;
        found_on_small += alone.size();
      }
    }
  EXPECT_GT(found_on_small, 0u);  // the tops past the rule's edge hold squares, and the rule kept them
}

}  // namespace
