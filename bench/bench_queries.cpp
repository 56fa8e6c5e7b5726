// Placement queries (queries.h) on every real scan and on synthetic rooms (Google Benchmark): building the
// RoomQueries of an analysis, find_placements for 10 objects on each kind of surface, one raycast, random points,
// and how they grow with room size. The analysis itself is done once per room, outside the timings.
// Run: build/bench/roomsense_bench_queries [--benchmark_filter=...].
#include "roomsense/analysis.h"
#include "roomsense/queries.h"
#include "roomsense/scanio.h"
#include "roomsense/surfaces.h"
#include "roomsense/synthetic.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace roomsense;

struct BenchRoom {
  std::string name;
  std::size_t vertices = 0;
  AnalysisResult analysis;
  std::vector<Surface> surfaces;
  RoomQueries queries;
  glm::vec3 centre{0.0f};  // the middle of the room's bounds, 1.2 m above its floor
};

std::shared_ptr<BenchRoom> analysed(std::string name, const Scan& scan) {
  auto room = std::make_shared<BenchRoom>();
  room->name = std::move(name);
  room->vertices = scan.vertices.size();
  room->analysis = analyze(scan);
  room->surfaces = extract_surfaces(room->analysis);
  room->queries = RoomQueries(room->analysis, room->surfaces);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& v : room->analysis.bounds.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  room->centre = glm::vec3(0.5f * (lo.x + hi.x), room->analysis.floor_y + 1.2f, 0.5f * (lo.z + hi.z));
  return room;
}

std::vector<std::shared_ptr<BenchRoom>> load_rooms() {
  std::vector<std::shared_ptr<BenchRoom>> rooms;
  for (const char* name : {"thesis-room1", "default", "hall"})
    rooms.push_back(analysed(std::string("synthetic:") + name, synth::generate(*synth::builtin(name))));
  const std::filesystem::path dir = ROOMSENSE_BENCH_ROOMS_DIR;
  for (const char* file : {"hololens1/holotoolkit_fake_spatial_mapping.obj", "hololens2-su/SU_Kitchen_world_mesh.obj",
                           "hololens2-su/SU_Apartment_world_mesh.obj", "quest-iwer/living_room_global_mesh.obj",
                           "quest-iwer/office_large_global_mesh.obj", "quest-iwer/office_small_global_mesh.obj"}) {
    if (std::filesystem::exists(dir / file)) rooms.push_back(analysed(file, scanio::load_mesh_file((dir / file).string())));
    else std::fprintf(stderr, "skipping %s: not found under %s\n", file, dir.c_str());
  }
  return rooms;
}

PlacementQuery ten(glm::vec3 size, std::uint32_t surfaces, float clearance = 0.0f) {
  PlacementQuery q;
  q.size = size;
  q.surfaces = surfaces;
  q.clearance = clearance;
  q.max_count = 10;
  return q;
}

void room_counters(benchmark::State& state, const BenchRoom& room) {
  const GridSpec& s = room.analysis.voxels.grid.spec;
  state.counters["vertices"] = double(room.vertices);
  state.counters["columns"] = double(s.column_count());
  state.counters["floor_m2"] = double(s.column_count()) * double(s.voxel_size) * double(s.voxel_size);
}

void register_queries(const std::shared_ptr<BenchRoom>& room, bool everything) {
  const std::string& n = room->name;
  benchmark::RegisterBenchmark(("queries_build/" + n).c_str(), [room](benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(RoomQueries(room->analysis, room->surfaces));
    room_counters(state, *room);
  })->Unit(benchmark::kMillisecond);
  const std::pair<const char*, PlacementQuery> queries[] = {
      {"floor_0.5m_clear0.2", ten({0.5f, 0.5f, 1.0f}, kOnFloor, 0.2f)},
      {"furniture_0.3m", ten({0.3f, 0.3f, 0.3f}, kOnFurniture)},
      {"wall_0.6x0.4", ten({0.6f, 0.4f, 0.05f}, kOnWall)},
      {"any_0.3m", ten({0.3f, 0.3f, 0.3f}, kOnAnySurface)}};
  for (const auto& [label, query] : queries) {
    if (!everything && std::string(label) != "floor_0.5m_clear0.2") continue;
    benchmark::RegisterBenchmark(("place10/" + std::string(label) + "/" + n).c_str(), [room, q = query](benchmark::State& state) {
      std::size_t found = 0;
      for (auto _ : state) {
        const PlacementResult r = room->queries.find_placements(q);
        found = r.placements.size();
        benchmark::DoNotOptimize(r);
      }
      state.counters["found"] = double(found);
      room_counters(state, *room);
    })->Unit(benchmark::kMicrosecond);
  }
  // One ray per iteration, from the room's middle in 64 directions in turn (some up, some down).
  benchmark::RegisterBenchmark(("raycast/" + n).c_str(), [room](benchmark::State& state) {
    std::vector<glm::vec3> directions;
    for (int i = 0; i < 64; ++i) {
      const float a = float(i) * 0.7853982f * 0.37f, e = std::sin(float(i) * 0.9f) * 0.6f;
      directions.emplace_back(std::cos(a) * std::cos(e), std::sin(e), std::sin(a) * std::cos(e));
    }
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
      const std::optional<RayHit> h = room->queries.raycast(room->centre, directions[i++ % directions.size()]);
      hits += h.has_value();
      benchmark::DoNotOptimize(h);
    }
    state.counters["hit_share"] = double(hits) / double(state.iterations());
    room_counters(state, *room);
  })->Unit(benchmark::kMicrosecond);
  if (!everything) return;
  benchmark::RegisterBenchmark(("random_point_on_surface/" + n).c_str(), [room](benchmark::State& state) {
    std::uint64_t seed = 0;
    for (auto _ : state) benchmark::DoNotOptimize(room->queries.random_point_on_surface(kOnAnySurface, 0.1f, seed++));
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark(("random_point_in_room/" + n).c_str(), [room](benchmark::State& state) {
    std::uint64_t seed = 0;
    for (auto _ : state) benchmark::DoNotOptimize(room->queries.random_point_in_room(0.3f, seed++));
  })->Unit(benchmark::kMicrosecond);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  // On stderr: --benchmark_format=json writes the results alone to stdout.
  std::fprintf(stderr,
               "Targets (issue 16): 10 placements on a ~78k-vertex room <= 1 ms, one raycast <= 10 us.\n"
               "place10/QUERY/ROOM: one find_placements call for 10 objects; raycast/ROOM: one ray.\n\n");
  static const std::vector<std::shared_ptr<BenchRoom>> rooms = load_rooms();
  for (const auto& room : rooms) register_queries(room, true);
  // Growth with room size: halls of increasing floor area.
  static std::vector<std::shared_ptr<BenchRoom>> halls;
  for (const float scale : {0.25f, 0.5f, 1.0f, 1.5f, 2.0f}) {
    const float w = 20.0f * scale, d = 14.0f * scale;
    halls.push_back(analysed("growth_hall_" + std::to_string(int(w)) + "x" + std::to_string(int(d)),
                             synth::generate(synth::hall_room(w, d))));
    register_queries(halls.back(), false);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
