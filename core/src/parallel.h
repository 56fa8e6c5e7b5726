// A minimal fork-join loop. Each worker owns a fixed contiguous slice of [0, n), so results never depend
// on timing or on the thread count.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
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
  const auto slice = [&](std::size_t w) { return n * w / workers; };
  std::exception_ptr failure;  // an exception escaping a thread would terminate the process: carry it here
  std::mutex failure_mutex;
  const auto run = [&](std::size_t w) {
    try {
      body(slice(w), slice(w + 1), w);
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  {
    std::vector<std::jthread> pool;
    pool.reserve(workers - 1);
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(run, w);
    run(0);
  }
  if (failure) std::rethrow_exception(failure);
}

// Runs task(i) for every i in [0, n) on up to `threads` workers, each taking the next task when it is free:
// for a few tasks of uneven cost. Each task must write only its own outputs, so results do not depend on
// which worker ran it.
template <class Task>
void parallel_tasks(std::size_t n, unsigned threads, Task&& task) {
  const std::size_t workers = std::min<std::size_t>(resolve_threads(threads), n);
  if (workers <= 1) {
    for (std::size_t i = 0; i < n; ++i) task(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;  // the first exception of any worker, rethrown here once all have joined
  std::mutex failure_mutex;
  const auto work = [&] {
    try {
      for (std::size_t i = next++; i < n; i = next++) task(i);
    } catch (...) {
      next = n;
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  {
    std::vector<std::jthread> pool;
    pool.reserve(workers - 1);
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace roomsense::detail
