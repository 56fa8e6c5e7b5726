// The order and parallelism of §3.2: levels, then A and B, then C/D/E in parallel, then F (needs C). Beyond the
// thesis: A without free-standing furniture before B, the room's inside after it, the runtime's labels on C and D,
// and the wall openings after F.
#include "column_steps.h"
#include "feature_memo.h"
#include "roomsense/features.h"
#include "roomsense/cancel.h"
#include "../parallel.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

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
  return detail::detect_features(grid, levels, column_counts, column_any, params, threads, stop, labels, nullptr, {},
                                 nullptr);
}

namespace detail {
namespace {

// derive() through `step`'s memo where there is one.
template <class Step, class Derive, class... Inputs>
auto through(Step* step, const Derive& derive, const Inputs&... inputs) {
  return step != nullptr ? step->get(derive, inputs...) : derive();
}

// `step` of every column into `out` where `redo` is null (on up to `threads` threads), else of the columns it lists.
template <class Value, class Step>
void derive_columns(std::vector<Value>& out, std::size_t columns, const std::vector<std::uint32_t>* redo,
                    const Step& step, unsigned threads) {
  if (redo == nullptr) out = every_column<Value>(columns, step, threads);
  else
    for (const std::uint32_t col : *redo) out[col] = step(col);
}

}  // namespace

RoomFeatures detect_features(const VoxelGrid& grid, const FloorCeiling& levels,
                             const std::vector<std::uint32_t>& column_counts,
                             const std::vector<std::uint8_t>& column_any, const FeatureParams& params,
                             unsigned threads, const std::stop_token& stop, const LabelGrid& labels,
                             FeatureMemo* memo, const GridChange& change, const RoomFeatures* previous,
                             bool area_features) {
  check_params(params);
  area_features = area_features || memo != nullptr;  // a memo keeps every step's inputs
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
  f.ceiling = column_ceilings(grid, f.levels, f.room, f.levels.ceiling, memo ? &memo->ceilings : nullptr, change);
  const std::size_t facet_columns = std::size_t(std::max(1.0f, std::ceil(params.min_ceiling_facet / (s * s) - 1e-3f)));
  const std::vector<int> over_walls = through(
      memo ? &memo->over_walls : nullptr,
      [&] { return wall_ceilings(grid.spec, f.levels, f.ceiling, f.room, 2, facet_columns); }, grid.spec, f.levels,
      f.ceiling, f.room, facet_columns);
  f.walls = detect_walls(grid.spec, column_counts, f.levels, over_walls, params.wall_fill);
  drop_free_standing(grid, f.levels, over_walls, voxels_for(params.wall_top_gap, s), f.walls);
  const int max_opening = voxels_for(params.max_opening, s);
  f.enclosed = through(
      memo ? &memo->enclosed : nullptr, [&] { return detect_enclosed(grid.spec, f.walls, f.room, max_opening); },
      grid.spec, f.walls, f.room, max_opening);
  cut_at_labelled_walls(grid.spec, f.levels, f.y_end, labels, f.room, f.enclosed);
  // Areas stay inside: the later steps see B cut to the inside (bounds keep B itself).
  const std::vector<std::uint8_t> inside = room_inside(grid.spec, f.room, f.enclosed);
  stop_point(stop);

  const int furniture_clear = voxels_for(params.furniture_clear, s);
  const int ceiling_clear = voxels_for(params.ceiling_clear, s);
  const int rough = voxels_for(params.floor_roughness, s);
  // C, D and E decide each column from its own voxels and entries (column_steps.h): through the memo, only the
  // columns where those changed since the grid it read, at the same levels and parameters.
  ColumnSteps fresh;
  ColumnSteps& steps = memo ? memo->columns : fresh;
  const std::optional<std::vector<std::uint32_t>> changed =
      memo ? steps.inputs.begin(change, {grid.spec, f.levels, f.y_end, furniture_clear, ceiling_clear, rough}, f.walls,
                                inside, f.ceiling)
           : std::nullopt;
  const std::vector<std::uint32_t>* redo = changed ? &*changed : nullptr;
  const std::size_t columns = inside.size();
  // Free floor needs the headroom a furniture top needs (Eq. 3.13's clear space).
  const auto floor = [&] {
    derive_columns(steps.free_floor, columns, redo,
                   FreeFloorTile(grid, f.levels, f.ceiling, f.y_end, f.walls, inside, rough, furniture_clear), threads);
    return memo ? steps.free_floor : std::move(steps.free_floor);
  };
  const auto ceiling = [&] {
    derive_columns(steps.free_ceiling, columns, redo, FreeCeilingTile(grid, f.ceiling, ceiling_clear, f.walls, inside),
                   threads);
    std::vector<std::uint8_t> tiles = memo ? steps.free_ceiling : std::move(steps.free_ceiling);
    CeilingFacets found = through(
        memo ? &memo->facets : nullptr,
        [&] {
          CeilingFacets out;
          find_ceiling_facets(grid.spec, f.levels, f.ceiling, tiles, facet_columns, out.facet_of, out.facets);
          return out;
        },
        grid.spec, f.levels, f.ceiling, tiles, facet_columns);
    f.ceiling_facet = std::move(found.facet_of);
    f.facets = std::move(found.facets);
    for (std::size_t c = 0; c < tiles.size(); ++c)
      if (f.ceiling_facet[c] == kNoFacet) tiles[c] = 0;
    return tiles;
  };
  // The rooms read the inside and the walls alone: beside C, D and E (a large storey's split is as long as the
  // three together), first, so that one thread takes it while the other takes the column steps' slices.
  // Without the areas' features: the rooms and E (whose facets the ceiling's height and planes read) alone.
  static constexpr std::size_t kEveryTask[] = {0, 1, 2, 3}, kBoundsTasks[] = {0, 2};
  const std::span<const std::size_t> tasks = area_features ? std::span<const std::size_t>(kEveryTask) : kBoundsTasks;
  detail::parallel_tasks(tasks.size(), threads, [&](std::size_t i) {
    const std::size_t task = tasks[i];
    if (task == 0)
      f.rooms = through(
          memo ? &memo->rooms : nullptr,
          [&] { return split_rooms(grid.spec, inside, f.walls, params.min_passage, params.min_room_area); },
          grid.spec, inside, f.walls, params.min_passage, params.min_room_area);
    if (task == 1) {
      derive_columns(steps.furniture, columns, redo,
                     FurnitureTop(grid, f.levels, f.ceiling, f.y_end, f.walls, furniture_clear, rough), threads);
      f.furniture = memo ? steps.furniture : std::move(steps.furniture);
    }
    if (task == 2) f.free_ceiling = ceiling();
    if (task == 3) f.free_floor = floor();
  });
  steps.inputs.done(change);
  if (!area_features) return f;
  for (std::size_t c = 0; c < inside.size(); ++c)
    if (!inside[c]) f.furniture[c] = kNoFurniture;
  apply_furniture_labels(grid.spec, f.levels, labels, f.free_floor, f.furniture);
  stop_point(stop);
  // F through the memo: the previous analysis's, derived again where a wall's run reads a column whose voxels or
  // entries changed.
  const auto normals = [&] {
    const int reach = voxels_for(params.wall_normal_reach, s);
    const auto whole = [&] { return detect_wall_normals(grid, f.levels, f.ceiling, reach, f.walls, inside, f.furniture); };
    if (!memo) return whole();
    NormalSteps& kept = memo->normals;
    const std::optional<std::vector<std::uint32_t>> again =
        kept.inputs.begin(change, {grid.spec, f.levels, reach}, f.walls, inside, f.ceiling, f.furniture);
    std::vector<std::uint8_t> out;
    if (again && previous != nullptr && previous->normals.size() == grid.spec.voxel_count()) {
      out = previous->normals;
      update_wall_normals(grid, f.levels, f.ceiling, reach, f.walls, inside, f.furniture, *again, out);
    } else {
      out = whole();
    }
    kept.inputs.done(change);
    return out;
  };
  // The openings through the memo: the previous analysis's, derived again near a column whose voxels or inside
  // changed.
  const auto openings = [&] {
    const int recess = voxels_for(params.wall_recess, s);
    const auto whole = [&] { return detect_wall_openings(grid, f.levels, f.walls, inside, recess, max_opening, labels); };
    if (!memo) return whole();
    OpeningSteps& kept = memo->openings;
    const std::optional<std::vector<std::uint32_t>> again = kept.inputs.begin(
        change, {grid.spec, f.levels, recess, max_opening, f.walls, labels.present, labels.masks}, inside);
    std::vector<std::uint8_t> out;
    if (again && previous != nullptr &&
        (previous->wall_blocked.empty() || previous->wall_blocked.size() == grid.spec.voxel_count())) {
      out = previous->wall_blocked;
      update_wall_openings(grid, f.levels, f.walls, inside, recess, max_opening, labels, *again, out);
    } else {
      out = whole();
    }
    kept.inputs.done(change);
    return out;
  };
  // F and the openings read what is above and not each other: side by side.
  detail::parallel_tasks(2, threads, [&](std::size_t task) {
    if (task == 0) f.normals = normals();
    if (task == 1) f.wall_blocked = openings();
  });
  return f;
}

}  // namespace detail
}  // namespace roomsense
