// Every field of two RoomFeatures, compared: the features an IncrementalAnalysis reuses or derives again near a
// change against those derived whole.
#pragma once
#include "roomsense/features.h"

#include <gtest/gtest.h>

namespace roomsense::test {

inline void expect_same_features(const RoomFeatures& a, const RoomFeatures& b) {
  EXPECT_EQ(a.levels, b.levels);
  EXPECT_EQ(a.y_end, b.y_end);
  EXPECT_EQ(a.walls, b.walls);
  EXPECT_EQ(a.room, b.room);
  EXPECT_EQ(a.furniture, b.furniture);
  EXPECT_EQ(a.free_floor, b.free_floor);
  EXPECT_EQ(a.free_ceiling, b.free_ceiling);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.enclosed, b.enclosed);
  EXPECT_EQ(a.wall_blocked, b.wall_blocked);
  EXPECT_EQ(a.rooms.room, b.rooms.room);
  EXPECT_EQ(a.rooms.count, b.rooms.count);
  EXPECT_EQ(a.ceiling, b.ceiling);
  EXPECT_EQ(a.ceiling_facet, b.ceiling_facet);
  ASSERT_EQ(a.facets.size(), b.facets.size());
  for (std::size_t i = 0; i < a.facets.size(); ++i) {
    EXPECT_EQ(a.facets[i].level, b.facets[i].level);
    EXPECT_EQ(a.facets[i].columns, b.facets[i].columns);
    EXPECT_EQ(a.facets[i].slope_x, b.facets[i].slope_x);
    EXPECT_EQ(a.facets[i].slope_z, b.facets[i].slope_z);
    EXPECT_EQ(a.facets[i].offset, b.facets[i].offset);
  }
}

}  // namespace roomsense::test
