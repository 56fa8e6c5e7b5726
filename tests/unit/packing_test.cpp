// SquarePacker (core/src/areas/reduce.h, internal) packs a whole analysis's squares without ranking every one
// (pack_fresh: a square whose middle sample is taken when its alignment step begins is refused without a
// contact). An IncrementalAnalysis packs through the ranked path, which ranks them all. Both must keep the same
// squares, size after size, on rooms off the grid's axes too, at any main direction.
#include "../../core/src/areas/reduce.h"
#include "../../core/src/areas/search.h"
#include "synthetic_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

}  // namespace
