// The order and parallelism of §3.2: levels, then A and B, then C/D/E in parallel, then F (needs C).
#include "roomsense/features.h"
#include "roomsense/cancel.h"

#include <future>

namespace roomsense {

RoomFeatures detect_features(const VoxelStageResult& voxels, const FeatureParams& params, unsigned threads,
                             const std::stop_token& stop) {
  const VoxelGrid& grid = voxels.grid;
  const float s = grid.spec.voxel_size;
  RoomFeatures f;
  f.levels = voxels.levels.value();
  f.y_end = f.levels.floor + voxels_for(params.furniture_top, s);
  f.walls = detect_walls(grid.spec, voxels.column_counts, f.levels, params.wall_fill);
  f.room = detect_room(grid.spec, voxels.column_any);
  stop_point(stop);

  const int furniture_clear = voxels_for(params.furniture_clear, s);
  const int ceiling_clear = voxels_for(params.ceiling_clear, s);
  if (threads == 1) {
    f.furniture = detect_furniture(grid, f.levels, f.y_end, f.walls, furniture_clear);
    f.free_floor = detect_free_floor(grid, f.levels, f.y_end, f.walls, f.room);
    f.free_ceiling = detect_free_ceiling(grid, f.levels, ceiling_clear, f.walls, f.room);
  } else {
    auto furniture = std::async(std::launch::async, [&] {
      return detect_furniture(grid, f.levels, f.y_end, f.walls, furniture_clear);
    });
    auto ceiling = std::async(std::launch::async, [&] {
      return detect_free_ceiling(grid, f.levels, ceiling_clear, f.walls, f.room);
    });
    f.free_floor = detect_free_floor(grid, f.levels, f.y_end, f.walls, f.room);
    f.furniture = furniture.get();
    f.free_ceiling = ceiling.get();
  }
  stop_point(stop);
  f.normals = detect_wall_normals(grid, f.levels, voxels_for(params.wall_normal_reach, s), f.walls, f.room,
                                  f.furniture);
  return f;
}

}  // namespace roomsense
