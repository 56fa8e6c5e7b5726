// A minimal fork-join loop. Each worker owns a fixed contiguous slice of [0, n), so results never depend
// on timing or on the thread count.
#pragma once
#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace roomsense::detail {

inline unsigned resolve_threads(unsigned requested) {
  if (requested != 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : hw;
}

// How many workers parallel_for uses: at most `threads`, each with a slice of at least min_grain items.
inline std::size_t parallel_workers(std::size_t n, unsigned threads, std::size_t min_grain) {
  const std::size_t max_workers = std::max<std::size_t>(1, n / std::max<std::size_t>(1, min_grain));
  return std::min<std::size_t>(resolve_threads(threads), max_workers);
}

// Calls body(begin, end, worker) for parallel_workers(...) contiguous slices of [0, n).
template <class Body>
void parallel_for(std::size_t n, unsigned threads, std::size_t min_grain, Body&& body) {
  const std::size_t workers = parallel_workers(n, threads, min_grain);
  if (workers <= 1) {
    body(std::size_t{0}, n, std::size_t{0});
    return;
  }
  std::vector<std::jthread> pool;
  pool.reserve(workers - 1);
  const auto slice = [&](std::size_t w) { return n * w / workers; };
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back([&, w] { body(slice(w), slice(w + 1), w); });
  body(slice(0), slice(1), 0);
}

}  // namespace roomsense::detail
