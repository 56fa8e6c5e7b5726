// The handle C API's compute of chunks as an engine sees it: from rs_analyzer_compute_chunks to READY through
// rs_analyzer_wait, on synthetic:thesis-room1 given as its 2 m blocks (split_into_blocks). Two cases:
//   capi_compute_chunks/unchanged: no chunk changed since the last compute (the analysis answers with its result);
//   capi_compute_chunks/changed: one more small chunk set before each compute (a 10 cm square, standing, away from
//     the walls): the analysis is an update. After each such compute, one placement query (a 0.3 m object on a wall
//     or the floor) is timed apart: the first query of a new result, which builds its placement index
//     (place_p50_ms, place_p90_ms).
// Each iteration is one compute; p50_ms and p90_ms are over the run's iterations, which are fixed.
//
//   build/bench/roomsense_bench_capi
#include "roomsense/incremental.h"
#include "roomsense/roomsense.h"
#include "roomsense/synthetic.h"

#include <benchmark/benchmark.h>

#include "percentiles.h"

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr int kComputes = 60;

void check(rs_result result, const char* call) {
  if (result != RS_SUCCESS) throw std::runtime_error(std::string(call) + " failed: " + std::to_string(int(result)));
}

// One compute of the analyzer's chunks, to READY; its seconds.
double compute(rs_analyzer* analyzer) {
  const auto start = std::chrono::steady_clock::now();
  check(rs_analyzer_compute_chunks(analyzer), "rs_analyzer_compute_chunks");
  rs_state state = RS_STATE_IDLE;
  check(rs_analyzer_wait(analyzer, RS_WAIT_INFINITE, &state), "rs_analyzer_wait");
  if (state != RS_STATE_READY) throw std::runtime_error("the compute did not end READY");
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void capi_compute_chunks(benchmark::State& state, bool changed) {
  rs_analyzer* analyzer = nullptr;
  check(rs_analyzer_create(nullptr, &analyzer), "rs_analyzer_create");
  const roomsense::Scan scan = roomsense::synth::generate_builtin_source("synthetic:thesis-room1");
  for (const auto& [id, chunk] : roomsense::split_into_blocks(scan))
    check(rs_analyzer_set_chunk(analyzer, id, &chunk.vertices[0].x, std::uint32_t(chunk.vertices.size()),
                                chunk.indices.data(), std::uint32_t(chunk.indices.size())),
          "rs_analyzer_set_chunk");
  compute(analyzer);  // the first analysis, not timed
  // The first query of a new result; its seconds.
  const auto place = [&] {
    rs_placement_query query;
    rs_placement_query_init(&query);
    query.surfaces = RS_SURFACE_WALL | RS_SURFACE_FLOOR;
    rs_placement found{};
    std::uint32_t count = 0;
    const auto start = std::chrono::steady_clock::now();
    check(rs_analyzer_find_placements(analyzer, &query, 1, &count, &found, nullptr), "rs_analyzer_find_placements");
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::vector<double> seconds, place_seconds;
  for (auto _ : state) {
    if (changed) {
      state.PauseTiming();
      const float x = -1.0f + 0.1f * float(seconds.size() % 20);
      const float xyz[12] = {x, 1.0f, 0.0f, x + 0.1f, 1.0f, 0.0f, x + 0.1f, 1.1f, 0.0f, x, 1.1f, 0.0f};
      const std::uint32_t indices[6] = {0, 2, 1, 0, 3, 2};
      check(rs_analyzer_set_chunk(analyzer, (std::uint64_t{1} << 62) + seconds.size(), xyz, 4, indices, 6),
            "rs_analyzer_set_chunk");
      state.ResumeTiming();
    }
    seconds.push_back(compute(analyzer));
    state.SetIterationTime(seconds.back());
    if (changed) {
      state.PauseTiming();
      place_seconds.push_back(place());
      state.ResumeTiming();
    }
  }
  rs_analyzer_destroy(analyzer);
  roomsense::bench::set_percentiles(state, std::move(seconds));
  roomsense::bench::set_percentiles(state, std::move(place_seconds), "place_");
}

BENCHMARK_CAPTURE(capi_compute_chunks, unchanged, false)->UseManualTime()->Iterations(kComputes)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(capi_compute_chunks, changed, true)->UseManualTime()->Iterations(kComputes)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
