// Room features of thesis §3.2: walls A (Eq. 3.11), room mask B (Eq. 3.12), furniture levels C (Eq. 3.13),
// free floor and ceiling tiles D and E (Eq. 3.14/3.15), wall normals F (Alg. 1).
#pragma once
#include "roomsense/grid.h"
#include "roomsense/voxelize.h"

#include <cstdint>
#include <stop_token>
#include <vector>

namespace roomsense {

// The thesis's constants, in metres (DESIGN.md's table). Converted to voxels with voxels_for().
struct FeatureParams {
  float min_floor_ceiling = 1.5f;  // Eq. 3.9/3.10: floor-ceiling separation
  float wall_fill = 0.5f;          // Eq. 3.11: share of [floor, ceiling] a wall column fills (strictly more)
  float furniture_top = 1.5f;      // Eq. 3.13: I_yEnd, furniture tops up to this height (also free floor)
  float furniture_clear = 1.0f;    // Eq. 3.13: clear space above a furniture top
  float ceiling_clear = 1.0f;      // Eq. 3.15: clear space below a free ceiling tile
  float wall_normal_reach = 1.0f;  // Eq. 3.19: I_Bounds
};

// ⌊metres / S_Voxel⌋, robust to the float error of e.g. 1.5 / 0.1.
int voxels_for(float metres, float voxel_size);

// Bits of F (Eq. 3.17).
enum WallNormalBits : std::uint8_t {
  kNormalLeft = 1,      // (-1, 0, 0)
  kNormalRight = 2,     // (+1, 0, 0)
  kNormalForward = 4,   // (0, 0, +1)
  kNormalBackward = 8,  // (0, 0, -1)
};

inline constexpr int kNoFurniture = -1;

struct RoomFeatures {
  FloorCeiling levels;
  int y_end = 0;                         // I_yEnd = I_Floor + ⌊1.5 / S⌋
  std::vector<std::uint8_t> walls;       // A, per column
  std::vector<std::uint8_t> room;        // B, per column
  std::vector<int> furniture;            // C, per column: the level above a furniture top, or kNoFurniture
  std::vector<std::uint8_t> free_floor;  // D, per column
  std::vector<std::uint8_t> free_ceiling;  // E, per column
  std::vector<std::uint8_t> normals;     // F, per voxel (GridSpec::index), WallNormalBits
};

std::vector<std::uint8_t> detect_walls(const GridSpec& spec, const std::vector<std::uint32_t>& column_counts,
                                       const FloorCeiling& levels, float wall_fill);
std::vector<std::uint8_t> detect_room(const GridSpec& spec, const std::vector<std::uint8_t>& column_any);
std::vector<int> detect_furniture(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                                  const std::vector<std::uint8_t>& walls, int clear_levels);
std::vector<std::uint8_t> detect_free_floor(const VoxelGrid& grid, const FloorCeiling& levels, int y_end,
                                            const std::vector<std::uint8_t>& walls,
                                            const std::vector<std::uint8_t>& room);
std::vector<std::uint8_t> detect_free_ceiling(const VoxelGrid& grid, const FloorCeiling& levels, int clear_levels,
                                              const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room);
std::vector<std::uint8_t> detect_wall_normals(const VoxelGrid& grid, const FloorCeiling& levels, int reach,
                                              const std::vector<std::uint8_t>& walls,
                                              const std::vector<std::uint8_t>& room,
                                              const std::vector<int>& furniture);

// All of §3.2 on a voxel stage's result that found a floor and a ceiling. C, D and E run in parallel
// when threads allows; the result does not depend on the thread count.
// A stop request throws Error(Cancelled) between the steps.
RoomFeatures detect_features(const VoxelStageResult& voxels, const FeatureParams& params, unsigned threads = 0,
                             const std::stop_token& stop = {});

}  // namespace roomsense
