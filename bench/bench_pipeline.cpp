// Per-stage timings of the room pipeline on every real scan and on synthetic rooms (Google Benchmark).
// Run: build/bench/roomsense_bench [--benchmark_filter=...]. Loading is excluded everywhere. Each case also
// reports peak_MB, the most heap one iteration held beyond what was live before it (heap_meter.h).
#include "heap_meter.h"
#include "roomsense/analysis.h"
#include "roomsense/areas.h"
#include "roomsense/bounds.h"
#include "roomsense/features.h"
#include "roomsense/incremental.h"
#include "roomsense/scanio.h"
#include "roomsense/synthetic.h"

#include <benchmark/benchmark.h>
#if ROOMSENSE_BENCH_LAYER_FEED
#include "../layer/src/chunk_feed.h"
#endif
#include "../core/src/pipeline/surface_heights.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace roomsense;

struct BenchRoom {
  std::string name;
  Scan scan;
};

std::vector<BenchRoom> load_rooms() {
  std::vector<BenchRoom> rooms;
  for (const char* name : {"thesis-room1", "hall", "default", "house", "flat"})
    rooms.push_back({std::string("synthetic:") + name, synth::generate_builtin_source(std::string("synthetic:") + name)});
  const std::filesystem::path dir = ROOMSENSE_BENCH_ROOMS_DIR;
  for (const char* file : {"hololens1/holotoolkit_fake_spatial_mapping.obj", "hololens1/mrtk_example_spatial_mesh.obj",
                           "hololens2-su/SU_Kitchen_world_mesh.obj", "hololens2-su/SU_Apartment_world_mesh.obj",
                           "quest-iwer/living_room_global_mesh.obj", "quest-iwer/meeting_room_global_mesh.obj",
                           "quest-iwer/music_room_global_mesh.obj", "quest-iwer/office_large_global_mesh.obj",
                           "quest-iwer/office_small_global_mesh.obj"}) {
    if (std::filesystem::exists(dir / file)) rooms.push_back({file, scanio::load_mesh_file((dir / file).string())});
    else std::fprintf(stderr, "skipping %s: not found under %s\n", file, dir.c_str());
  }
  return rooms;
}

// A box of side `side` standing on `corner` (its lowest x, y, z), its five faces but the bottom each n x n quads
// of two triangles: an object a headset meshes as one chunk.
Scan box_chunk(const glm::vec3& corner, float side, int n) {
  Scan s;
  const auto face = [&](const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v) {
    const auto base = std::uint32_t(s.vertices.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) s.vertices.push_back(origin + u * (float(i) / float(n)) + v * (float(j) / float(n)));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::uint32_t a = base + std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
        s.indices.insert(s.indices.end(), {a, b, d, a, d, c});
      }
  };
  const glm::vec3 x(side, 0, 0), y(0, side, 0), z(0, 0, side);
  face(corner + y, x, z);
  face(corner, x, y);
  face(corner + z, x, y);
  face(corner, z, y);
  face(corner + x, z, y);
  return s;
}

using Versions = std::vector<std::pair<std::uint64_t, std::array<Scan, 2>>>;

// Every block of a room into `inc`, and the time of its first result (counter first_ms).
const AnalysisResult& first_result(benchmark::State& state, IncrementalAnalysis& inc, const Versions& versions) {
  const auto start = std::chrono::steady_clock::now();
  for (const auto& [id, two] : versions) inc.set_chunk(id, two[1]);
  const AnalysisResult& r = inc.result();
  state.counters["first_ms"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// The object of update_object/ for turn `turn`: added on even turns, at one of 24 places spread over the room's
// floor (each place twice in a row: added, then removed).
Scan object_at(const GridSpec& grid, float floor_y, std::size_t turn) {
  const std::size_t place = (turn / 2) % 24;
  const float fx = 0.2f + 0.6f * float(place % 6) / 5.0f, fz = 0.2f + 0.6f * float(place / 6) / 3.0f;
  return box_chunk(glm::vec3(grid.origin.x + fx * float(grid.nx) * grid.voxel_size, floor_y,
                             grid.origin.z + fz * float(grid.nz) * grid.voxel_size),
                   0.4f, 14);
}

// Each iteration: `change` (one chunk set or removed) of what `arrive` gave, then the new result; the percentiles of
// those times, and how many chunks an update voxelized and what share of the area searches' bands it searched.
// `arrive` runs before the clock: the chunk as the runtime hands it over (made, or copied from the room's blocks),
// which is not the update's cost; `change` moves it in.
template <class Arrive, class Change>
void time_updates(benchmark::State& state, IncrementalAnalysis& inc, Arrive arrive, Change change) {
  std::vector<double> ms;
  // The result's own stage times, for where an update's time goes: the areas' (search, reduction and reach
  // together) and the bounds' overlap (analyze.cpp), so neither adds to the other.
  std::array<std::vector<double>, 5> stages;
  double revoxelized = 0, bands_searched = 0, bands = 0;
  for (auto _ : state) {
    auto arrived = arrive();
    const auto start = std::chrono::steady_clock::now();
    change(std::move(arrived));
    const StageTimings& t = inc.result().timings;
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    const std::array<double, 5> stage = {t.prepare, t.voxelize, t.features, t.areas + t.reduce + t.classify, t.bounds};
    for (std::size_t k = 0; k < stage.size(); ++k) stages[k].push_back(stage[k]);
    revoxelized += double(inc.revoxelized_chunks());
    bands_searched += double(inc.area_bands_searched()), bands += double(inc.area_bands_total());
  }
  std::sort(ms.begin(), ms.end());
  for (std::vector<double>& times : stages) std::sort(times.begin(), times.end());
  const auto percentile = [](const std::vector<double>& sorted, double p) {
    return sorted.empty() ? 0.0 : sorted[std::size_t(p * double(sorted.size() - 1))];
  };
  state.counters["p10_ms"] = percentile(ms, 0.1);
  state.counters["p50_ms"] = percentile(ms, 0.5);
  state.counters["p90_ms"] = percentile(ms, 0.9);
  state.counters["max_ms"] = percentile(ms, 1.0);
  const std::array<const char*, 5> names = {"prepare_p50", "voxelize_p50", "features_p50", "areas_p50", "bounds_p50"};
  for (std::size_t k = 0; k < names.size(); ++k) state.counters[names[k]] = percentile(stages[k], 0.5);
  state.counters["revoxelized"] = revoxelized / double(std::max<std::size_t>(1, ms.size()));
  state.counters["bands_searched"] = bands > 0 ? bands_searched / bands : 0.0;
}

// Inputs prepared once per room, so each benchmark times only its own stage.
struct Prepared {
  PreparedInput input;
  GridSpec spec;
  std::vector<glm::vec3> grid_vertices;
  VoxelStageResult voxels;
  RoomFeatures features;
  SurfaceLevels surfaces;
};

std::shared_ptr<Prepared> prepare(const Scan& scan) {
  auto p = std::make_shared<Prepared>();
  p->input = prepare_input(scan);
  p->spec = make_grid_spec(p->input.lo, p->input.hi, kDefaultVoxelSize);
  p->grid_vertices = to_grid_units(p->input.vertices, p->spec);
  p->voxels = CpuVoxelStage().run({p->spec, p->grid_vertices, p->input.indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}});
  p->features = detect_features(p->voxels, {});
  const float s = p->spec.voxel_size;
  p->surfaces = {p->spec.origin.y + float(p->features.levels.floor + 1) * s,
                 p->spec.origin.y + float(p->features.levels.ceiling) * s, {}};
  return p;
}

// §3.3-3.5 on prepared features, with the split into search, reduction and classification and the room's
// free floor, so the growth with room size can be read off.
void time_areas(benchmark::State& state, const Prepared& p) {
  AreaTimings sum;
  std::size_t areas = 0;
  for (auto _ : state) {
    AreaResult r = find_areas(p.voxels.grid, p.features, p.surfaces, {}, {});
    sum.search += r.timings.search, sum.reduce += r.timings.reduce, sum.classify += r.timings.classify;
    areas = r.areas.size();
    benchmark::DoNotOptimize(r);
  }
  const double n = double(state.iterations());
  state.counters["search_ms"] = sum.search / n;
  state.counters["reduce_ms"] = sum.reduce / n;
  state.counters["classify_ms"] = sum.classify / n;
  state.counters["areas"] = double(areas);
  const double tile = double(p.spec.voxel_size) * double(p.spec.voxel_size);
  state.counters["free_floor_m2"] =
      tile * double(std::count(p.features.free_floor.begin(), p.features.free_floor.end(), std::uint8_t{1}));
}

void counters(benchmark::State& state, const BenchRoom& room) {
  state.counters["vertices"] = double(room.scan.vertices.size());
  state.counters["triangles"] = double(room.scan.indices.size() / 3);
}

// Registers `name`, timing body() per iteration and reporting peak_MB: the most heap any iteration held beyond
// what was live when the case started.
template <class Body>
benchmark::internal::Benchmark* register_case(const std::string& name, Body body) {
  return benchmark::RegisterBenchmark(name.c_str(), [body](benchmark::State& state) {
    const std::size_t base = bench::live_heap_bytes();
    bench::reset_heap_peak();
    body(state);
    state.counters["peak_MB"] = double(bench::peak_heap_bytes() - std::min(base, bench::peak_heap_bytes())) / 1e6;
  })->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string filter = [&] {  // read before Initialize, which takes the flags out of argv
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]).rfind("--benchmark_filter=", 0) == 0) return std::string(argv[i]).substr(19);
    return std::string();
  }();
  benchmark::Initialize(&argc, argv);
  // On stderr: --benchmark_format=json writes the results alone to stdout.
  std::fprintf(stderr,
      "Thesis figures (6-core i7-5820K, rooms 1-2 of about 78k vertices): room understanding 55-180 ms,\n"
      "room bounds 18-37 ms. Targets here (2 cores): bounds <= 5 ms and understanding <= 20 ms on a ~78k-vertex room.\n"
      "Stages: voxelize = voxel stage (V, |V_y|, levels, |V_xz|); heights = the floor's and ceiling's height sums\n"
      "(one thread); features = A-F; areas = search + reduce + classify\n"
      "(§3.3-3.5); understanding = prepare + voxelize + features + areas (what StartRoomUnderstanding runs);\n"
      "understanding_kept = the same on worker threads kept from one analysis to the next (an analyzer handle's);\n"
      "bounds = I + its mesh; bounds_pipeline = prepare + voxelize + A/B + bounds; analyze_bounds = analyze() without\n"
      "the areas (what StartRoomBounds runs: the features, storeys and rooms the bounds read, and the bounds); analyze = all.\n\n");
  static const std::vector<BenchRoom> rooms = load_rooms();
  for (const BenchRoom& room : rooms) {
    const auto p = prepare(room.scan);
    register_case("voxelize/" + room.name, [&room, p](benchmark::State& state) {
      CpuVoxelStage stage;
      for (auto _ : state)
        benchmark::DoNotOptimize(stage.run({p->spec, p->grid_vertices, p->input.indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}}));
      counters(state, room);
    });
    // The floor's and ceiling's height sums (surface_heights.h), one pass over the triangles on one thread: a
    // whole analysis runs it beside the features (12 % of a bounds-only run on thesis-room1, bench/README.md).
    register_case("heights/" + room.name, [&room, p](benchmark::State& state) {
      if (!p->voxels.levels) {
        state.SkipWithError("no floor and ceiling levels");
        return;
      }
      const FloorCeiling& fc = *p->voxels.levels;
      const std::vector<detail::BandLimits> bands = {detail::band_limits(p->spec, fc.floor_peak, fc.floor),
                                                     detail::band_limits(p->spec, fc.ceiling, fc.ceiling_peak)};
      for (auto _ : state) benchmark::DoNotOptimize(detail::band_sums(p->input.vertices, p->input.indices, bands, 1));
      counters(state, room);
    });
    register_case("features/" + room.name, [&room, p](benchmark::State& state) {
      for (auto _ : state) benchmark::DoNotOptimize(detect_features(p->voxels, {}));
      counters(state, room);
    });
    register_case("areas/" + room.name, [&room, p](benchmark::State& state) {
      time_areas(state, *p);
      counters(state, room);
    });
    register_case("understanding/" + room.name, [&room](benchmark::State& state) {
      AnalysisOptions o;
      o.build_bounds = false;
      for (auto _ : state) benchmark::DoNotOptimize(analyze(room.scan, o));
      counters(state, room);
    });
    // The same with the worker threads kept from one analysis to the next (KeptThreads), as an engine holding an
    // analyzer handle of the C API runs it: analyze() alone starts and joins its threads each time.
    register_case("understanding_kept/" + room.name, [&room](benchmark::State& state) {
      KeptThreads kept;
      AnalysisOptions o;
      o.build_bounds = false;
      o.kept_threads = &kept;
      for (auto _ : state) benchmark::DoNotOptimize(analyze(room.scan, o));
      counters(state, room);
    });
    register_case("bounds/" + room.name, [&room, p](benchmark::State& state) {
      for (auto _ : state)
        benchmark::DoNotOptimize(build_bounds(p->voxels.grid, *p->voxels.levels, p->features.y_end, p->features.room));
      counters(state, room);
    });
    register_case("bounds_pipeline/" + room.name, [&room](benchmark::State& state) {
      for (auto _ : state) {
        const PreparedInput in = prepare_input(room.scan);
        const GridSpec spec = make_grid_spec(in.lo, in.hi, kDefaultVoxelSize);
        const std::vector<glm::vec3> g = to_grid_units(in.vertices, spec);
        const VoxelStageResult v = CpuVoxelStage().run({spec, g, in.indices, VoxelMode::Triangles, 15, kDefaultVoxelTestBudget, {}});
        const int y_end = v.levels->floor + voxels_for(1.5f, spec.voxel_size);
        const std::vector<std::uint8_t> room_mask = detect_room(spec, v.column_any);
        benchmark::DoNotOptimize(build_bounds(v.grid, *v.levels, y_end, room_mask));
      }
      counters(state, room);
    });
    // The bounds as the thesis API's StartRoomBounds runs them alone: analyze() without the area search and
    // without the features only it and the queries read (AnalysisOptions::area_features), so the features,
    // storeys and rooms the bounds read are found too. (The handle API's RS_COMPUTE_BOUNDS keeps every feature:
    // its placement queries read them.)
    register_case("analyze_bounds/" + room.name, [&room](benchmark::State& state) {
      AnalysisOptions o;
      o.find_areas = false;
      o.area_features = false;  // as StartRoomBounds runs
      for (auto _ : state) benchmark::DoNotOptimize(analyze(room.scan, o));
      counters(state, room);
    });
    register_case("analyze/" + room.name, [&room](benchmark::State& state) {
      for (auto _ : state) benchmark::DoNotOptimize(analyze(room.scan));
      counters(state, room);
    });
    // Issue 19: one 2 x 2 m block of the room re-sent (refined: every fifth triangle gone, or back as it was),
    // then the new result, on an IncrementalAnalysis that holds every block. Every block twice, in turn (the
    // iterations are fixed to that), so the percentiles are those of every block of the room.
    auto versions = std::make_shared<Versions>();
    for (auto& [id, block] : split_into_blocks(room.scan)) {
      Scan refined = block;
      refined.indices.clear();
      for (std::size_t t = 0; t + 2 < block.indices.size(); t += 3)
        if ((t / 3) % 5 != 4) refined.indices.insert(refined.indices.end(), &block.indices[t], &block.indices[t] + 3);
      versions->push_back({id, {std::move(refined), std::move(block)}});
    }
    register_case("update/" + room.name, [&room, versions](benchmark::State& state) {
      IncrementalAnalysis inc;
      first_result(state, inc, *versions);
      std::size_t turn = 0;
      time_updates(
          state, inc,
          [&] {
            const auto& [id, two] = (*versions)[turn % versions->size()];
            return std::pair(id, two[(turn++ / versions->size()) % 2]);
          },
          [&](std::pair<std::uint64_t, Scan> block) { inc.set_chunk(block.first, std::move(block.second)); });
      double block_triangles = 0;
      for (const auto& [id, two] : *versions) block_triangles += double(two[1].indices.size() / 3);
      state.counters["blocks"] = double(versions->size());
      state.counters["block_triangles"] = block_triangles / double(std::max<std::size_t>(1, versions->size()));
      counters(state, room);
    })->Iterations(benchmark::IterationCount(2 * std::max<std::size_t>(1, versions->size())));
    // Issue 19's per-update case: a chunk of 1,960 triangles (a 0.4 m box of fine triangles standing on the
    // floor) added, then removed, at 24 places spread over the room, the room held in blocks as above.
    register_case("update_object/" + room.name, [&room, versions](benchmark::State& state) {
      IncrementalAnalysis inc;
      const AnalysisResult& first = first_result(state, inc, *versions);
      const GridSpec grid = first.voxels.grid.spec;
      const float floor_y = first.floor_y;
      // Below split_into_blocks's ids (about 2^63): the object comes first in id order, so every update also
      // copies every block into the combined scan again (incremental.h), the most an added chunk costs there.
      constexpr std::uint64_t kObject = std::uint64_t{1} << 62;
      std::size_t turn = 0;
      time_updates(
          state, inc,
          [&] {  // added on even turns, else removed
            const std::size_t t = turn++;
            return t % 2 == 0 ? std::optional(object_at(grid, floor_y, t)) : std::nullopt;
          },
          [&](std::optional<Scan> object) {
            if (object) inc.set_chunk(kObject, std::move(*object));
            else inc.remove_chunk(kObject);
          });
      state.counters["object_triangles"] = double(box_chunk({}, 0.4f, 14).indices.size() / 3);
      counters(state, room);
    })->Iterations(48);
#if ROOMSENSE_BENCH_LAYER_FEED
    // The same object through the layer's way in: each compute keys every mesh of the room (the runtime serves
    // them all again), its ChunkFeed measures the workload and gives the analysis the changed meshes alone, with
    // the object's id sorting last, as ChunkIds gives a new mesh.
    register_case("update_object_layer/" + room.name, [&room, versions](benchmark::State& state) {
      std::vector<layer::MeshPiece> meshes;
      std::vector<std::uint64_t> block_ids;
      for (const auto& [id, two] : *versions) meshes.push_back({two[1].vertices, two[1].indices}), block_ids.push_back(id);
      IncrementalAnalysis inc;
      layer::ChunkFeed feed;
      const auto compute = [&](const layer::MeshPiece* object) {
        std::vector<layer::FedPiece> pieces;
        std::vector<std::uint64_t> ids = block_ids;
        for (const layer::MeshPiece& m : meshes) pieces.push_back({&m, nullptr, layer::piece_key(m, nullptr)});
        if (object) pieces.push_back({object, nullptr, layer::piece_key(*object, nullptr)}), ids.push_back(~std::uint64_t{0});
        benchmark::DoNotOptimize(feed.workload(pieces, ids, 0.1f));
        feed.feed(inc, pieces, ids);
      };
      compute(nullptr);
      const AnalysisResult& first = inc.result();
      if (!first.ok()) {
        state.SkipWithError(first.status_message.c_str());
        return;
      }
      const GridSpec grid = first.voxels.grid.spec;
      const float floor_y = first.floor_y;
      std::size_t turn = 0;
      layer::MeshPiece object;
      time_updates(
          state, inc,
          [&] {  // the runtime's buffers of the object, on even turns
            const std::size_t t = turn++;
            if (t % 2 != 0) return false;
            Scan box = object_at(grid, floor_y, t);
            object = {std::move(box.vertices), std::move(box.indices)};
            return true;
          },
          [&](bool added) { compute(added ? &object : nullptr); });
      counters(state, room);
    })->Iterations(48);
#endif
  }
  // How the area search grows with room size: empty-ish halls of increasing floor area.
  for (const float scale : {0.25f, 0.5f, 1.0f, 1.5f}) {
    const std::string name = "area_growth/hall_" + std::to_string(int(20 * scale)) + "x" + std::to_string(int(14 * scale));
    const auto p = prepare(synth::generate(synth::hall_room(20.0f * scale, 14.0f * scale)));
    register_case(name, [p](benchmark::State& state) { time_areas(state, *p); });
  }
  // The area search alone on open floors of 50 x 50 and 90 x 90 m (about the largest the default voxel budget
  // takes at 0.1 m; issue 19 bounds its memory by the grid's): generated only when the filter asks for growth.
  if (filter.find("growth") != std::string::npos)
    for (const float side : {50.0f, 90.0f}) {
      const std::string name = "area_growth/hall_" + std::to_string(int(side)) + "x" + std::to_string(int(side));
      const auto p = prepare(synth::generate(synth::hall_room(side, side)));
      register_case(name, [p](benchmark::State& state) {
        time_areas(state, *p);
        state.counters["grid_MB"] = double(p->voxels.grid.cells.size()) / 1e6;
      });
    }
  // How the whole analysis (understanding and bounds) grows with room size, up to a 50 x 50 m open floor: the
  // hall's furniture rows over ever larger floors. Generated only when the filter asks for them.
  if (filter.find("growth") != std::string::npos) {
    for (const auto& [w, d] : std::vector<std::pair<float, float>>{{10, 7}, {20, 14}, {30, 21}, {40, 28}, {50, 50}}) {
      const std::string name = "analyze_growth/hall_" + std::to_string(int(w)) + "x" + std::to_string(int(d));
      auto scan = std::make_shared<const Scan>(synth::generate(synth::hall_room(w, d)));
      register_case(name, [scan](benchmark::State& state) {
        AnalysisResult r;
        for (auto _ : state) {
          r = analyze(*scan);
          benchmark::DoNotOptimize(r);
        }
        const GridSpec& g = r.voxels.grid.spec;
        state.counters["grid_m2"] = double(g.nx) * double(g.nz) * double(g.voxel_size) * double(g.voxel_size);
        state.counters["grid_MB"] = double(r.voxels.grid.cells.size()) / 1e6;
        state.counters["areas"] = double(r.areas.size());
        state.counters["triangles"] = double(scan->indices.size() / 3);
      });
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
