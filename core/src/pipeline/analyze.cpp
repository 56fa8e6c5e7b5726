// The pipeline of thesis chapter 3 in the order of DESIGN.md's data flow.
#include "roomsense/analysis.h"
#include "roomsense/cancel.h"
#include "roomsense/error.h"
#include "roomsense/number_text.h"
#include "surface_heights.h"

#include <chrono>

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

}  // namespace

AnalysisResult analyze(const Scan& scan, const AnalysisOptions& options) {
  Stopwatch clock;
  AnalysisResult r;
  stop_point(options.stop);
  const PreparedInput in = prepare_input(scan, options.reject_outliers);
  r.input = {in.input_vertices, in.input_triangles, in.skipped_vertices, in.outlier_vertices, in.dropped_triangles};
  if (in.skipped_vertices > 0)
    r.warnings.push_back(std::to_string(in.skipped_vertices) + " vertices with NaN or Inf coordinates skipped");
  if (in.outlier_vertices > 0)
    r.warnings.push_back(std::to_string(in.outlier_vertices) + " outlier vertices far from the room rejected");
  if (in.dropped_triangles > 0)
    r.warnings.push_back(std::to_string(in.dropped_triangles) + " triangles touching skipped vertices dropped");

  r.mode = options.mode.value_or(in.indices.empty() ? VoxelMode::Vertices : VoxelMode::Triangles);
  if (r.mode == VoxelMode::Triangles && in.indices.empty()) {
    r.mode = VoxelMode::Vertices;
    r.warnings.push_back("triangle mode asked for a scan without triangles: vertex mode used");
  }
  const GridSpec spec = make_grid_spec(in.lo, in.hi, options.voxel_size, options.voxel_budget);
  const std::vector<glm::vec3> grid_vertices = to_grid_units(in.vertices, spec);
  const int min_separation = voxels_for(options.features.min_floor_ceiling, spec.voxel_size);
  r.timings.prepare = clock.lap();

  stop_point(options.stop);
  CpuVoxelStage cpu(options.threads);
  VoxelStage& stage = options.voxel_stage != nullptr ? *options.voxel_stage : cpu;
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
  const FloorCeiling& levels = *r.voxels.levels;
  const auto height = [&](int lower, int upper) { return detail::surface_height(spec, in.vertices, in.indices, lower, upper); };
  r.floor_y = height(levels.floor_peak, levels.floor);
  r.ceiling_y = height(levels.ceiling, levels.ceiling_peak);
  // Eq. 3.9/3.10 keep levels 1.5 m apart, but the surfaces inside them may be closer (a lone wall's two
  // ends): what is less than 1.5 m high is no room, as the thesis and DESIGN.md state.
  if (r.ceiling_y - r.floor_y < min_height)
    return no_room("no floor and ceiling found: the fullest levels, at " + metres(r.floor_y) + " and " +
                   metres(r.ceiling_y) + ", are less than " + metres(min_height) + " apart");
  r.storeys.push_back({r.floor_y, r.ceiling_y});
  for (const FloorCeiling& other : detail::other_storeys(r.voxels.level_counts, levels, min_separation)) {
    const Storey storey{height(other.floor_peak, other.floor), height(other.ceiling, other.ceiling_peak)};
    if (storey.ceiling_y - storey.floor_y >= min_height) r.storeys.push_back(storey);
  }
  const LabelGrid labels = voxelize_labels(spec, scan.labels, options.voxel_test_budget, r.warnings);
  r.features = detect_features(r.voxels, options.features, options.threads, options.stop, labels);
  r.status_message = "ok";
  r.timings.features = clock.lap();
  stop_point(options.stop);

  if (options.find_areas) {
    AreaResult found = find_areas(r.voxels.grid, *r.features, {r.floor_y, r.ceiling_y}, options.areas,
                                  options.features, options.threads, options.stop);
    r.areas = std::move(found.areas);
    r.area_counts = found.counts;
    r.warnings.insert(r.warnings.end(), found.warnings.begin(), found.warnings.end());
    r.timings.areas = found.timings.search;
    r.timings.reduce = found.timings.reduce;
    r.timings.classify = found.timings.classify;
    clock.lap();
  }
  stop_point(options.stop);
  if (options.build_bounds) {
    r.bounds = build_bounds(r.voxels.grid, levels, r.features->y_end, r.features->room, options.bounds,
                            options.threads, options.stop);
    r.timings.bounds = clock.lap();
  }
  r.timings.total = r.timings.prepare + r.timings.voxelize + r.timings.features + r.timings.areas +
                    r.timings.reduce + r.timings.classify + r.timings.bounds;
  return r;
}

}  // namespace roomsense
