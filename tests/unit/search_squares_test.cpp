// search_squares (core/src/areas/search_squares.cpp, internal) skips a layer of several (furniture's levels) where
// no centre can hold a square: where no run of rows (or of columns) as long as a square's cells span holds the tiles
// the fewest-tiled valid square needs (Eq. 3.30-3.38: all but the cells its fill may miss), or no run as long as the
// inner box every square holds spans holds that box's. Skipping must never lose a square: a top is searched alone,
// where the rule may skip its layer, and beside a large top at the same level far off, which keeps every run full
// and the layer searched; the small top's squares must be the same in both.
#include "../../core/src/areas/search.h"

#include "roomsense/features.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

using namespace roomsense;
using namespace roomsense::detail;

TEST(SquareSearch, ALayerIsSkippedOnlyWhereItHoldsNoSquare) {
  GridSpec s;
  s.nx = 96, s.ny = 16, s.nz = 96;
  s.voxel_size = 0.1f;
  RoomFeatures f;
  f.levels.floor = 1, f.levels.ceiling = 14, f.y_end = 9;
  f.walls.assign(s.column_count(), 0);
  f.normals.assign(s.voxel_count(), 0);
  f.free_floor.assign(s.column_count(), 0);
  f.furniture.assign(s.column_count(), kNoFurniture);
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
