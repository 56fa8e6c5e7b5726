// §3.3-3.5 in the thesis's order: the 12 searches in parallel (§3.7), reduction per type, classification.
#include "../parallel.h"
#include "roomsense/cancel.h"
#include "classify.h"
#include "grow.h"
#include "reduce.h"
#include "search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

namespace roomsense {
namespace {

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

// What each type may grow over (grow.h): the cells its search accepts (Alg. 2, Alg. 3, §3.3.4).
detail::GrowthRule growth_rule(const GridSpec& spec, const RoomFeatures& features, const AreaParams& params,
                               std::size_t type) {
  using detail::SurfaceCell;
  const float voxel = spec.voxel_size;
  detail::GrowthRule rule;
  rule.step = 0.5f * voxel;
  rule.max_length = voxel * std::sqrt(float(spec.nx) * float(spec.nx) + float(spec.ny) * float(spec.ny) +
                                      float(spec.nz) * float(spec.nz));
  rule.fill = type == 0 ? params.wall_fill : params.horizontal_fill;
  // A strip may hold a speck the scan missed (one sample in five) as long as the whole area keeps its fill.
  rule.strip_fill = std::min(rule.fill, 0.8f);
  const auto voxel_of = [&spec, voxel](const glm::vec3& p) {
    return glm::ivec3(glm::floor((p - spec.origin) / voxel));
  };
  if (type == 0) {
    // Walls lie on the wall-side face of the voxels F marks (to_area): the voxel is half a voxel in front.
    const int floor = features.levels.floor, ceiling = std::min(features.levels.ceiling, spec.ny - 1);
    rule.conflict_depths = {-voxel, 0.0f, voxel};
    rule.cell_at = [&spec, &features, voxel_of, voxel, floor, ceiling](const glm::vec3& p, const Area& a) {
      const glm::ivec3 v = voxel_of(p + 0.5f * voxel * a.normal);
      if (!spec.contains(v.x, v.y, v.z) || v.y < floor || v.y > ceiling) return SurfaceCell::Forbidden;
      const std::size_t col = spec.column(v.x, v.z), i = spec.index(v.x, v.y, v.z);
      if (features.walls[col] || (!features.wall_blocked.empty() && features.wall_blocked[i]))
        return SurfaceCell::Forbidden;
      // Beyond the thesis: a wall ends at the ceiling in front of it (a roof's slope, a soffit), as F does.
      if (!features.ceiling.empty() && features.ceiling[col] < features.levels.ceiling && v.y >= features.ceiling[col])
        return SurfaceCell::Forbidden;
      return glm::dot(detail::normal_bits_direction(features.normals[i]), a.normal) > 0.0f ? SurfaceCell::Usable
                                                                                             : SurfaceCell::Unusable;
    };
    return rule;
  }
  if (type == 3) {
    rule.lookahead = 0.5f * voxel;
    for (int l = 1; l < params.reduction_offset; ++l) {  // Eq. 3.49: tops fewer levels apart are one top
      rule.conflict_depths.push_back(-float(l) * voxel);
      rule.conflict_depths.push_back(float(l) * voxel);
    }
  }
  rule.cell_at = [&spec, &features, voxel_of, voxel, type](const glm::vec3& p, const Area& a) {
    const glm::ivec3 v = voxel_of(p);
    if (v.x < 0 || v.z < 0 || v.x >= spec.nx || v.z >= spec.nz) return SurfaceCell::Forbidden;
    const std::size_t col = spec.column(v.x, v.z);
    if (features.walls[col]) return SurfaceCell::Forbidden;
    bool usable = false;
    if (type == 1) usable = features.free_floor[col] != 0;
    if (type == 2) {  // on the facet under the area's centre (find_ceiling_facets)
      usable = features.free_ceiling[col] != 0;
      if (usable && !features.ceiling_facet.empty()) {
        const glm::ivec3 c = voxel_of(a.center);
        const bool inside = c.x >= 0 && c.z >= 0 && c.x < spec.nx && c.z < spec.nz;
        usable = inside && features.ceiling_facet[col] == features.ceiling_facet[spec.column(c.x, c.z)];
      }
    }
    if (type == 3) {  // C holds the level above a top (Eq. 3.13); y_Actual may be one higher (Eq. 3.41)
      const int level = int(std::lround((a.center.y - spec.origin.y) / voxel));
      usable = features.furniture[col] == level || features.furniture[col] == level + 1;
    }
    return usable ? SurfaceCell::Usable : SurfaceCell::Unusable;
  };
  return rule;
}

}  // namespace

AreaResult find_areas(const VoxelGrid& grid, const RoomFeatures& features, const SurfaceLevels& surfaces,
                      const AreaParams& params, const FeatureParams& feature_params, unsigned threads,
                      std::stop_token stop) {
  using namespace detail;
  const GridSpec& spec = grid.spec;
  const float voxel = spec.voxel_size;
  AreaResult result;
  auto clock = std::chrono::steady_clock::now();

  // §3.3: task t searches type t / 3 in size t % 3. Each writes only its own slot.
  NormalCounts normals = count_normals(spec, features);  // for the wall searches only: freed after them
  // The corners a search starts from, for its cost estimate: voxels with a normal, or tiles.
  const auto count_if = [](const auto& v, auto pred) { return double(std::count_if(v.begin(), v.end(), pred)); };
  double with_normal = 0;  // from the prefix counts, not another pass over F
  for (std::size_t col = 0; col < spec.column_count() && normals.levels > 0; ++col)
    with_normal += normals.count(col, normals.y0, normals.y0 + normals.levels - 1);
  const std::array<double, 4> starts = {
      with_normal,
      count_if(features.free_floor, [](std::uint8_t t) { return t != 0; }),
      count_if(features.free_ceiling, [](std::uint8_t t) { return t != 0; }),
      count_if(features.furniture, [](int c) { return c != kNoFurniture; })};
  std::array<std::array<Candidates, 3>, 4> found;
  std::array<bool, 12> skipped{};
  double dominant_deg = 0.0;  // the room's main direction, from the walls (reduce.h)
  const auto search = [&](std::size_t t) {
    const std::size_t type = t / 3, size = t % 3;
    const SizeRange range =
        type == 0 ? size_range(params.wall_width[size], params.wall_height[size], params.width_tolerance, voxel)
                  : size_range(params.square_width[size], params.square_width[size], params.width_tolerance, voxel);
    // Half a ring of second corners per first one (Eq. 3.21); squares try about four centres per tile.
    const double ring = 0.5 * std::numbers::pi * (range.max_d * range.max_d - range.min_d * range.min_d);
    if (starts[type] * ring * (type == 0 ? 1.0 : 2.0) > kAreaSearchBudget) {
      skipped[t] = true;
      return;
    }
    if (type == 0) {
      found[type][size] = search_walls(spec, features, normals, range, params.wall_fill, stop);
      return;
    }
    const Surface surface = type == 1 ? Surface::Floor : type == 2 ? Surface::Ceiling : Surface::Furniture;
    found[type][size] = search_squares(spec, features, surface, range, params.horizontal_fill, dominant_deg, stop);
  };
  // The three wall searches first: their rectangles give the room's main direction, which the square
  // searches try first.
  parallel_tasks(3, threads, search);
  normals = NormalCounts();
  std::vector<Sized> deduplicated_walls;
  deduplicate_centres(found[0], [&](const Sized& s) { deduplicated_walls.push_back(s); });
  dominant_deg = dominant_direction_deg(deduplicated_walls);

  // §3.4, independent per type: V_Wall, V_Floor, ... (Eq. 3.44), for reach; packing (reduce.h) picks from all
  // the rectangles found: Eq. 3.44 would drop a medium square whose centre a large one has, though packing
  // may then refuse that large one.
  // Reach reads the deduplicated walls and floors; of ceilings and furniture only the count is kept.
  const PlacementContext context{spec, features, surfaces, feature_params};
  std::vector<ReachWall> wall_areas;
  std::vector<ReachFloor> floor_areas;
  std::array<std::size_t, 4> deduplicated_count{deduplicated_walls.size()};
  std::array<std::vector<std::size_t>, 4> kept;
  std::array<std::size_t, 4> found_count{};
  // Eq. 3.54-3.57 for the kept rectangles, which then grow into the surface packing left free (grow.h): per
  // type, in the same task as its packing, so that no type waits for the others'.
  std::array<std::vector<Area>, 4> kept_areas;
  const auto reduce = [&](std::size_t type) {
    if (type == 0) {
      for (const Sized& s : deduplicated_walls) wall_areas.emplace_back(to_area(s, AreaType::Wall, context));
      deduplicated_walls = {};
    }
    if (type == 1)
      deduplicated_count[type] = deduplicate_centres(
          found[type], [&](const Sized& s) { floor_areas.emplace_back(to_area(s, AreaType::Floor, context)); });
    if (type > 1) deduplicated_count[type] = deduplicate_centres(found[type], [](const Sized&) {});
    const SizedList all(found[type]);
    // Eq. 3.49: furniture squares less than reduction_offset levels apart are on one top.
    const TileMap is_tile{spec, type == 1 ? std::span<const std::uint8_t>(features.free_floor)
                                : type == 2 ? std::span<const std::uint8_t>(features.free_ceiling)
                                            : std::span<const std::uint8_t>(),
                          type == 3 ? std::span<const int>(features.furniture) : std::span<const int>()};
    kept[type] = type == 0 ? pack_walls(all)
                           : pack_squares(all, type == 3 ? params.reduction_offset - 1 : 0, dominant_deg, is_tile);
    for (std::size_t i : kept[type]) kept_areas[type].push_back(to_area(all[i], kAreaTypes[type], context));
    // Growth needs only the kept areas: the candidates go before it allocates its sample table.
    for (std::size_t size = 0; size < found[type].size(); ++size) {
      found_count[type] += found[type][size].size();
      found[type][size] = Candidates();
    }
    if (params.grow) grow_areas(kept_areas[type], growth_rule(spec, features, params, type), params, stop);
  };
  // The walls' reduction needs only the wall searches: it runs beside the nine square searches.
  parallel_tasks(10, threads, [&](std::size_t t) { t == 0 ? reduce(0) : search(t + 2); });
  for (std::size_t t = 0; t < skipped.size(); ++t)
    if (skipped[t])
      result.warnings.push_back(std::string(to_string(kAreaSizes[t % 3])) + " " + std::string(to_string(kAreaTypes[t / 3])) +
                                " areas not searched: too many corner pairs for this room at " +
                                std::to_string(voxel).substr(0, 5) + " m voxels (a coarser --voxel searches them)");
  stop_point(stop);
  result.timings.search = elapsed_ms(clock);  // the square searches, and the walls' reduction beside them
  clock = std::chrono::steady_clock::now();
  parallel_tasks(3, threads, [&](std::size_t type) { reduce(type + 1); });
  for (std::size_t type = 0; type < 4; ++type) {
    result.counts.found[type] = found_count[type];
    result.counts.deduplicated[type] = deduplicated_count[type];
    result.counts.reduced[type] = kept[type].size();
  }
  stop_point(stop);
  result.timings.reduce = elapsed_ms(clock);
  clock = std::chrono::steady_clock::now();

  // §3.5: reach against V_Floor and V_Wall (before packing).
  for (std::vector<Area>& areas : kept_areas) result.areas.insert(result.areas.end(), areas.begin(), areas.end());
  assign_reach(result.areas, floor_areas, wall_areas, surfaces.floor_y, params, threads);
  result.timings.classify = elapsed_ms(clock);
  return result;
}

}  // namespace roomsense
