// Minimal fork-join loops. A loop's slices of [0, n) are fixed by n and the thread count alone, and each slice's
// outputs are its own, so results never depend on timing or on the thread count. The workers run on the thread's
// current pool (worker_pool.h), or on threads started for the loop where there is none.
#pragma once
#include "worker_pool.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace roomsense::detail {

// 0: one per hardware thread. std::thread::hardware_concurrency reads /sys on every call (glibc's get_nprocs:
// three system calls, 6 us on this project's VM), and every loop below resolves its count, dozens an analysis:
// read once per process, a constant of the machine, not state.
inline unsigned resolve_threads(unsigned requested) {
  if (requested != 0) return requested;
  static const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  return hardware;
}

// Runs work(w) for every w in [0, workers): w = 0 on this thread, the others on the current pool or on threads
// of their own. `work` must not throw.
template <class Work>
void run_workers(std::size_t workers, Work&& work) {
  if (workers <= 1) {
    if (workers == 1) work(std::size_t{0});
    return;
  }
  if (WorkerPool* pool = WorkerPool::current(); pool != nullptr && pool->threads() > 0) {
    pool->run(workers, [&work](std::size_t w) { work(w); });
    return;
  }
  std::vector<std::jthread> threads;
  threads.reserve(workers - 1);
  for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work, w);
  work(std::size_t{0});
}

// How many slices parallel_for cuts [0, n) into: one on one thread; else up to `per_thread` (kSlicesPerThread unless
// a loop asks for more: parallel_for_apart's) per thread, each of at least min_grain items. More slices than
// threads, taken by whichever thread is free, let the calling thread go on with the next slice while a pool thread
// still wakes (some 50 us on this project's 2-core VM, as much as a small loop's whole slice): an update of a few
// milliseconds ran six or so such loops.
inline constexpr std::size_t kSlicesPerThread = 4;
inline std::size_t parallel_slices(std::size_t n, unsigned threads, std::size_t min_grain,
                                   std::size_t per_thread = kSlicesPerThread) {
  const unsigned t = resolve_threads(threads);
  if (t <= 1) return 1;
  const std::size_t most = std::max<std::size_t>(1, n / std::max<std::size_t>(1, min_grain));
  return std::min<std::size_t>(per_thread * t, most);
}

// Calls body(begin, end, slice) for the parallel_slices(...) contiguous slices of [0, n), slice k being
// [n k / slices, n (k + 1) / slices): a body's outputs kept per slice, in slice order, are those of one pass.
template <class Body>
void parallel_for(std::size_t n, unsigned threads, std::size_t min_grain, Body&& body) {
  const std::size_t slices = parallel_slices(n, threads, min_grain);
  if (slices <= 1) {
    body(std::size_t{0}, n, std::size_t{0});
    return;
  }
  const auto bound = [&](std::size_t k) { return n * k / slices; };
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;  // an exception escaping a thread would terminate the process: carry it here
  std::mutex failure_mutex;
  const auto run = [&](std::size_t) {
    try {
      for (std::size_t k = next++; k < slices; k = next++) body(bound(k), bound(k + 1), k);
    } catch (...) {
      next = slices;  // no slice starts after a failure
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  run_workers(std::min<std::size_t>(resolve_threads(threads), slices), run);
  if (failure) std::rethrow_exception(failure);
}

// parallel_for over `slices` slices, each worker taking the slices of its own run of them in order, and then
// those of the others' runs from their far ends: the workers stay in parts of [0, n) far apart until the last
// few slices. For passes whose nearby items write near each other (a scan's triangles marking its grid: slices
// taken in turn put both workers on the same cache lines), in slices small enough that the workers' last ones
// end close together.
template <class Body>
void parallel_for_apart(std::size_t n, unsigned threads, std::size_t slices, Body&& body) {
  const auto bound = [&](std::size_t k) { return n * k / slices; };
  const std::size_t workers = std::min<std::size_t>(resolve_threads(threads), slices);
  if (workers <= 1 || slices > 0xffffffffu) {
    for (std::size_t k = 0; k < slices; ++k) body(bound(k), bound(k + 1), k);
    return;
  }
  // A run's slices not yet taken, [front, back): front in the high 32 bits, back in the low. Each on its own
  // cache line: its owner takes from it at every slice.
  struct alignas(64) Run {
    std::atomic<std::uint64_t> ends;
  };
  std::vector<Run> runs(workers);
  for (std::size_t w = 0; w < workers; ++w) runs[w].ends = (std::uint64_t(slices * w / workers) << 32) | (slices * (w + 1) / workers);
  // The next slice of `run` from its front or its back, or none left.
  const auto take = [](Run& run, bool from_front, std::size_t& slice) {
    std::uint64_t ends = run.ends.load(std::memory_order_relaxed);
    for (;;) {
      const std::uint64_t front = ends >> 32, back = ends & 0xffffffffu;
      if (front >= back) return false;
      const std::uint64_t next = from_front ? ((front + 1) << 32) | back : (front << 32) | (back - 1);
      if (run.ends.compare_exchange_weak(ends, next, std::memory_order_relaxed)) {
        slice = std::size_t(from_front ? front : back - 1);
        return true;
      }
    }
  };
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&](std::size_t w) {
    try {
      std::size_t k = 0;
      while (!failed && take(runs[w], true, k)) body(bound(k), bound(k + 1), k);
      for (std::size_t i = 1; i < workers; ++i)
        while (!failed && take(runs[(w + i) % workers], false, k)) body(bound(k), bound(k + 1), k);
    } catch (...) {
      failed = true;  // no slice starts after a failure
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  run_workers(workers, work);
  if (failure) std::rethrow_exception(failure);
}

// Slices of a grid's light per-column passes: columns (a count or a test per level), or rows of columns.
inline constexpr std::size_t kColumnGrain = 2048;
inline constexpr std::size_t kRowGrain = 4;

// Counts per level over [0, n) on the threads: count(begin, end, counts) adds those of [begin, end) into `counts`
// (`levels` zeros to start), each slice into its own; the slices' counts summed after (integers: the same in any
// order and on any number of threads).
template <class Count>
std::vector<std::uint32_t> counts_by_slices(std::size_t n, unsigned threads, std::size_t min_grain, std::size_t levels,
                                            Count&& count) {
  std::vector<std::vector<std::uint32_t>> parts(parallel_slices(n, threads, min_grain));
  parallel_for(n, threads, min_grain, [&](std::size_t begin, std::size_t end, std::size_t slice) {
    std::vector<std::uint32_t> part(levels, 0);
    count(begin, end, part);
    parts[slice] = std::move(part);
  });
  std::vector<std::uint32_t> counts(levels, 0);
  for (const std::vector<std::uint32_t>& part : parts)
    for (std::size_t y = 0; y < part.size(); ++y) counts[y] += part[y];
  return counts;
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
  const auto work = [&](std::size_t) {
    try {
      for (std::size_t i = next++; i < n; i = next++) task(i);
    } catch (...) {
      next = n;
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  run_workers(workers, work);
  if (failure) std::rethrow_exception(failure);
}

// Runs task(i) for every i in [0, n) on up to `threads` workers, task i only once every task in after[i] has
// ended; a free worker takes the lowest-numbered task that may run. For tasks of uneven cost where some need
// others' results. Each task must write only its own outputs (and read others' only after them), so results do
// not depend on which worker ran what. The first exception of any task is rethrown once all workers have
// stopped; tasks not yet started then never start. `after` must hold no cycle.
template <class Task>
void parallel_graph(const std::vector<std::vector<std::size_t>>& after, unsigned threads, Task&& task) {
  const std::size_t n = after.size();
  std::vector<std::size_t> waiting(n);
  std::vector<std::vector<std::size_t>> unlocks(n);
  for (std::size_t i = 0; i < n; ++i) {
    waiting[i] = after[i].size();
    for (const std::size_t before : after[i]) unlocks[before].push_back(i);
  }
  std::vector<bool> started(n, false);
  std::size_t started_count = 0;
  std::mutex mutex;
  std::condition_variable changed;
  std::exception_ptr failure;
  const auto work = [&](std::size_t) {
    std::unique_lock lock(mutex);
    while (!failure && started_count < n) {
      std::size_t i = 0;
      while (i < n && (started[i] || waiting[i] != 0)) ++i;
      if (i == n) {  // every task left waits for one that is running
        changed.wait(lock);
        continue;
      }
      started[i] = true;
      ++started_count;
      lock.unlock();
      std::exception_ptr error;
      try {
        task(i);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      if (error && !failure) failure = error;
      for (const std::size_t next : unlocks[i]) --waiting[next];
      changed.notify_all();
    }
  };
  const std::size_t workers = std::min<std::size_t>(resolve_threads(threads), n);
  run_workers(workers, work);
  if (failure) std::rethrow_exception(failure);
}

}  // namespace roomsense::detail
