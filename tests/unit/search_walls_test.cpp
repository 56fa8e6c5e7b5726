// search_walls (core/src/areas/search_walls.cpp, internal) against a literal reading of Alg. 2 (Eq. 3.20-3.27):
// every first corner in the search's order, every ring offset in the ring's, the second corner's normal compatible,
// the first rectangle of each centre kept, and Eq. 3.25 tested cell by cell over the cells its top covers
// (RingOffset::runs): none in a wall column or before an opening, and enough voxels with a normal, a cell past the
// grid's edge lacking every one. The search reads those cells by runs along z or along x, by bit rows and counts;
// the lists must be equal, item for item, on rooms with walls at many angles.
#include "../../core/src/areas/ring_offsets.h"
#include "../../core/src/areas/search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace {

using namespace roomsense;
using namespace roomsense::detail;

Candidates literal_walls(const GridSpec& s, const RoomFeatures& f, const SizeRange& size, float fill) {
  const std::vector<RingOffset> ring = ring_offsets(size, Shape::WallTop);
  const int floor = f.levels.floor;
  const int ceiling = std::min(f.levels.ceiling, s.ny - 1);
  std::vector<Candidates::Shape> shapes;
  for (const RingOffset& o : ring) shapes.push_back({o.dx, o.dz, size.wall_height(o.d)});
  Candidates out(s, s.ny, shapes);
  const auto normal = [&](int x, int y, int z) { return f.normals[s.index(x, y, z)]; };
  const auto valid = [&](int x1, int y1, int z1, std::size_t r) {
    const RingOffset& o = ring[r];
    const int h = shapes[r].side, bottom = std::max(y1 - h, floor);
    const double need = double(fill) * (std::floor(o.d) + 1.0) * double(h + 1);
    long with_normal = 0;
    for (const CellRun& run : o.runs)
      for (int z = z1 + run.dz_lo; z <= z1 + run.dz_hi; ++z) {
        const int x = x1 + run.dx;
        if (z < 0 || z >= s.nz) continue;  // lacks every voxel (a top between corners in the grid never reaches it)
        if (f.walls[s.column(x, z)]) return false;
        for (int y = bottom; y <= y1; ++y) {
          if (!f.wall_blocked.empty() && f.wall_blocked[s.index(x, y, z)]) return false;
          with_normal += normal(x, y, z) != 0 ? 1 : 0;
        }
      }
    return double(long(o.cells) * (y1 - bottom + 1) - with_normal) <= double(long(o.cells) * (y1 - bottom + 1)) - need;
  };
  std::set<std::tuple<int, int, int>> centres;
  const int y_first = floor + int(std::floor(size.min_d * size.height_ratio));
  for (int z1 = 0; z1 < s.nz; ++z1)
    for (int x1 = 0; x1 < s.nx; ++x1)
      for (int y1 = std::max(y_first, floor); y1 <= ceiling; ++y1) {
        const std::uint8_t f1 = normal(x1, y1, z1);
        if (f1 == 0) continue;
        for (std::size_t r = 0; r < ring.size(); ++r) {
          const int x2 = x1 + ring[r].dx, z2 = z1 + ring[r].dz;
          if (x2 >= s.nx || z2 < 0 || z2 >= s.nz || (normal(x2, y1, z2) & compatible_normals(f1)) == 0) continue;
          const std::tuple<int, int, int> centre(2 * x1 + ring[r].dx, 2 * y1 - shapes[r].side, 2 * z1 + ring[r].dz);
          if (centres.count(centre) || !valid(x1, y1, z1, r)) continue;
          centres.insert(centre);
          out.push_back({x1, y1, z1}, std::uint32_t(r));
        }
      }
  return out;
}

// A room of nx x nz columns with walls round it, and panels of normals at random angles, some through the grid's
// edge, some with gaps; beside the panels, a few wall columns (no rectangle may hold one) and blocked voxels.
RoomFeatures random_room(const GridSpec& s, std::mt19937& rng) {
  RoomFeatures f;
  f.levels.floor = 1, f.levels.ceiling = s.ny - 2;
  f.walls.assign(s.column_count(), 0);
  f.normals.assign(s.voxel_count(), 0);
  f.wall_blocked.assign(s.voxel_count(), 0);
  const auto paint = [&](double x0, double z0, double angle, double length, int top, std::uint8_t n, bool gaps) {
    for (double t = 0.0; t <= length; t += 0.25) {
      const int x = int(std::floor(x0 + t * std::cos(angle))), z = int(std::floor(z0 + t * std::sin(angle)));
      if (x < 0 || z < 0 || x >= s.nx || z >= s.nz || (gaps && int(t) % 9 == 4)) continue;
      for (int y = 1; y <= top; ++y) f.normals[s.index(x, y, z)] |= n;
      if (rng() % 97 == 0) f.walls[s.column(x, z)] = 1;
      if (rng() % 61 == 0) f.wall_blocked[s.index(x, 1 + int(rng() % std::uint32_t(top)), z)] = 1;
    }
  };
  const int top = s.ny - 2;
  paint(0, 0, 0.0, s.nx - 1, top, kNormalForward, false);
  paint(0, s.nz - 1, 0.0, s.nx - 1, top, kNormalBackward, false);
  paint(0, 0, std::numbers::pi / 2, s.nz - 1, top, kNormalRight, false);
  paint(s.nx - 1, 0, std::numbers::pi / 2, s.nz - 1, top, kNormalLeft, false);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::uint8_t normals[] = {kNormalLeft, kNormalRight, kNormalForward, kNormalBackward};
  for (int k = 0; k < 10; ++k)
    paint(unit(rng) * s.nx, unit(rng) * s.nz, unit(rng) * 2.0 * std::numbers::pi, 8.0 + unit(rng) * 30.0,
          2 + int(rng() % std::uint32_t(top - 1)), normals[rng() % 4], rng() % 2 == 0);
  return f;
}

TEST(WallSearch, EqualsALiteralReadingOfAlgorithm2) {
  std::mt19937 rng(19);
  std::size_t compared = 0;
  for (int room = 0; room < 12; ++room) {
    GridSpec s;
    // Under 32 z the search tests second corners one by one, from 32 on by bit rows.
    s.nx = 24 + int(rng() % 40), s.ny = 8 + int(rng() % 6), s.nz = room % 3 == 0 ? 20 + int(rng() % 10) : 32 + int(rng() % 60);
    s.voxel_size = 0.1f;
    const RoomFeatures f = random_room(s, rng);
    const NormalCounts normals = count_normals(s, f);
    // The last size's ring spans over 64 z: its second corners are read from two windows a column.
    for (const SizeRange& size : {SizeRange{4.0, 6.0, 0.5}, SizeRange{8.0, 12.0, 0.5}, SizeRange{14.5, 21.5, 0.45},
                                  SizeRange{30.0, 34.0, 0.2}}) {
      const Candidates got = search_walls(s, f, normals, size, 0.8f);
      const Candidates want = literal_walls(s, f, size, 0.8f);
      ASSERT_EQ(got.size(), want.size()) << "room " << room << ", sizes from " << size.min_d;
      for (std::size_t i = 0; i < want.size(); ++i)
        ASSERT_TRUE(got.item(i) == want.item(i)) << "room " << room << ", sizes from " << size.min_d << ", rectangle " << i;
      compared += want.size();
    }
  }
  EXPECT_GE(compared, 2000u);  // the comparison means something
}

}  // namespace
