// The order and parallelism of §3.2: levels, then A and B, then C/D/E in parallel, then F (needs C). Beyond the
// thesis: A without free-standing furniture before B, the room's inside after it, the runtime's labels on C and D,
// and the wall openings after F.
#include "roomsense/features.h"
#include "roomsense/cancel.h"
#include "../parallel.h"

#include <algorithm>
#include <cmath>

namespace roomsense {

RoomFeatures detect_features(const VoxelStageResult& voxels, const FeatureParams& params, unsigned threads,
                             const std::stop_token& stop, const LabelGrid& labels) {
  return detect_features(voxels.grid, voxels.levels.value(), voxels.column_counts, voxels.column_any, params,
                         threads, stop, labels);
}

RoomFeatures detect_features(const VoxelGrid& grid, const FloorCeiling& levels,
                             const std::vector<std::uint32_t>& column_counts,
                             const std::vector<std::uint8_t>& column_any, const FeatureParams& params,
                             unsigned threads, const std::stop_token& stop, const LabelGrid& labels) {
  check_params(params);
  const float s = grid.spec.voxel_size;
  RoomFeatures f;
  f.levels = levels;
  f.y_end = f.levels.floor + voxels_for(params.furniture_top, s);
  f.room = detect_room(grid.spec, column_any);
  // B counts voxels from I_Floor up; a floor that spans two levels (select_floor_ceiling) has part of its scan
  // in the level below, and those columns are room too.
  for (std::size_t c = 0; c < f.room.size(); ++c) {
    const std::uint8_t* v = grid.cells.data() + c * std::size_t(grid.spec.ny);
    if (!f.room[c]) f.room[c] = std::any_of(v + f.levels.floor_peak, v + f.levels.floor, [](std::uint8_t x) { return x != 0; });
  }
  f.ceiling = column_ceilings(grid, f.levels, f.room, f.levels.ceiling);
  const std::size_t facet_columns = std::size_t(std::max(1.0f, std::ceil(params.min_ceiling_facet / (s * s) - 1e-3f)));
  const std::vector<int> over_walls = wall_ceilings(grid.spec, f.levels, f.ceiling, f.room, 2, facet_columns);
  f.walls = detect_walls(grid.spec, column_counts, f.levels, over_walls, params.wall_fill);
  drop_free_standing(grid, f.levels, over_walls, voxels_for(params.wall_top_gap, s), f.walls);
  const int max_opening = voxels_for(params.max_opening, s);
  f.enclosed = detect_enclosed(grid.spec, f.walls, f.room, max_opening);
  cut_at_labelled_walls(grid.spec, f.levels, f.y_end, labels, f.room, f.enclosed);
  // Areas stay inside: the later steps see B cut to the inside (bounds keep B itself).
  const std::vector<std::uint8_t> inside = room_inside(grid.spec, f.room, f.enclosed);
  stop_point(stop);

  const int furniture_clear = voxels_for(params.furniture_clear, s);
  const int ceiling_clear = voxels_for(params.ceiling_clear, s);
  const int rough = voxels_for(params.floor_roughness, s);
  // Free floor needs the headroom a furniture top needs (Eq. 3.13's clear space).
  const auto floor = [&] {
    return detect_free_floor(grid, f.levels, f.ceiling, f.y_end, f.walls, inside, rough, furniture_clear);
  };
  const auto ceiling = [&] {
    std::vector<std::uint8_t> tiles = detect_free_ceiling(grid, f.ceiling, ceiling_clear, f.walls, inside);
    find_ceiling_facets(grid.spec, f.levels, f.ceiling, tiles, facet_columns, f.ceiling_facet, f.facets);
    for (std::size_t c = 0; c < tiles.size(); ++c)
      if (f.ceiling_facet[c] == kNoFacet) tiles[c] = 0;
    return tiles;
  };
  detail::parallel_tasks(3, threads, [&](std::size_t task) {
    if (task == 0) f.furniture = detect_furniture(grid, f.levels, f.ceiling, f.y_end, f.walls, furniture_clear, rough);
    if (task == 1) f.free_ceiling = ceiling();
    if (task == 2) f.free_floor = floor();
  });
  for (std::size_t c = 0; c < inside.size(); ++c)
    if (!inside[c]) f.furniture[c] = kNoFurniture;
  apply_furniture_labels(grid.spec, f.levels, labels, f.free_floor, f.furniture);
  stop_point(stop);
  // F, the rooms and the openings read what is above and not each other: side by side.
  detail::parallel_tasks(3, threads, [&](std::size_t task) {
    if (task == 0)
      f.normals = detect_wall_normals(grid, f.levels, f.ceiling, voxels_for(params.wall_normal_reach, s), f.walls,
                                      inside, f.furniture);
    if (task == 1) f.rooms = split_rooms(grid.spec, inside, f.walls, params.min_passage, params.min_room_area);
    if (task == 2)
      f.wall_blocked = detect_wall_openings(grid, f.levels, f.walls, inside, voxels_for(params.wall_recess, s),
                                            max_opening, labels);
  });
  return f;
}

}  // namespace roomsense
