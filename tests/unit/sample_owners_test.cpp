// SampleOwners (core/src/areas/sample_owners.h, internal): growth's owner of each sample cell, in tiles kept in
// blocks that are added, never moved, as the areas grow past the tiles reserved for them. Checked against a
// plain map on cells spread over many more tiles than were reserved, on both tile shapes; `lower`, which a replay's
// growth uses to mark areas out of order, against the lowest value per cell; `lower_box` against `lower` of each
// of its cells; finds through cursors (one per run of reads, as growth keeps one per depth) against plain finds
// while tiles are made between and among them.
#include "../../core/src/areas/sample_owners.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <tuple>

namespace {

using roomsense::detail::SampleOwners;

void expect_same_as_a_map(glm::ivec3 shift, std::size_t reserved, int span) {
  SampleOwners owners(shift);
  owners.reserve(reserved);
  std::map<std::tuple<int, int, int>, std::uint32_t> first;
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(-span, span);
  for (std::uint32_t value = 0; value < 200000; ++value) {
    const glm::ivec3 cell(coordinate(random), coordinate(random) / 8, coordinate(random));
    owners.insert(cell, value);
    first.try_emplace({cell.x, cell.y, cell.z}, value);  // the first owner stays, as insert keeps it
    if (value == 1000) owners.reserve(1);                 // too late to change the blocks: ignored for their size
  }
  for (const auto& [cell, value] : first) {
    const glm::ivec3 c(std::get<0>(cell), std::get<1>(cell), std::get<2>(cell));
    ASSERT_EQ(owners.find(c), value) << c.x << " " << c.y << " " << c.z;
    EXPECT_EQ(owners.find(c + glm::ivec3(0, 2 * span, 0)), SampleOwners::kAbsent);  // never inserted
  }
}

TEST(SampleOwners, KeepsEachCellsFirstOwnerAcrossBlocksAddedAsTheyGrow) {
  expect_same_as_a_map(glm::ivec3(3, 0, 3), 4, 300);   // flat tiles, 16-tile blocks: thousands of tiles
  expect_same_as_a_map(glm::ivec3(2, 2, 2), 64, 120);  // cubes
  expect_same_as_a_map(glm::ivec3(3, 0, 3), 100000, 40);  // more reserved than used: one block
}

TEST(SampleOwners, LowerLeavesEachCellsLowestOwnerWhateverTheOrder) {
  SampleOwners owners(glm::ivec3(3, 0, 3));
  std::map<std::tuple<int, int, int>, std::uint32_t> lowest;
  std::mt19937 random(11);
  std::uniform_int_distribution<int> coordinate(-60, 60);
  std::uniform_int_distribution<std::uint32_t> any_value(0, 5000);
  for (int n = 0; n < 50000; ++n) {
    const glm::ivec3 cell(coordinate(random), coordinate(random) / 8, coordinate(random));
    const std::uint32_t value = any_value(random);
    owners.lower(cell, value);
    const auto [it, added] = lowest.try_emplace({cell.x, cell.y, cell.z}, value);
    if (!added) it->second = std::min(it->second, value);
  }
  for (const auto& [cell, value] : lowest)
    ASSERT_EQ(owners.find(glm::ivec3(std::get<0>(cell), std::get<1>(cell), std::get<2>(cell))), value);
}

TEST(SampleOwners, LowerBoxIsLowerOfEachOfItsCells) {
  for (const glm::ivec3 shift : {glm::ivec3(3, 0, 3), glm::ivec3(2, 2, 2)}) {
    SampleOwners boxes(shift), cells(shift);
    std::mt19937 random(13);
    std::uniform_int_distribution<int> corner(-40, 40), extent(0, 19), any_value(0, 300);
    for (int n = 0; n < 300; ++n) {  // boxes across tiles' borders, below zero and above, overlapping
      const glm::ivec3 lo(corner(random), corner(random) / 8, corner(random));
      const glm::ivec3 hi = lo + glm::ivec3(extent(random), extent(random) / 8, extent(random));
      const auto value = std::uint32_t(any_value(random));
      boxes.lower_box(lo, hi, value);
      for (int x = lo.x; x <= hi.x; ++x)
        for (int y = lo.y; y <= hi.y; ++y)
          for (int z = lo.z; z <= hi.z; ++z) cells.lower(glm::ivec3(x, y, z), value);
    }
    for (int x = -45; x <= 65; ++x)  // every cell a box may reach, and a margin no box does
      for (int y = -8; y <= 10; ++y)
        for (int z = -45; z <= 65; ++z)
          ASSERT_EQ(boxes.find(glm::ivec3(x, y, z)), cells.find(glm::ivec3(x, y, z))) << x << " " << y << " " << z;
  }
}

TEST(SampleOwners, CursorsFindWhatPlainFindsDoWhileTilesAreMade) {
  // Three cursors, each reading its own run of cells (as growth's depths do), each run near its cursor's last
  // cell; between reads cells are owned, some in tiles a cursor last found missing.
  SampleOwners owners(glm::ivec3(2, 2, 2));
  std::array<SampleOwners::Cursor, 3> cursors;
  std::array<glm::ivec3, 3> at = {glm::ivec3(0), glm::ivec3(0, 8, 0), glm::ivec3(0, -8, 0)};
  std::mt19937 random(17);
  std::uniform_int_distribution<int> step(-1, 2), which(0, 2), coin(0, 3);
  std::size_t missing_then_owned = 0;
  for (std::uint32_t value = 0; value < 20000; ++value) {
    const std::size_t d = std::size_t(which(random));
    at[d] += glm::ivec3(step(random), 0, step(random) / 2);
    const std::uint32_t found = owners.find(at[d], cursors[d]);
    ASSERT_EQ(found, owners.find(at[d])) << value;
    if (coin(random) == 0) {  // a cell ahead of some cursor: often in a tile that cursor found missing
      const glm::ivec3 ahead = at[std::size_t(which(random))] + glm::ivec3(1, 0, 0);
      const bool was_missing = owners.find(ahead) == SampleOwners::kAbsent;
      owners.insert(ahead, value);
      for (std::size_t k = 0; k < cursors.size(); ++k) {
        const std::uint32_t seen = owners.find(ahead, cursors[k]);
        ASSERT_EQ(seen, owners.find(ahead)) << value << " cursor " << k;
        missing_then_owned += was_missing && seen == value;
        ASSERT_EQ(owners.find(at[k], cursors[k]), owners.find(at[k])) << value << " cursor " << k;
      }
    }
  }
  EXPECT_GT(missing_then_owned, 100u);  // the case a cursor's memory of a missing tile must not hide
}

}  // namespace
