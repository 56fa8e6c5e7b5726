// CPU vs Vulkan for the voxel stage (thesis §3.1-3.2): per stage and end to end, on the real scans
// (../shared/rooms or ROOMSENSE_ROOMS_DIR, skipped when missing), on a synthetic room of about 78k vertices
// (thesis room 1), the 20 x 14 m hall, and that hall refined to about 1M vertices. Every Vulkan case first
// checks that the device gives the CPU's result bit for bit, and fails (skips with an error) where it does
// not. Vulkan runs report where their time went as counters: host work list and copies against GPU passes
// (timestamp queries). The `analysis/` cases time the whole analysis with each stage, the Vulkan stage
// kept across runs or created for each one (as a one-off CLI run pays). CPU cases run on 2 threads (the
// two-core reference machine) and, where the machine has more, on all of them. Set XDG_CACHE_HOME to keep
// Mesa's shader cache out of $HOME.
//
//   roomsense_bench_compute --benchmark_min_time=0.5
#include "roomsense/analysis.h"
#include "roomsense/grid.h"
#include "roomsense/input.h"
#include "roomsense/scanio.h"
#include "roomsense/synthetic.h"
#include "roomsense/vulkan_voxel_stage.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace roomsense;

struct BenchRoom {
  std::string name;
  Scan scan;
  GridSpec spec;
  std::vector<glm::vec3> grid_vertices;
  std::vector<std::uint32_t> indices;

  VoxelizeRequest request(VoxelMode mode) const {
    VoxelizeRequest r;
    r.spec = spec;
    r.grid_vertices = grid_vertices;
    r.indices = indices;
    r.mode = mode;
    return r;
  }
};

BenchRoom prepare(std::string name, const Scan& scan) {
  const PreparedInput in = prepare_input(scan);
  BenchRoom room;
  room.name = std::move(name);
  room.scan = scan;
  room.spec = make_grid_spec(in.lo, in.hi, kDefaultVoxelSize);
  room.grid_vertices = to_grid_units(in.vertices, room.spec);
  room.indices = in.indices;
  return room;
}

// One stage for the whole run: instance and pipeline creation are a one-off cost, reported separately.
VulkanVoxelStage* vulkan() {
  static std::unique_ptr<VulkanVoxelStage> stage = [] {
    std::string why;
    auto s = VulkanVoxelStage::create({}, &why);
    if (!s) std::cerr << "Vulkan unavailable, its benchmarks are skipped: " << why << '\n';
    return s;
  }();
  return stage.get();
}

const char* mode_name(VoxelMode m) { return m == VoxelMode::Triangles ? "tri" : "vtx"; }

void set_size_counters(benchmark::State& state, const BenchRoom& room) {
  state.counters["voxels"] = double(room.spec.voxel_count());
  state.counters["verts"] = double(room.grid_vertices.size());
  state.counters["tris"] = double(room.indices.size() / 3);
}

void cpu_end_to_end(benchmark::State& state, const BenchRoom& room, VoxelMode mode, unsigned threads) {
  const VoxelizeRequest r = room.request(mode);
  CpuVoxelStage cpu(threads);
  for (auto _ : state) benchmark::DoNotOptimize(cpu.run(r));
  set_size_counters(state, room);
}

bool same_result(const VoxelStageResult& a, const VoxelStageResult& b) {
  return a.grid.spec.nx == b.grid.spec.nx && a.grid.spec.ny == b.grid.spec.ny && a.grid.spec.nz == b.grid.spec.nz &&
         a.grid.cells == b.grid.cells && a.level_counts == b.level_counts && a.levels == b.levels &&
         a.column_counts == b.column_counts && a.column_any == b.column_any;
}

// The CPU's stages one by one: voxelize (Eq. 3.6/3.7), |V_y| (3.8), levels (3.9/3.10), columns (3.11/3.12).
void cpu_stages(benchmark::State& state, const BenchRoom& room, VoxelMode mode) {
  const VoxelizeRequest r = room.request(mode);
  double voxelize = 0, levels = 0, select = 0, columns = 0;
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  for (auto _ : state) {
    const auto t0 = Clock::now();
    VoxelGrid grid = voxelize_cpu(r);
    const auto t1 = Clock::now();
    std::vector<std::uint32_t> counts = count_levels(grid);
    const auto t2 = Clock::now();
    const auto fc = select_floor_ceiling(counts, r.min_separation_levels);
    const auto t3 = Clock::now();
    std::vector<std::uint32_t> cc;
    std::vector<std::uint8_t> any;
    count_columns(grid, fc, cc, any);
    const auto t4 = Clock::now();
    benchmark::DoNotOptimize(any.data());
    voxelize += ms(t0, t1), levels += ms(t1, t2), select += ms(t2, t3), columns += ms(t3, t4);
  }
  const double n = double(state.iterations());
  state.counters["voxelize_ms"] = voxelize / n;
  state.counters["levels_ms"] = levels / n;
  state.counters["select_ms"] = select / n;
  state.counters["columns_ms"] = columns / n;
}

void vulkan_end_to_end(benchmark::State& state, const BenchRoom& room, VoxelMode mode) {
  VulkanVoxelStage* stage = vulkan();
  if (stage == nullptr) {
    state.SkipWithError("no Vulkan device");
    return;
  }
  const VoxelizeRequest r = room.request(mode);
  // Warm (buffers sized, pipelines compiled), and the device's result checked against the CPU's.
  if (!same_result(stage->run(r), CpuVoxelStage().run(r))) {
    state.SkipWithError(stage->last_timings().fell_back ? "fell back to the CPU" : "differs from the CPU result");
    return;
  }
  VulkanRunTimings sum;
  for (auto _ : state) {
    benchmark::DoNotOptimize(stage->run(r));
    const VulkanRunTimings& t = stage->last_timings();
    if (t.fell_back) {
      state.SkipWithError("fell back to the CPU");
      return;
    }
    sum.host_work_list_ms += t.host_work_list_ms;
    sum.host_upload_ms += t.host_upload_ms;
    sum.submit_wait_ms += t.submit_wait_ms;
    sum.host_readback_ms += t.host_readback_ms;
    sum.gpu_upload_ms += t.gpu_upload_ms;
    sum.gpu_vertices_ms += t.gpu_vertices_ms;
    sum.gpu_triangles_ms += t.gpu_triangles_ms;
    sum.gpu_levels_ms += t.gpu_levels_ms;
    sum.gpu_select_ms += t.gpu_select_ms;
    sum.gpu_columns_ms += t.gpu_columns_ms;
    sum.gpu_readback_ms += t.gpu_readback_ms;
  }
  const double n = double(state.iterations());
  // Transfer: host copies in and out plus GPU-side staging copies and clears. Compute: the GPU passes.
  state.counters["xfer_ms"] = (sum.host_upload_ms + sum.host_readback_ms + sum.gpu_upload_ms + sum.gpu_readback_ms) / n;
  state.counters["gpu_ms"] = (sum.gpu_vertices_ms + sum.gpu_triangles_ms + sum.gpu_levels_ms + sum.gpu_select_ms +
                              sum.gpu_columns_ms) / n;
  state.counters["worklist_ms"] = sum.host_work_list_ms / n;
  state.counters["submit_wait_ms"] = sum.submit_wait_ms / n;
  state.counters["voxelize_ms"] = (sum.gpu_vertices_ms + sum.gpu_triangles_ms) / n;
  state.counters["levels_ms"] = sum.gpu_levels_ms / n;
  state.counters["select_ms"] = sum.gpu_select_ms / n;
  state.counters["columns_ms"] = sum.gpu_columns_ms / n;
  set_size_counters(state, room);
  state.SetLabel(stage->device().name);
}

enum class StageUse { Cpu, VulkanKept, VulkanPerRun };

// The whole analysis (understanding and bounds) with the voxel stage `use` picks, on `threads` threads.
void analysis(benchmark::State& state, const BenchRoom& room, StageUse use, unsigned threads) {
  AnalysisOptions options;
  options.threads = threads;
  if (use == StageUse::VulkanKept) {
    options.voxel_stage = vulkan();
    if (options.voxel_stage == nullptr) {
      state.SkipWithError("no Vulkan device");
      return;
    }
  }
  benchmark::DoNotOptimize(analyze(room.scan, options));  // warm
  for (auto _ : state) {
    std::unique_ptr<VulkanVoxelStage> own;
    if (use == StageUse::VulkanPerRun) {
      std::string why;
      own = VulkanVoxelStage::create({}, &why);
      if (!own) {
        state.SkipWithError(why.c_str());
        return;
      }
      options.voxel_stage = own.get();
    }
    benchmark::DoNotOptimize(analyze(room.scan, options));
  }
  set_size_counters(state, room);
}

// One-off cost of Vulkan: instance, device, pipelines (what a first run pays unless the stage is kept).
void vulkan_create(benchmark::State& state) {
  for (auto _ : state) {
    std::string why;
    auto stage = VulkanVoxelStage::create({}, &why);
    if (!stage) {
      state.SkipWithError(why.c_str());
      return;
    }
    benchmark::DoNotOptimize(stage.get());
  }
}

std::vector<BenchRoom>& rooms() {
  static std::vector<BenchRoom> all;
  return all;
}

// `spec` with its triangle size scaled until the generated room has about `vertices` vertices.
synth::RoomSpec refined(synth::RoomSpec spec, double vertices) {
  for (int i = 0; i < 4; ++i) {
    const double n = double(synth::generate(spec).vertices.size());
    if (n <= 0 || std::abs(n - vertices) < 0.03 * vertices) break;
    spec.cell *= float(std::sqrt(n / vertices));
  }
  return spec;
}

std::filesystem::path rooms_dir() {
  if (const char* env = std::getenv("ROOMSENSE_ROOMS_DIR"); env != nullptr && *env != '\0') return env;
  return ROOMSENSE_BENCH_ROOMS_DIR;
}

void load_rooms() {
  const std::filesystem::path dir = rooms_dir();
  const char* const scans[] = {"hololens1/holotoolkit_fake_spatial_mapping.obj", "hololens1/mrtk_example_spatial_mesh.obj",
                               "hololens2-su/SU_Apartment_world_mesh.obj",      "hololens2-su/SU_Kitchen_world_mesh.obj",
                               "quest-iwer/living_room_global_mesh.obj",        "quest-iwer/meeting_room_global_mesh.obj",
                               "quest-iwer/music_room_global_mesh.obj",         "quest-iwer/office_large_global_mesh.obj",
                               "quest-iwer/office_small_global_mesh.obj"};
  for (const char* rel : scans) {
    const std::filesystem::path path = dir / rel;
    if (!std::filesystem::exists(path)) {
      std::cerr << "skipping missing scan " << path << '\n';
      continue;
    }
    rooms().push_back(prepare(path.stem().string(), scanio::load_mesh_file(path.string())));
  }
  // The thesis's room 1 has about 78k vertices; the GPU goal is set on a scan of 1M.
  rooms().push_back(prepare("synthetic_78k", synth::generate(refined(synth::thesis_room1(), 78000.0))));
  rooms().push_back(prepare("synthetic_hall", synth::generate(synth::hall_room())));
  rooms().push_back(prepare("synthetic_hall_1m", synth::generate(refined(synth::hall_room(), 1.0e6))));
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  load_rooms();
  benchmark::RegisterBenchmark("vulkan/create_stage", vulkan_create)->Unit(benchmark::kMillisecond)->Iterations(3);
  // 2 threads: the reference machine; all of them, where there are more.
  std::vector<unsigned> thread_counts{2};
  if (const unsigned all = std::thread::hardware_concurrency(); all > 2) thread_counts.push_back(all);
  for (const BenchRoom& room : rooms()) {
    for (VoxelMode mode : {VoxelMode::Vertices, VoxelMode::Triangles}) {
      const std::string suffix = room.name + "/" + mode_name(mode);
      for (unsigned threads : thread_counts)
        benchmark::RegisterBenchmark(("cpu/end_to_end/" + suffix + "/threads:" + std::to_string(threads)).c_str(),
                                     cpu_end_to_end, room, mode, threads)
            ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("cpu/stages/" + suffix).c_str(), cpu_stages, room, mode)->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("vulkan/end_to_end/" + suffix).c_str(), vulkan_end_to_end, room, mode)->Unit(benchmark::kMillisecond);
    }
    for (unsigned threads : thread_counts) {
      const std::string suffix = "/threads:" + std::to_string(threads);
      for (const auto& [use, name] : {std::pair{StageUse::Cpu, "cpu"}, std::pair{StageUse::VulkanKept, "vulkan_kept"},
                                      std::pair{StageUse::VulkanPerRun, "vulkan_created"}})
        benchmark::RegisterBenchmark(("analysis/" + room.name + "/" + name + suffix).c_str(), analysis, room, use, threads)
            ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
