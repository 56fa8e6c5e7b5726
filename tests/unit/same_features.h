// Parts of two analyses compared field by field: every field of two RoomFeatures (the features an
// IncrementalAnalysis reuses or derives again near a change against those derived whole), and the bounds meshes.
#pragma once
#include "roomsense/analysis.h"
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

// The bounds mesh and each room's, vertex for vertex and index for index.
inline void expect_same_bounds(const AnalysisResult& got, const AnalysisResult& want) {
  EXPECT_EQ(got.bounds.vertices, want.bounds.vertices);
  EXPECT_EQ(got.bounds.indices, want.bounds.indices);
  ASSERT_EQ(got.room_bounds.size(), want.room_bounds.size());
  for (std::size_t i = 0; i < got.room_bounds.size(); ++i) {
    EXPECT_EQ(got.room_bounds[i].vertices, want.room_bounds[i].vertices);
    EXPECT_EQ(got.room_bounds[i].indices, want.room_bounds[i].indices);
  }
}

}  // namespace roomsense::test
