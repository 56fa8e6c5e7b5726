// §3.3-3.5 in the thesis's order: the 12 searches in parallel (§3.7), reduction per type and size beside them,
// classification.
#include "../floor_int.h"
#include "../parallel.h"
#include "roomsense/cancel.h"
#include "classify.h"
#include "grow.h"
#include "reduce.h"
#include "ring_offsets.h"
#include "search.h"
#include "search_cache.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>

namespace roomsense {
namespace {

double elapsed_ms(std::chrono::steady_clock::time_point since,
                  std::chrono::steady_clock::time_point until = std::chrono::steady_clock::now()) {
  return std::chrono::duration<double, std::milli>(until - since).count();
}

// A rule's cells as its voxels' (grow.h): voxel_at, cell_of, and cell_at the two in turn.
template <class VoxelAt, class CellOf>
void set_cells(detail::GrowthRule& rule, VoxelAt voxel_at, CellOf cell_of) {
  rule.voxel_at = voxel_at;
  rule.cell_of = cell_of;
  rule.cell_at = [voxel_at, cell_of](const glm::vec3& p, const Area& a) { return cell_of(voxel_at(p, a), a); };
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
    return detail::floor_ivec3((p - spec.origin) / voxel);
  };
  if (type == 0) {
    // Walls lie on the wall-side face of the voxels F marks (to_area): the voxel is half a voxel in front.
    const int floor = features.levels.floor, ceiling = std::min(features.levels.ceiling, spec.ny - 1);
    rule.conflict_depths = {-voxel, 0.0f, voxel};
    set_cells(rule, [voxel_of, voxel](const glm::vec3& p, const Area& a) { return voxel_of(p + 0.5f * voxel * a.normal); },
              [&spec, &features, floor, ceiling](const glm::ivec3& v, const Area& a) {
      if (!spec.contains(v.x, v.y, v.z) || v.y < floor || v.y > ceiling) return SurfaceCell::Forbidden;
      const std::size_t col = spec.column(v.x, v.z), i = spec.index(v.x, v.y, v.z);
      if (features.walls[col] || (!features.wall_blocked.empty() && features.wall_blocked[i]))
        return SurfaceCell::Forbidden;
      // Beyond the thesis: a wall ends at the ceiling in front of it (a roof's slope, a soffit), as F does.
      if (!features.ceiling.empty() && features.ceiling[col] < features.levels.ceiling && v.y >= features.ceiling[col])
        return SurfaceCell::Forbidden;
      return glm::dot(detail::normal_bits_direction(features.normals[i]), a.normal) > 0.0f ? SurfaceCell::Usable
                                                                                             : SurfaceCell::Unusable;
    });
    return rule;
  }
  rule.cells_read_height = type == 3;  // a top's level; floor and ceiling cells are columns
  if (type == 3) {
    rule.lookahead = 0.5f * voxel;
    for (int l = 1; l < params.reduction_offset; ++l) {  // Eq. 3.49: tops fewer levels apart are one top
      rule.conflict_depths.push_back(-float(l) * voxel);
      rule.conflict_depths.push_back(float(l) * voxel);
    }
  }
  set_cells(rule, [voxel_of](const glm::vec3& p, const Area&) { return voxel_of(p); },
            [&spec, &features, voxel_of, voxel, type](const glm::ivec3& v, const Area& a) {
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
  });
  return rule;
}

}  // namespace

AreaResult find_areas(const VoxelGrid& grid, const RoomFeatures& features, const SurfaceLevels& surfaces,
                      const AreaParams& params, const FeatureParams& feature_params, unsigned threads,
                      std::stop_token stop) {
  check_params(params);
  check_params(feature_params);
  return detail::find_areas(grid, features, surfaces, params, feature_params, threads, std::move(stop), nullptr);
}

AreaResult detail::find_areas(const VoxelGrid& grid, const RoomFeatures& features, const SurfaceLevels& surfaces,
                              const AreaParams& params, const FeatureParams& feature_params, unsigned threads,
                              std::stop_token stop, SearchCache* cache) {
  using namespace detail;
  const GridSpec& spec = grid.spec;
  const float voxel = spec.voxel_size;
  AreaResult result;
  auto clock = std::chrono::steady_clock::now();

  if (cache) cache->begin(spec, features);
  // What each type's searches and their reduction derive, in voxels, before the areas in metres: the previous
  // analysis's where nothing they read changed (IncrementalAnalysis: walls decided here, squares once the
  // walls give the room's main direction), else found by the graph below.
  std::array<SearchCache::TypeReduction, 4> red;
  std::array<const SearchCache::TypeReduction*, 4> reused{};
  if (cache) reused[0] = cache->unchanged_type(0, params, 0.0);
  // §3.3: task t searches type t / 3 in size t % 3. Each writes only its own slot.
  // For the wall searches only (made below, beside the square rings): freed after them.
  NormalCounts normals;
  // The corners a search starts from, for its cost estimate: voxels with a normal (once they are counted), or tiles.
  const auto count_if = [](const auto& v, auto pred) { return double(std::count_if(v.begin(), v.end(), pred)); };
  std::array<double, 4> starts = {
      0.0, count_if(features.free_floor, [](std::uint8_t t) { return t != 0; }),
      count_if(features.free_ceiling, [](std::uint8_t t) { return t != 0; }),
      count_if(features.furniture, [](int c) { return c != kNoFurniture; })};
  std::array<std::array<Candidates, 3>, 4> found;
  double dominant_deg = 0.0;  // the room's main direction, from the walls (reduce.h)
  const auto range_of = [&](std::size_t type, std::size_t size) {
    return type == 0 ? size_range(params.wall_width[size], params.wall_height[size], params.width_tolerance, voxel)
                     : size_range(params.square_width[size], params.square_width[size], params.width_tolerance, voxel);
  };
  // The corner pairs a search may try: half a ring of second corners per first one (Eq. 3.21); squares try
  // about four centres per tile.
  const auto pairs = [&](std::size_t type, std::size_t size) {
    const SizeRange range = range_of(type, size);
    const double ring = 0.5 * std::numbers::pi * (range.max_d * range.max_d - range.min_d * range.min_d);
    return starts[type] * ring * (type == 0 ? 1.0 : 2.0);
  };
  const auto search_cost = [&](std::size_t type) { return pairs(type, 0) + pairs(type, 1) + pairs(type, 2); };
  // A size that cannot lie in the grid's columns (a wall's top longer than their diagonal, a square wider than
  // their narrower side: its extent along each axis is at least its side) has no rectangle and is not searched:
  // its ring alone (a 100 m square at 0.1 m voxels) would take seconds.
  const auto fits = [&](std::size_t type, std::size_t size) {
    const double room = type == 0 ? std::hypot(double(spec.nx), double(spec.nz)) : double(std::min(spec.nx, spec.nz));
    return range_of(type, size).min_d <= room;
  };
  // The three square types of a size search one ring of corner offsets (an IncrementalAnalysis's searches keep
  // their own): a whole analysis's, of each size some square search takes.
  std::array<std::vector<RingOffset>, 3> square_rings;
  const auto make_square_ring = [&](std::size_t size) {
    if (fits(1, size) &&
        (pairs(1, size) <= kAreaSearchBudget || pairs(2, size) <= kAreaSearchBudget || pairs(3, size) <= kAreaSearchBudget))
      square_rings[size] = ring_offsets(range_of(1, size), Shape::Square);
  };
  // The normals' counts, which the wall searches (the graph's first tasks) wait for, on one thread, and the medium
  // and small squares' rings, which need nothing, beside them on the other. The large squares' ring, which takes
  // as long as the normals (0.13 ms on thesis-room1), is a task of the graph.
  parallel_tasks(cache ? 1 : 2, threads, [&](std::size_t task) {
    if (task == 0) {
      if (!reused[0]) normals = count_normals(spec, features);
      return;
    }
    for (std::size_t size = 1; size < kAreaSizes.size(); ++size) make_square_ring(size);
  });
  for (std::size_t col = 0; col < spec.column_count() && normals.levels > 0; ++col)  // from the counts, not F again
    starts[0] += normals.count(col, normals.y0, normals.y0 + normals.levels - 1);
  const auto search = [&](std::size_t t) {
    const std::size_t type = t / 3, size = t % 3;
    if (reused[type]) return;
    const SizeRange range = range_of(type, size);
    if (!fits(type, size)) return;
    if (pairs(type, size) > kAreaSearchBudget) {
      red[type].skipped[size] = true;
      return;
    }
    if (type == 0) {
      found[type][size] = cache ? cache->walls(size, spec, features, normals, range, params.wall_fill, stop)
                                : search_walls(spec, features, normals, range, params.wall_fill, stop);
      return;
    }
    if (cache) {
      found[type][size] = cache->squares(type, size, spec, features, range, params.horizontal_fill, dominant_deg, stop);
      return;
    }
    const Surface surface = type == 1 ? Surface::Floor : type == 2 ? Surface::Ceiling : Surface::Furniture;
    found[type][size] = search_squares(spec, features, surface, range, params.horizontal_fill, dominant_deg, stop,
                                       {nullptr, nullptr, &square_rings[size]});
  };
  // §3.4, independent per type: V_Wall, V_Floor, ... (Eq. 3.44), for reach; packing (reduce.h) picks from all
  // the rectangles found: Eq. 3.44 would drop a medium square whose centre a large one has, though packing
  // may then refuse that large one. Eq. 3.54-3.57 for the kept rectangles, which then grow into the surface
  // packing left free (grow.h), per type in the task of its last packing, so that no type waits for the others'.
  // Reach reads the deduplicated walls and floors; of ceilings and furniture only the count is kept.
  const PlacementContext context{spec, features, surfaces, feature_params};
  // V_Wall's and V_Floor's areas: made here, or the cache's lists read in place.
  std::vector<ReachWall> own_wall_areas;
  const std::vector<ReachWall>* wall_areas = &own_wall_areas;
  std::shared_ptr<const WallSegments> wall_segments;  // of wall_areas, for reach
  std::vector<ReachFloor> own_floor_areas;
  const std::vector<ReachFloor>* floor_areas = &own_floor_areas;
  std::array<std::vector<Area>, 4> kept_areas;
  // The areas in metres of what the reduction keeps; each type's grown (grow.h).
  // Without a cache the lists in voxels go once in metres (a large floor's are many).
  const auto finish_walls_for_reach = [&] {
    const auto place = [&](const Sized& s) { return ReachWall(to_area(s, AreaType::Wall, context)); };
    if (cache) {
      wall_areas = &cache->reach_walls(reused[0] ? reused[0]->for_reach : red[0].for_reach, place);
    } else {
      for (const Sized& s : red[0].for_reach) own_wall_areas.push_back(place(s));
      red[0].for_reach = {};
    }
    wall_segments = reach_segments(*wall_areas, cache ? &cache->reach_memo() : nullptr);
  };
  const auto finish_floors_for_reach = [&](const std::vector<Sized>& for_reach) {
    const auto place = [&](const Sized& s) { return reach_floor(s, context); };
    if (cache) floor_areas = &cache->reach_floors(for_reach, place);
    else for (const Sized& s : for_reach) own_floor_areas.push_back(place(s));
  };
  const auto finish = [&](std::size_t type) {
    // Made in the task's own vector and moved in after: the types' vectors lie side by side, and the types' tasks
    // would pass their cache lines back and forth.
    std::vector<Area> areas;
    areas.reserve(red[type].kept.size());
    for (const Sized& s : red[type].kept) areas.push_back(to_area(s, kAreaTypes[type], context));
    if (!cache) red[type].kept = {};
    if (params.grow) {
      if (const std::vector<Area>* same = cache ? cache->grown(type, areas, params) : nullptr) {
        areas = *same;
      } else if (!cache) {
        grow_areas(areas, growth_rule(spec, features, params, type), params, stop);
      } else {
        GrowthRecord record;
        grow_areas(areas, growth_rule(spec, features, params, type), params, stop, cache->growth_replay(type, params),
                   &record);
        cache->keep_grown(type, std::move(record), params);
      }
    }
    kept_areas[type] = std::move(areas);
  };
  // Each search's candidates go once both their deduplication and their packing are done.
  std::array<std::array<std::atomic<int>, 3>, 4> candidate_users;
  for (auto& type_users : candidate_users)
    for (std::atomic<int>& users : type_users) users = 2;
  const auto release = [&](std::size_t type, std::size_t size) {
    if (--candidate_users[type][size] == 0) found[type][size] = Candidates();
  };
  // The square types whose reduction is the previous analysis's, decided once the walls give the main direction.
  const auto reuse_squares = [&] {
    for (std::size_t type = 1; type < 4 && cache; ++type) reused[type] = cache->unchanged_type(type, params, dominant_deg);
  };
  // Walls size by size, each as soon as its search ends (beside the next sizes' searches): V_Wall and, after the
  // last size, the room's main direction, which the square searches try first (reduce.h); beside them packing.
  // Deduplication's and packing's marks go with the last size (a large floor's walls mark megabytes).
  std::optional<CentreDeduplicator> wall_deduplicator(std::in_place, spec, stop);
  const auto deduplicate_walls = [&](std::size_t size) {
    if (!reused[0])
      red[0].deduplicated += wall_deduplicator->add(found[0][size], kAreaSizes[size],
                                                    [&](const Sized& s) { red[0].for_reach.push_back(s); });
    release(0, size);
    if (size + 1 < kAreaSizes.size()) return;
    wall_deduplicator.reset();
    normals = NormalCounts();  // the last wall search has ended
    // Walls taken whole give the main direction they gave (their V_Wall is read where it is kept, not copied):
    // every square search waits for this task.
    if (reused[0]) red[0].deduplicated = reused[0]->deduplicated, dominant_deg = reused[0]->dominant_deg;
    else dominant_deg = red[0].dominant_deg = dominant_direction_deg(red[0].for_reach);
    reuse_squares();
  };
  // A wall's corners lie at levels from the normals' first less its height (Eq. 3.20, one more for rounding)
  // to their last.
  int wall_height_max = 0;
  for (std::size_t size = 0; size < kAreaSizes.size(); ++size) {
    const SizeRange range = range_of(0, size);
    wall_height_max = std::max(wall_height_max, range.wall_height(range.max_d) + 1);
  }
  std::optional<WallPacker> wall_packer(std::in_place, spec, normals.y0 - wall_height_max,
                                       normals.y0 + normals.levels - 1, stop);
  const auto pack_walls = [&](std::size_t size) {
    if (reused[0]) {
      if (size + 1 < kAreaSizes.size()) return;
      red[0].kept = reused[0]->kept, red[0].found = reused[0]->found, red[0].skipped = reused[0]->skipped;
      finish(0);
      return;
    }
    const Candidates& walls = found[0][size];
    const std::vector<std::size_t> packed = wall_packer->pack(walls, cache ? cache->replay(0, size) : nullptr);
    for (const std::size_t i : packed) red[0].kept.push_back(Sized{walls[i], kAreaSizes[size]});
    if (cache) cache->record_packing(0, size, packed);
    red[0].found += walls.size();
    release(0, size);
    if (size + 1 < kAreaSizes.size()) return;
    wall_packer.reset();
    finish(0);
  };
  // Squares one size at a time, large first: deduplicated (V_Floor for reach) and packed, each in its own chain
  // of tasks (neither reads the other), and dropped once both are done, before the next size is searched where
  // a type's candidates are many (on a 50 x 50 m floor, millions).
  std::array<std::unique_ptr<CentreDeduplicator>, 4> deduplicators;
  std::array<std::unique_ptr<SquarePacker>, 4> packers;
  const auto deduplicate_squares = [&](std::size_t type, std::size_t size) {
    if (reused[type]) {  // packing's last task takes the whole reduction; V_Floor is the previous analysis's
      if (type == 1 && size + 1 == kAreaSizes.size()) finish_floors_for_reach(reused[type]->for_reach);
      return;
    }
    if (size == 0) deduplicators[type] = std::make_unique<CentreDeduplicator>(spec, stop);
    // V_Floor: kept in voxels only for an IncrementalAnalysis (which may place it again at another floor height);
    // a large floor's are many, so the whole analysis holds them in metres alone.
    red[type].deduplicated += deduplicators[type]->add(found[type][size], kAreaSizes[size], [&](const Sized& s) {
      if (type != 1) return;
      if (cache) red[type].for_reach.push_back(s);
      else own_floor_areas.push_back(reach_floor(s, context));
    });
    release(type, size);
    if (size + 1 < kAreaSizes.size()) return;
    deduplicators[type].reset();
    if (type == 1) finish_floors_for_reach(red[type].for_reach);
  };
  const auto pack_squares = [&](std::size_t type, std::size_t size) {
    if (reused[type]) {
      if (size + 1 < kAreaSizes.size()) return;
      red[type] = *reused[type];
      finish(type);
      return;
    }
    if (size == 0) {
      // The direction this type is searched and packed in: an update takes the type's reduction only where the
      // walls give the same one again (SearchCache::unchanged_type).
      red[type].dominant_deg = dominant_deg;
      const TileMap is_tile{spec, type == 1 ? std::span<const std::uint8_t>(features.free_floor)
                                  : type == 2 ? std::span<const std::uint8_t>(features.free_ceiling)
                                              : std::span<const std::uint8_t>(),
                            type == 3 ? std::span<const int>(features.furniture) : std::span<const int>()};
      // Eq. 3.49: furniture squares less than reduction_offset levels apart are on one top.
      packers[type] = std::make_unique<SquarePacker>(spec, type == 3 ? params.reduction_offset - 1 : 0, dominant_deg,
                                                     is_tile, stop, cache ? &cache->sample_runs(type) : nullptr);
    }
    const Candidates& squares = found[type][size];
    std::vector<std::uint32_t> ranks;
    const std::vector<std::size_t> packed =
        packers[type]->pack(squares, cache ? cache->replay(type, size) : nullptr, cache ? &ranks : nullptr);
    for (std::size_t i : packed) red[type].kept.push_back(Sized{squares[i], kAreaSizes[size]});
    if (cache) cache->record_packing(type, size, packed, ranks);
    red[type].found += squares.size();
    release(type, size);
    if (size + 1 < kAreaSizes.size()) return;
    packers[type].reset();
    finish(type);
  };
  // The work as a graph (parallel_graph): the three wall searches; each size's deduplication and, beside it,
  // its packing once its search and the previous size's are done; after the last deduplication V_Wall's areas,
  // and each type's square searches, side by side, the types most costly to search first, and each size's packing and
  // deduplication after its search and the previous size's. Where one size's candidates would be large (about
  // two per tile, 12 bytes each, past kChainBytes: a floor of some 400 m² and more), a size's search also waits
  // for the previous size's reduction, so that the type holds one size's candidates at a time (on a 50 x 50 m
  // floor, 6 MB each) rather than searching them side by side.
  constexpr double kChainBytes = 1 << 20;
  const auto chained = [&](std::size_t type) { return 2.0 * starts[type] * double(Candidates::kBytesEach) > kChainBytes; };
  constexpr std::size_t kDeduplicateWalls = 5;  // the last size's, which gives the main direction
  constexpr std::size_t kPackWalls = 8;          // the last size's, which ends with V_Wall's growth
  std::size_t finish_walls_task = 0;             // V_Wall's areas for reach (below)
  std::vector<std::vector<std::size_t>> after = {{}, {}, {}, {0}, {1, 3}, {2, 4}, {0}, {1, 6}, {2, 7}};
  std::vector<std::function<void()>> tasks = {
      [&] { search(0); },            [&] { search(1); },            [&] { search(2); },
      [&] { deduplicate_walls(0); }, [&] { deduplicate_walls(1); }, [&] { deduplicate_walls(2); },
      [&] { pack_walls(0); },        [&] { pack_walls(1); },        [&] { pack_walls(2); }};
  std::array<std::size_t, 3> square_types = {1, 2, 3};
  std::stable_sort(square_types.begin(), square_types.end(),
                   [&](std::size_t a, std::size_t b) { return search_cost(a) > search_cost(b); });
  // Per type and size three tasks: search, packing, deduplication (packing's chain is the longest path of the
  // graph: growth ends it). The graph runs the ready task of lowest index first, so they come size by size:
  // every type's large search, then their packings and deduplications, then the medium sizes'. Each type's
  // packing chain then starts once its own large search is done, rather than after another type's every
  // search (on thesis-room1, two threads: 0.5 ms of one thread working alone at the end, saved).
  std::array<std::array<std::size_t, 3>, 4> search_task{}, pack_task{}, deduplication_task{};
  std::vector<std::size_t> square_searches;
  for (std::size_t size = 0; size < kAreaSizes.size(); ++size) {
    for (const std::size_t type : square_types) {
      search_task[type][size] = tasks.size();
      square_searches.push_back(tasks.size());
      after.push_back(size > 0 && chained(type)
                          ? std::vector<std::size_t>{pack_task[type][size - 1], deduplication_task[type][size - 1]}
                          : std::vector<std::size_t>{kDeduplicateWalls});
      tasks.push_back([&search, type, size] { search(3 * type + size); });
    }
    for (const std::size_t type : square_types) {
      const std::size_t found_by = search_task[type][size];
      pack_task[type][size] = tasks.size();
      after.push_back(size == 0 ? std::vector<std::size_t>{found_by}
                                : std::vector<std::size_t>{found_by, pack_task[type][size - 1]});
      tasks.push_back([&pack_squares, type, size] { pack_squares(type, size); });
      deduplication_task[type][size] = tasks.size();
      after.push_back(size == 0 ? std::vector<std::size_t>{found_by}
                                : std::vector<std::size_t>{found_by, deduplication_task[type][size - 1]});
      tasks.push_back([&deduplicate_squares, type, size] { deduplicate_squares(type, size); });
    }
    // V_Wall's areas for reach after the large squares' tasks: nothing in the graph waits for them, and a large
    // square search begins the longest chain (in an update, a floor's).
    if (size == 0) {
      finish_walls_task = tasks.size();
      after.push_back({kDeduplicateWalls});
      tasks.push_back(finish_walls_for_reach);
    }
  }
  // Types of large lists one after another (the walls, then the square types by cost): a type's first search waits
  // for the whole reduction of the one before it (its last size's packing ends with its growth), so that one type's
  // list, packer and growth are held at a time whatever the threads do. Side by side, as the two threads' timing
  // fell, they took a 50 x 50 m floor's search from 3.3 to 4.5 times the grid's bytes, a 90 x 90 m floor's to 4.2.
  std::vector<std::size_t> previous_reduction;  // the last tasks of the large type before, none at first
  if (chained(0)) previous_reduction = {kPackWalls, kDeduplicateWalls};
  for (const std::size_t type : square_types) {
    if (!chained(type)) continue;
    std::vector<std::size_t>& first_search = after[search_task[type][0]];
    first_search.insert(first_search.end(), previous_reduction.begin(), previous_reduction.end());
    previous_reduction = {pack_task[type][kAreaSizes.size() - 1], deduplication_task[type][kAreaSizes.size() - 1]};
  }
  // §3.5: reach against V_Floor and V_Wall (before packing), once both are final, and per type as soon as the
  // type has grown, beside the other types' reduction (in an update, beside a floor's chain of packings).
  std::optional<ReachView> reach_view;
  std::array<ReachMemo::Seen, 4> reach_seen;  // kept once the graph has ended (ReachView::keep)
  const std::size_t reach_view_task = tasks.size();
  after.push_back({finish_walls_task, deduplication_task[1][kAreaSizes.size() - 1]});
  tasks.push_back([&] {
    reach_view.emplace(*floor_areas, *wall_areas, params, cache ? &cache->reach_memo() : nullptr, std::move(wall_segments));
  });
  std::vector<std::size_t> reach_tasks;
  for (std::size_t type = 0; type < 4; ++type) {
    reach_tasks.push_back(tasks.size());
    after.push_back({reach_view_task, type == 0 ? kPackWalls : pack_task[type][kAreaSizes.size() - 1]});
    tasks.push_back([&, type] {
      assign_reach(kept_areas[type], *reach_view, surfaces.floor_y, params, threads, type, cache ? &reach_seen[type] : nullptr);
    });
  }
  // A whole analysis's large squares' ring, which their searches wait for: the graph's last task, which a worker
  // takes once nothing else is ready (the first wall search to end leaves one so, before the walls give the main
  // direction the square searches wait for).
  if (!cache) {
    const std::size_t large_ring_task = tasks.size();
    after.push_back({});
    tasks.push_back([&] { make_square_ring(0); });
    for (const std::size_t type : square_types) after[search_task[type][0]].push_back(large_ring_task);
  }
  // The search time ends with the last search, the reduction's with the graph; classification's is from its first
  // reach to its last, beside the reduction.
  std::mutex searches_mutex;
  std::size_t searches_left = square_searches.size();
  auto searches_end = clock;
  std::optional<std::chrono::steady_clock::time_point> reach_begin;
  auto reach_end = clock;
  parallel_graph(after, threads, [&](std::size_t i) {
    stop_point(stop);  // a stop ends the graph at the next task, not only inside the searches
    const bool reach = std::find(reach_tasks.begin(), reach_tasks.end(), i) != reach_tasks.end();
    if (reach) {
      const std::lock_guard lock(searches_mutex);
      if (!reach_begin) reach_begin = std::chrono::steady_clock::now();
    }
    tasks[i]();
    const bool search = std::find(square_searches.begin(), square_searches.end(), i) != square_searches.end();
    if (!search && !reach) return;
    const std::lock_guard lock(searches_mutex);
    if (search && --searches_left == 0) searches_end = std::chrono::steady_clock::now();
    if (reach) reach_end = std::chrono::steady_clock::now();
  });
  for (std::size_t t = 0; t < 12; ++t)
    if (red[t / 3].skipped[t % 3])
      result.warnings.push_back(std::string(to_string(kAreaSizes[t % 3])) + " " + std::string(to_string(kAreaTypes[t / 3])) +
                                " areas not searched: too many corner pairs for this room at " +
                                std::to_string(voxel).substr(0, 5) + " m voxels (a coarser --voxel searches them)");
  stop_point(stop);
  result.timings.search = elapsed_ms(clock, searches_end);  // and overlapping reductions
  result.timings.reduce = elapsed_ms(searches_end);          // and overlapping classification
  result.timings.classify = reach_begin ? elapsed_ms(*reach_begin, reach_end) : 0.0;
  for (std::size_t type = 0; type < 4; ++type) {
    result.counts.found[type] = red[type].found;
    result.counts.deduplicated[type] = red[type].deduplicated;
    result.counts.reduced[type] = kept_areas[type].size();  // growth changes extents, not the count
  }
  for (std::vector<Area>& areas : kept_areas) result.areas.insert(result.areas.end(), areas.begin(), areas.end());
  if (cache) reach_view->keep(cache->reach_memo(), reach_seen);
  for (std::size_t type = 0; type < 4 && cache; ++type)
    if (!reused[type]) cache->keep_type(type, std::move(red[type]), params);
  return result;
}

}  // namespace roomsense
