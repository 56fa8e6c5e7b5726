// What RoomQueries answers from (queries.h): the analysis's voxel grid and features, read once into rasters the
// queries look up in constant time. Internal to core.
#pragma once
#include "roomsense/queries.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace roomsense {

// One wall segment's free surface (a wall Surface of extract_surfaces) as a raster on its plane: u runs along
// x_axis from `start`, one cell per voxel; row v is grid level level0 + v. A cell is free where the voxel in front
// of the wall there carries a wall normal F (Alg. 1) facing the segment's way and no opening blocks it
// (RoomFeatures::wall_blocked); `depth` is the clear space in front of it, metres from the wall's plane.
struct WallFace {
  glm::vec3 start{0.0f};  // on the wall's plane, at u = 0, y = 0
  glm::vec3 x_axis{1.0f, 0.0f, 0.0f}, normal{0.0f, 0.0f, 1.0f};
  int nu = 0, nv = 0, level0 = 0;
  std::vector<float> depth;  // nu * nv, v-major (v * nu + u); 0 where not free
  std::uint32_t storey = 0;
};

struct RoomQueries::Index {
  GridSpec spec;
  std::vector<std::uint8_t> cells;     // V (Eq. 3.7), GridSpec::index
  FloorCeiling levels;
  float floor_y = 0.0f, ceiling_y = 0.0f;
  float close_distance = 0.0f, close_height = 0.0f;  // AreaParams' defaults (§3.5.1)
  double dominant_deg = 0.0;           // the longest wall's direction, mod 90°: footprints follow it first

  // Per column (GridSpec::column).
  std::vector<std::uint8_t> inside;    // within the room's walls (room_inside of B and the enclosure)
  std::vector<std::uint8_t> walls;     // A (Eq. 3.11)
  // Clear space along the normal above free floor D, above a furniture top C, below free ceiling E (metres);
  // negative where the column has no such surface.
  std::vector<float> floor_clear, top_clear, ceiling_clear;
  std::vector<int> top_level;          // C: the level above the top, or kNoFurniture
  std::vector<std::int32_t> top_region;  // one id per connected furniture top (levels within 1), or -1
  std::vector<float> stand_distance;   // metres from the column's centre to the nearest free floor column's

  std::vector<WallFace> faces;
  // Surface cells for random points: columns with free floor, free ceiling, a furniture top; (face, cell) pairs.
  std::vector<std::uint32_t> floor_cells, ceiling_cells, top_cells, inside_cells;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> wall_cells;

  float top_y(int level) const { return spec.origin.y + float(level) * spec.voxel_size; }
  bool solid(int x, int y, int z) const;  // a scanned voxel, or outside the room (the ray's and clearance's view)
};

// Is the voxel at (x, y, z) outside the room's free space: outside the grid, a column outside the room, at or
// below I_Floor, at or above I_Ceiling? Occupied voxels are checked apart (Index::cells).
inline bool outside_room(const RoomQueries::Index& ix, int x, int y, int z) {
  if (x < 0 || z < 0 || x >= ix.spec.nx || z >= ix.spec.nz) return true;
  return !ix.inside[ix.spec.column(x, z)] || y <= ix.levels.floor || y >= ix.levels.ceiling;
}

inline bool RoomQueries::Index::solid(int x, int y, int z) const {
  return outside_room(*this, x, y, z) || cells[spec.index(x, y, z)] != 0;
}

}  // namespace roomsense
