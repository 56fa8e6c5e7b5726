// The p50 and p90 of a case's per-iteration times, as its counters (PREFIXp50_ms, PREFIXp90_ms): the cases whose
// iterations are fixed computes (layer_compute.cpp, capi_compute.cpp).
#pragma once
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

namespace roomsense::bench {

inline void set_percentiles(benchmark::State& state, std::vector<double> seconds, const std::string& prefix = "") {
  if (seconds.empty()) return;
  std::sort(seconds.begin(), seconds.end());
  state.counters[prefix + "p50_ms"] = 1e3 * seconds[seconds.size() / 2];
  state.counters[prefix + "p90_ms"] = 1e3 * seconds[seconds.size() * 9 / 10];
}

}  // namespace roomsense::bench
