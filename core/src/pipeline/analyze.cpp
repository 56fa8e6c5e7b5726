// The pipeline of thesis chapter 3 in the order of DESIGN.md's data flow.
#include "roomsense/analysis.h"
#include "roomsense/cancel.h"
#include "roomsense/error.h"
#include "roomsense/number_text.h"
#include "../parallel.h"
#include "../grid/changed_columns.h"
#include "../grid/voxelize_cpu.h"
#include "../input/input_view.h"
#include "analysis_caches.h"
#include "storeys.h"
#include "surface_heights.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <utility>

namespace roomsense {
namespace {

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

std::string metres(float value) { return fixed_or_g(value, 2) + " m"; }

// Issue 15: the rooms of every storey in one list.
void list_rooms(AnalysisResult& r) {
  const GridSpec& s = r.voxels.grid.spec;
  const double cell = double(s.voxel_size) * double(s.voxel_size);
  for (std::uint32_t i = 0; i < r.storeys.size(); ++i) {
    const RoomSplit& split = r.storey_features(i).rooms;
    if (split.count == 0) continue;
    // The columns' centres (x + 1/2, z + 1/2) summed as whole x and z and half the count: the same sums (exact in
    // a double either way), without a double per column.
    std::vector<std::array<std::uint64_t, 2>> sum(std::size_t(split.count), {0, 0});
    std::vector<std::size_t> cells(std::size_t(split.count), 0);
    for (int z = 0; z < s.nz; ++z) {
      const int* row = split.room.data() + s.column(0, z);
      for (int x = 0; x < s.nx; ++x) {
        const int room = row[x];
        if (room == kNoRoom) continue;
        std::array<std::uint64_t, 2>& at = sum[std::size_t(room)];
        at[0] += std::uint64_t(x);
        at[1] += std::uint64_t(z);
        ++cells[std::size_t(room)];
      }
    }
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const glm::dvec2 mean = (glm::dvec2(double(sum[k][0]), double(sum[k][1])) + 0.5 * double(cells[k])) /
                              double(std::max<std::size_t>(cells[k], 1));
      const Storey& storey = r.storeys[i];
      r.rooms.push_back({i, float(double(cells[k]) * cell),
                         {s.origin.x + float(mean.x) * s.voxel_size, storey.floor_y, s.origin.z + float(mean.y) * s.voxel_size},
                         storey.floor_y, storey.ceiling_y});
    }
  }
}

// Issue 15: each area's room: the room of the column under a horizontal area's centre or in front of a wall
// area's, or the nearest within 0.3 m.
void assign_area_rooms(AnalysisResult& r) {
  const GridSpec& s = r.voxels.grid.spec;
  for (Area& a : r.areas)
    a.room = room_at_point(r, a.storey, a.type == AreaType::Wall ? a.center + 0.5f * s.voxel_size * a.normal : a.center);
}

// What the bounds read of a storey with these features.
BoundsStorey bounds_storey(const RoomFeatures& f) { return {f.levels, f.y_end, &f.room, &f.ceiling}; }

// The bounds built from a result's grid and its storeys' features (in order): the home's and each room's.
struct AllBounds {
  BoundsMesh bounds;
  std::vector<BoundsMesh> room_bounds;  // index as the result's rooms
};

// Issue 15: each room's bounds (build_room_bounds) over its room_mask of its storey's B (its free columns and
// the walls within 0.3 m of them). A scan of one room has its bounds.
// The home's bounds and each room's (the rooms as list_rooms lists them: each storey's split in order). Every
// mesh is its own task, on one thread each: a home's rooms are independent, so two cores build two at a time (one
// after another, five rooms of SU_Apartment cost as much as the rest of its analysis).
AllBounds build_all_bounds(const VoxelGrid& grid, std::span<const RoomFeatures* const> features,
                           const AnalysisOptions& options, std::vector<detail::MeshMemo>* memos) {
  std::vector<BoundsStorey> storeys;
  std::size_t rooms = 0;
  for (const RoomFeatures* f : features) storeys.push_back(bounds_storey(*f)), rooms += std::size_t(f->rooms.count);
  const auto memo = [&](std::size_t k) { return memos ? &(*memos)[k] : nullptr; };
  AllBounds out;
  if (rooms <= 1) {
    if (memos) memos->resize(1);
    out.bounds = detail::build_bounds(grid, storeys, options.bounds, options.threads, options.stop, memo(0));
    out.room_bounds.assign(rooms, out.bounds);
    return out;
  }
  const GridSpec& s = grid.spec;
  const int reach = room_reach_columns(s);
  struct RoomJob {
    std::size_t storey;
    std::shared_ptr<const std::vector<int>> rooms_of;
    int room;
  };
  std::vector<RoomJob> jobs;
  for (std::size_t i = 0; i < storeys.size(); ++i) {
    const RoomSplit& split = features[i]->rooms;
    const auto rooms_of = std::make_shared<const std::vector<int>>(rooms_of_mask(s, *storeys[i].room, split, reach));
    for (int k = 0; k < split.count; ++k) jobs.push_back({i, rooms_of, k});
  }
  out.room_bounds.assign(jobs.size(), {});
  if (memos) memos->resize(jobs.size() + 1);
  detail::parallel_tasks(jobs.size() + 1, options.threads, [&](std::size_t t) {
    stop_point(options.stop);
    if (t == 0) {
      out.bounds = detail::build_bounds(grid, storeys, options.bounds, 1, options.stop, memo(0));
      return;
    }
    const RoomJob& job = jobs[t - 1];
    out.room_bounds[t - 1] = detail::build_room_bounds(grid, storeys[job.storey], room_mask(*job.rooms_of, job.room),
                                                       options.bounds, 1, options.stop, memo(t));
  });
  return out;
}

}  // namespace

std::vector<BoundsStorey> bounds_storeys(const AnalysisResult& result) {
  std::vector<BoundsStorey> out;
  for (std::size_t i = 0; i < result.storeys.size(); ++i) out.push_back(bounds_storey(result.storey_features(i)));
  return out;
}

int room_reach_columns(const GridSpec& spec) {
  return std::max(1, int(std::lround(double(kRoomReach) / double(spec.voxel_size))));
}

int first_room_of(const AnalysisResult& result, std::uint32_t storey) {
  return int(std::count_if(result.rooms.begin(), result.rooms.end(), [&](const Room& r) { return r.storey < storey; }));
}

int room_at_point(const AnalysisResult& result, std::uint32_t storey, const glm::vec3& p) {
  if (storey >= result.storeys.size()) return kNoRoom;
  const GridSpec& s = result.voxels.grid.spec;
  const float fx = std::floor((p.x - s.origin.x) / s.voxel_size), fz = std::floor((p.z - s.origin.z) / s.voxel_size);
  if (!(std::fabs(fx) < 1e8f && std::fabs(fz) < 1e8f)) return kNoRoom;  // NaN or far outside
  const int local = room_at(s, result.storey_features(storey).rooms, int(fx), int(fz), room_reach_columns(s));
  return local == kNoRoom ? kNoRoom : first_room_of(result, storey) + local;
}

AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options) { return detail::analyze(scan, options, nullptr); }

AnalysisResult detail::analyze(const Scan& scan, const AnalysisOptions& options, AnalysisCaches* caches) {
  Stopwatch clock, total_clock;
  // The threads of every parallel loop below: started once per analysis, or kept by an IncrementalAnalysis.
  std::unique_ptr<detail::WorkerPool> own_workers;
  const bool kept = caches == nullptr && options.kept_threads != nullptr &&
                    options.kept_threads->threads() == detail::resolve_threads(options.threads);
  const detail::PoolScope scope(kept ? options.kept_threads->pool()
                                     : detail::pool_for(caches ? caches->workers : own_workers, options.threads));
  AnalysisResult r;
  // This analysis among its IncrementalAnalysis's: caches->previous, where there is one, is the one before.
  const std::uint64_t serial = caches ? ++caches->serial : 0;
  stop_point(options.stop);
  check_params(options.features);
  check_params(options.areas);
  // An IncrementalAnalysis's chunks: what it knows of each. Their input checks, voxels, surface sums and labels
  // read each chunk's own arrays; `scan` is not read (its arrays are made only by chunks->whole()).
  CombinedScan* const chunks = caches != nullptr && &scan == &caches->combined.handle() ? &caches->combined : nullptr;
  detail::InputView in;
  // The chunks checked as parts, where nothing is to be removed: `in` then has the counts and bounds alone, and
  // whole_input() gives it the whole scan's arrays where a step reads them. Otherwise the whole scan, as given or
  // made from the chunks, checked and where need be renumbered.
  std::optional<PreparedInput> parts_checked;
  if (chunks) {
    std::vector<std::span<const glm::vec3>> parts;
    parts.reserve(chunks->chunks.size());
    for (const Scan* chunk : chunks->chunks) parts.emplace_back(chunk->vertices);
    std::vector<detail::PartKey> keys;
    keys.reserve(chunks->placed.size());
    for (const CombinedScan::Placed& p : chunks->placed) keys.push_back({p.id, p.hash});
    parts_checked = detail::check_parts(parts, chunks->end.index, options.reject_outliers, chunks->known,
                                        options.threads, &caches->quantiles, keys);
  }
  if (parts_checked) in.checked = std::move(*parts_checked);
  else in = detail::view_input(chunks ? chunks->whole(options.threads) : scan, options.reject_outliers,
                               chunks ? &chunks->known : nullptr, options.threads, caches ? &caches->quantiles : nullptr);
  // Whether the checks renumbered the input (then `in` holds its own arrays, and a chunk's are not the input's).
  const bool renumbered = !in.checked.vertices.empty();
  const bool in_parts = parts_checked.has_value();
  const auto whole_input = [&] {
    if (!in_parts || !in.vertices.empty()) return;
    const Scan& whole = chunks->whole(options.threads);
    in.vertices = whole.vertices, in.indices = whole.indices;
  };
  const std::size_t index_count = in_parts ? chunks->end.index : in.indices.size();
  const PreparedInput& checked = in.checked;
  r.input = {checked.input_vertices, checked.input_triangles, checked.skipped_vertices, checked.outlier_vertices,
             checked.dropped_triangles};
  if (checked.skipped_vertices > 0)
    r.warnings.push_back(std::to_string(checked.skipped_vertices) + " vertices with NaN or Inf coordinates skipped");
  if (checked.outlier_vertices > 0)
    r.warnings.push_back(std::to_string(checked.outlier_vertices) + " outlier vertices far from the room rejected");
  if (checked.dropped_triangles > 0)
    r.warnings.push_back(std::to_string(checked.dropped_triangles) + " triangles touching skipped vertices dropped");

  r.mode = options.mode.value_or(index_count == 0 ? VoxelMode::Vertices : VoxelMode::Triangles);
  if (r.mode == VoxelMode::Triangles && index_count == 0) {
    r.mode = VoxelMode::Vertices;
    r.warnings.push_back("triangle mode asked for a scan without triangles: vertex mode used");
  }
  const GridSpec spec = make_grid_spec(checked.lo, checked.hi, options.voxel_size, options.voxel_budget);
  CpuVoxelStage cpu(options.threads);
  VoxelStage& stage = options.voxel_stage != nullptr ? *options.voxel_stage : cpu;
  // An IncrementalAnalysis's stage maps the few chunks it voxelizes again itself, where the input checks removed
  // nothing: the whole scan's vertices are not mapped for each change.
  const bool stage_maps_chunks = chunks != nullptr && &stage == caches->chunk_stage && r.mode == VoxelMode::Triangles &&
                                 !renumbered;
  if (!stage_maps_chunks) whole_input();
  const std::size_t mapped = stage_maps_chunks ? 0 : in.vertices.size();
  const std::unique_ptr<glm::vec3[]> grid_vertex_data = std::make_unique_for_overwrite<glm::vec3[]>(mapped);
  detail::to_grid_units_into(in.vertices.first(mapped), spec, options.threads, grid_vertex_data.get());
  const std::span<const glm::vec3> grid_vertices(grid_vertex_data.get(), mapped);
  const int min_separation = voxels_for(options.features.min_floor_ceiling, spec.voxel_size);
  r.timings.prepare = clock.lap();

  stop_point(options.stop);
  r.backend = stage.name();
  r.voxels = stage.run({spec, grid_vertices, in.indices, r.mode, min_separation, options.voxel_test_budget,
                        options.stop});
  r.timings.voxelize = clock.lap();
  stop_point(options.stop);

  const float min_height = options.features.min_floor_ceiling;
  // Moves the result out (a copy would copy the voxel grid).
  const auto no_room = [&](std::string message) {
    r.status = AnalysisStatus::NoFloorCeiling;
    r.status_message = std::move(message);
    r.timings.total = r.timings.prepare + r.timings.voxelize;
    return std::move(r);
  };
  if (!r.voxels.levels)
    return no_room("no floor and ceiling found: no two horizontal levels are at least " + metres(min_height) +
                   " apart (" + std::to_string(spec.ny) + " levels scanned)");
  // An IncrementalAnalysis's previous result, alive through this analysis, which may take its features and
  // bounds (a chunk refined within its voxels) and compares against it.
  const AnalysisResult* previous = caches ? caches->previous : nullptr;
  // Which columns' voxels changed since the previous analysis: its horizontal counts and the features' column
  // steps are derived again there.
  const std::vector<std::uint8_t> changed = previous != nullptr && previous->voxels.grid.spec == spec
                                                ? detail::changed_columns(previous->voxels.grid, r.voxels.grid)
                                                : std::vector<std::uint8_t>();
  // Beyond the thesis: the stage's pair may span several storeys (storeys.h); the main one gets its own counts.
  std::vector<std::uint32_t> horizontal =
      !changed.empty() && caches->horizontal_serial + 1 == serial
          ? detail::horizontal_counts(r.voxels.grid, previous->voxels.grid, std::move(caches->horizontal), changed)
          : detail::horizontal_counts(r.voxels.grid, options.threads);
  detail::StoreyLevels storeys = detail::find_storeys(r.voxels.level_counts, horizontal, *r.voxels.levels, min_separation);
  if (caches) caches->horizontal = std::move(horizontal), caches->horizontal_serial = serial;
  // Beyond the thesis (issue 15): a storey under a pitched roof reaches up to its ridge (raised_ceiling), below
  // the next storey's floor.
  // Every storey's levels, the main one first.
  std::vector<FloorCeiling*> all{&storeys.main};
  for (FloorCeiling& other : storeys.others) all.push_back(&other);
  // count_columns on a storey's levels: counted once an analysis (the main storey's again below where no ridge raised
  // it); in an IncrementalAnalysis, the previous analysis's counts on them counted again where the voxels changed,
  // where it counted them.
  std::vector<detail::AnalysisCaches::StoreyCounts> storey_counts;
  const auto count_storey = [&](const FloorCeiling& fc, std::vector<std::uint32_t>& counts, std::vector<std::uint8_t>& any) {
    for (const detail::AnalysisCaches::StoreyCounts& done : storey_counts)
      if (done.levels == fc) {
        counts = done.counts, any = done.any;
        return;
      }
    const detail::AnalysisCaches::StoreyCounts* kept = nullptr;
    if (caches && !changed.empty() && caches->counts_serial + 1 == serial) {
      const auto& last = caches->storey_counts;
      const auto same = std::find_if(last.begin(), last.end(), [&](const detail::AnalysisCaches::StoreyCounts& c) {
        return c.levels == fc && c.counts.size() == spec.column_count();
      });
      if (same != last.end()) kept = &*same;
    }
    if (kept) {
      counts = kept->counts, any = kept->any;
      detail::count_columns_again(r.voxels.grid, fc, changed, counts, any);
    } else {
      count_columns(r.voxels.grid, fc, counts, any, options.threads);
    }
    storey_counts.push_back({fc, counts, any});
  };
  std::vector<bool> raised;
  {
    std::vector<std::uint32_t> counts;
    std::vector<std::uint8_t> any;
    for (FloorCeiling* fc : all) {
      int upper = spec.ny;
      for (const FloorCeiling* other : all)
        if (other->floor_peak > fc->ceiling_peak) upper = std::min(upper, other->floor_peak);
      // The voxel stage counted the columns on its own levels: the main storey's, but where storeys moved them.
      const bool counted = *fc == *r.voxels.levels;
      if (!counted) count_storey(*fc, counts, any);
      const auto up = raised_ceiling(r.voxels.grid, *fc, detect_room(spec, counted ? r.voxels.column_any : any), upper);
      if (up) *fc = *up;
      raised.push_back(up.has_value());
    }
  }
  if (storeys.main != *r.voxels.levels) {
    r.voxels.levels = storeys.main;
    count_storey(storeys.main, r.voxels.column_counts, r.voxels.column_any);
  }
  if (caches) caches->storey_counts = std::move(storey_counts), caches->counts_serial = serial;
  const FloorCeiling& levels = *r.voxels.levels;
  // Each storey's floor and ceiling heights: the sums over the triangles in their bands, in one pass over the
  // triangles shared by the two workers, or from each chunk's sums where the scan is in chunks and the input
  // checks removed nothing. A raised storey's ceiling is its ridge: the highest point of the roof.
  // Height k is storey k / 2's floor (k even) or ceiling, in the levels [lo, hi].
  const auto levels_of = [&](std::size_t k) {
    const FloorCeiling& fc = *all[k / 2];
    return k % 2 == 0 ? std::pair(fc.floor_peak, fc.floor) : std::pair(fc.ceiling, fc.ceiling_peak);
  };
  const auto ridge = [&](std::size_t k) { return k % 2 == 1 && raised[k / 2]; };
  std::vector<float> heights(2 * all.size());
  std::vector<BandLimits> bands;  // of the heights but ridges, in order
  std::vector<std::size_t> band_of(heights.size());
  for (std::size_t k = 0; k < heights.size(); ++k)
    if (!ridge(k)) band_of[k] = bands.size(), bands.push_back(band_limits(spec, levels_of(k).first, levels_of(k).second));
  // Beyond the thesis: §3.2-3.6 for each storey on its own levels and column counts, side by side, and beside
  // them the heights' sums: the features read the levels alone, and their first steps are one thread's. What the
  // heights decide (no room, which storeys are rooms) waits for all; a storey the heights drop is rare. The
  // labels' warnings come after that decision, as the features do.
  std::vector<std::string> label_warnings;
  LabelGrid labels = chunks != nullptr ? caches->label_voxels.grid(*chunks, spec, options.voxel_test_budget,
                                                                   label_warnings, options.threads)
                                        : voxelize_labels(spec, scan.labels, options.voxel_test_budget, label_warnings);
  // An IncrementalAnalysis whose chunks changed within their voxels: the features of a storey on the levels of one
  // of the previous analysis's (and below, the bounds, where every storey is) are that analysis's.
  const detail::GridChange change{serial - 1, serial, changed.empty() ? nullptr : &changed};
  const bool same_grid = previous != nullptr && previous->features && change.changed != nullptr &&
                         std::find(changed.begin(), changed.end(), std::uint8_t{1}) == changed.end() &&
                         caches->previous_labels.present == labels.present &&
                         caches->previous_labels.masks == labels.masks;
  // The previous analysis's features of a storey on these levels, where it has one.
  const auto previous_storey = [&](const FloorCeiling& storey) -> const RoomFeatures* {
    for (std::size_t i = 0; previous != nullptr && i < previous->storeys.size(); ++i)
      if (previous->storeys[i].levels == storey) return i == 0 ? &*previous->features : &previous->other_features[i - 1];
    return nullptr;
  };
  const auto previous_features = [&](const FloorCeiling& storey) { return same_grid ? previous_storey(storey) : nullptr; };
  std::vector<RoomFeatures> storey_features(all.size());  // as `all`
  std::vector<BandSum> sums;  // as `bands`; none for a point cloud
  if (caches && caches->features.size() < all.size()) caches->features.resize(all.size());
  const bool area_features = options.find_areas || options.area_features;
  // Without the areas, the bounds wait for the features alone, not for the heights: the task that ends the last
  // storey's features builds them, beside the heights' sums (in a bounds-only run the two longest steps, side by
  // side). They are every storey's; where the heights then drop a storey (rare), they are built again below. An
  // IncrementalAnalysis whose storeys' levels are the previous result's takes that result's bounds instead.
  const bool same_levels = same_grid && previous->storeys.size() == all.size() &&
                           std::equal(all.begin(), all.end(), previous->storeys.begin(),
                                      [](const FloorCeiling* x, const Storey& y) { return *x == y.levels; });
  const bool early_bounds = options.build_bounds && !options.find_areas && !same_levels;
  std::atomic<std::size_t> features_left = all.size();
  std::optional<AllBounds> every_storeys_bounds;
  double every_storeys_bounds_ms = 0.0;
  const auto build_early_bounds = [&] {
    Stopwatch bounds_clock;
    std::vector<const RoomFeatures*> every;
    for (const RoomFeatures& f : storey_features) every.push_back(&f);
    every_storeys_bounds = build_all_bounds(r.voxels.grid, every, options, caches ? &caches->bounds : nullptr);
    every_storeys_bounds_ms = bounds_clock.lap();
  };
  // Task 0, the main storey's, most likely on this thread, whose heap then holds what lives longest (worker_pool.h).
  detail::parallel_tasks(all.size() + 1, options.threads, [&](std::size_t k) {
    stop_point(options.stop);
    if (k < all.size()) {
      detail::FeatureMemo* memo = caches ? &caches->features[k] : nullptr;
      if (const RoomFeatures* same = previous_features(*all[k])) {
        storey_features[k] = *same;
        // The grid is the previous one: what the memo's column steps derived from that still holds.
        if (memo) {
          memo->ceilings.inputs.same_grid(change);
          memo->columns.inputs.same_grid(change);
          memo->normals.inputs.same_grid(change);
          memo->openings.inputs.same_grid(change);
        }
      } else if (k == 0)
        storey_features[k] = detail::detect_features(r.voxels.grid, *all[k], r.voxels.column_counts,
                                                     r.voxels.column_any, options.features, options.threads,
                                                     options.stop, labels, memo, change, previous_storey(*all[k]),
                                                     area_features);
      else {
        std::vector<std::uint32_t> column_counts;
        std::vector<std::uint8_t> column_any;
        count_columns(r.voxels.grid, *all[k], column_counts, column_any);
        storey_features[k] = detail::detect_features(r.voxels.grid, *all[k], column_counts, column_any,
                                                     options.features, options.threads, options.stop, labels, memo,
                                                     change, previous_storey(*all[k]), area_features);
      }
      if (early_bounds && --features_left == 0) build_early_bounds();
      return;
    }
    if (index_count > 0)
      sums = chunks != nullptr && !renumbered ? caches->band_sums.sums(*chunks, bands, options.threads)
                                              : band_sums(in.vertices, in.indices, bands, options.threads);
  });
  // From the sums at once; a ridge, a point cloud's (or terms past the sums) a pass each, side by side.
  for (std::size_t k = 0; k < heights.size(); ++k)
    if (ridge(k) || sums.empty() || !sums[band_of[k]].exact()) whole_input();
  detail::parallel_tasks(heights.size(), sums.empty() ? options.threads : 1, [&](std::size_t k) {
    const auto [lo, hi] = levels_of(k);
    const std::size_t b = band_of[k];
    heights[k] = ridge(k)                           ? detail::surface_top(spec, in.vertices, lo, hi)
                 : !sums.empty() && sums[b].exact() ? band_height(sums[b], bands[b])
                                                    : detail::surface_height(spec, in.vertices, in.indices, lo, hi);
  });
  r.floor_y = heights[0];
  r.ceiling_y = heights[1];
  // Eq. 3.9/3.10 keep levels 1.5 m apart, but the surfaces inside them may be closer (a lone wall's two
  // ends): what is less than 1.5 m high is no room, as the thesis and DESIGN.md state.
  if (r.ceiling_y - r.floor_y < min_height)
    return no_room("no floor and ceiling found: the fullest levels, at " + metres(r.floor_y) + " and " +
                   metres(r.ceiling_y) + ", are less than " + metres(min_height) + " apart");
  r.storeys.push_back({r.floor_y, r.ceiling_y, levels, {}});
  r.features = std::move(storey_features[0]);
  for (std::size_t i = 1; i < all.size(); ++i) {
    const Storey storey{heights[2 * i], heights[2 * i + 1], *all[i], {}};
    if (storey.ceiling_y - storey.floor_y < min_height) continue;
    r.storeys.push_back(storey);
    r.other_features.push_back(std::move(storey_features[i]));
  }
  r.warnings.insert(r.warnings.end(), label_warnings.begin(), label_warnings.end());
  const bool same_input = same_grid && previous->storeys.size() == r.storeys.size() &&
                          std::equal(r.storeys.begin(), r.storeys.end(), previous->storeys.begin(),
                                     [](const Storey& x, const Storey& y) { return x.levels == y.levels; });
  r.status_message = "ok";
  r.timings.features = clock.lap();
  stop_point(options.stop);

  for (std::uint32_t i = 0; i < r.storeys.size(); ++i) {
    if (r.storey_features(i).facets.size() > 1) whole_input();  // the facets past the first read the input
    r.storeys[i].ceiling_planes = detail::ceiling_planes(spec, in.vertices, in.indices, r.storey_features(i));
  }
  // A run without the areas starts no loop after the features' (the bounds were built beside the heights): its
  // threads end now, while this one lists the rooms.
  if (own_workers && !options.find_areas) own_workers->release();
  // The areas (each storey's, side by side: one storey's search leaves a worker idle now and then, the next
  // fills it) and the bounds, which read the features alone, beside them: the area search's task graph leaves
  // a worker idle at times, the bounds' meshes fill it. The rooms are listed there too, before the bounds: the
  // area search does not read them, and an update's search is its critical path.
  std::vector<AreaResult> storey_areas(options.find_areas ? r.storeys.size() : 0);
  if (caches)
    while (caches->storeys.size() < storey_areas.size()) caches->storeys.push_back(std::make_unique<SearchCache>());
  double areas_wall = 0.0;
  const auto find_all_areas = [&] {
    Stopwatch areas_clock;
    detail::parallel_tasks(storey_areas.size(), options.threads, [&](std::size_t i) {
      const Storey& storey = r.storeys[i];
      storey_areas[i] = find_areas(r.voxels.grid, r.storey_features(i),
                                   {storey.floor_y, storey.ceiling_y, storey.ceiling_planes}, options.areas,
                                   options.features, options.threads, options.stop,
                                   caches ? caches->storeys[i].get() : nullptr);
    });
    areas_wall = areas_clock.lap();
  };
  const auto build_bounds = [&] {
    Stopwatch bounds_clock;
    stop_point(options.stop);
    if (same_input) {  // an IncrementalAnalysis keeps its options: the previous result has its bounds
      r.bounds = previous->bounds;
      r.room_bounds = previous->room_bounds;
    } else if (every_storeys_bounds && r.storeys.size() == all.size()) {  // built beside the heights, every storey kept
      r.bounds = std::move(every_storeys_bounds->bounds);
      r.room_bounds = std::move(every_storeys_bounds->room_bounds);
      r.timings.bounds = every_storeys_bounds_ms;
      return;
    } else {
      std::vector<const RoomFeatures*> kept;
      for (std::size_t i = 0; i < r.storeys.size(); ++i) kept.push_back(&r.storey_features(i));
      AllBounds built = build_all_bounds(r.voxels.grid, kept, options, caches ? &caches->bounds : nullptr);
      r.bounds = std::move(built.bounds);
      r.room_bounds = std::move(built.room_bounds);
    }
    r.timings.bounds = bounds_clock.lap();
  };
  const auto rooms_and_bounds = [&] {
    list_rooms(r);
    if (options.build_bounds) build_bounds();
  };
  if (!options.find_areas) {
    rooms_and_bounds();
  } else {
    detail::parallel_tasks(2, options.threads, [&](std::size_t task) {
      if (task == 0) find_all_areas();
      else rooms_and_bounds();
    });
    if (own_workers) own_workers->release();  // no loop follows: the threads end while the areas are gathered
  }
  for (std::uint32_t i = 0; i < storey_areas.size(); ++i) {
    AreaResult& found = storey_areas[i];
    for (Area& area : found.areas) area.storey = i;
    r.areas.insert(r.areas.end(), found.areas.begin(), found.areas.end());
    for (std::size_t type = 0; type < kAreaTypes.size(); ++type) {
      r.area_counts.found[type] += found.counts.found[type];
      r.area_counts.deduplicated[type] += found.counts.deduplicated[type];
      r.area_counts.reduced[type] += found.counts.reduced[type];
    }
    for (std::string& warning : found.warnings)
      r.warnings.push_back(i == 0 ? std::move(warning) : "storey " + std::to_string(i + 1) + ": " + warning);
    r.timings.areas += found.timings.search;
    r.timings.reduce += found.timings.reduce;
    r.timings.classify += found.timings.classify;
  }
  // Storeys searched side by side: their stage times, scaled to the time they took together.
  const double areas_summed = r.timings.areas + r.timings.reduce + r.timings.classify;
  if (storey_areas.size() > 1 && areas_summed > 0.0)
    for (double* t : {&r.timings.areas, &r.timings.reduce, &r.timings.classify}) *t *= areas_wall / areas_summed;
  assign_area_rooms(r);
  stop_point(options.stop);
  if (caches) caches->previous_labels = std::move(labels);
  r.timings.total = total_clock.lap();  // the areas and the bounds overlap: not the stages' sum
  return r;
}

}  // namespace roomsense
