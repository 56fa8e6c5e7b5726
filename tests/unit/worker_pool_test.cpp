// WorkerPool (core/src/worker_pool.h, internal): the threads an analysis keeps for its parallel loops. Every job
// runs once, loops inside loops finish on a pool of any size (the caller runs what no pool thread took), a job's
// exception reaches the caller after every job ended, and parallel.h's loops use the pool of their thread;
// parallel_for's slices are fixed by the count and the threads, and any free thread takes the next one.
#include "../../core/src/parallel.h"
#include "../../core/src/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

using roomsense::detail::PoolScope;
using roomsense::detail::WorkerPool;

TEST(WorkerPool, RunsEveryJobOnceOnAnyPoolSize) {
  for (const unsigned threads : {0u, 1u, 3u}) {
    WorkerPool pool(threads);
    for (std::size_t n = 0; n < 40; ++n) {
      std::vector<std::atomic<int>> runs(n);
      pool.run(n, [&](std::size_t i) { ++runs[i]; });
      for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(runs[i].load(), 1) << threads << " threads, job " << i << " of " << n;
    }
  }
}

TEST(WorkerPool, LoopsInsideLoopsFinishOnAPoolOfOneThread) {
  WorkerPool pool(1);
  const PoolScope scope(&pool);
  std::atomic<long> sum = 0;
  // Three levels of parallel loops: the pool's one thread is always busy in an outer job while inner ones wait.
  roomsense::detail::parallel_tasks(4, 8, [&](std::size_t a) {
    roomsense::detail::parallel_for(64, 8, 1, [&](std::size_t begin, std::size_t end, std::size_t) {
      for (std::size_t b = begin; b < end; ++b)
        roomsense::detail::parallel_tasks(3, 8, [&](std::size_t c) { sum += long(a * 1000 + b * 10 + c); });
    });
  });
  long expected = 0;
  for (long a = 0; a < 4; ++a)
    for (long b = 0; b < 64; ++b)
      for (long c = 0; c < 3; ++c) expected += a * 1000 + b * 10 + c;
  EXPECT_EQ(sum.load(), expected);
}

TEST(WorkerPool, AJobsExceptionReachesTheCallerOnceEveryJobEnded) {
  WorkerPool pool(2);
  std::atomic<int> ended = 0;
  EXPECT_THROW(pool.run(16,
                        [&](std::size_t i) {
                          std::this_thread::sleep_for(std::chrono::milliseconds(i % 3));
                          ++ended;
                          if (i == 5) throw std::runtime_error("job 5");
                        }),
               std::runtime_error);
  EXPECT_EQ(ended.load(), 16);
  // The pool serves the next run as before.
  std::atomic<int> runs = 0;
  pool.run(8, [&](std::size_t) { ++runs; });
  EXPECT_EQ(runs.load(), 8);
}

TEST(WorkerPool, ParallelLoopsUseTheirThreadsPool) {
  EXPECT_EQ(WorkerPool::current(), nullptr);
  WorkerPool pool(1);
  {
    const PoolScope scope(&pool);
    EXPECT_EQ(WorkerPool::current(), &pool);
    // Two tasks, each waiting (up to 10 s) until both have started: they end only when two threads run them, the
    // caller and the pool's thread, whatever the scheduler's timing; the pool's thread sees its pool as current.
    std::mutex mutex;
    std::condition_variable both;
    int started = 0;
    bool waited_out = false;
    std::set<std::thread::id> ids;
    roomsense::detail::parallel_tasks(2, 2, [&](std::size_t) {
      EXPECT_EQ(WorkerPool::current(), &pool);
      std::unique_lock lock(mutex);
      ids.insert(std::this_thread::get_id());
      ++started;
      both.notify_all();
      if (!both.wait_for(lock, std::chrono::seconds(10), [&] { return started == 2; })) waited_out = true;
    });
    EXPECT_FALSE(waited_out);
    EXPECT_EQ(ids.size(), 2u);
    EXPECT_TRUE(ids.count(std::this_thread::get_id()));
    {
      const PoolScope none(nullptr);
      EXPECT_EQ(WorkerPool::current(), nullptr);
    }
    EXPECT_EQ(WorkerPool::current(), &pool);
  }
  EXPECT_EQ(WorkerPool::current(), nullptr);
}

TEST(ParallelFor, SlicesAreFixedByTheCountAndTheThreadsAlone) {
  using roomsense::detail::parallel_slices;
  EXPECT_EQ(parallel_slices(1000, 1, 1), 1u);  // one thread: one pass
  EXPECT_EQ(parallel_slices(1000, 2, 1), 2 * roomsense::detail::kSlicesPerThread);
  EXPECT_EQ(parallel_slices(1000, 2, 400), 2u);  // each slice at least the grain
  EXPECT_EQ(parallel_slices(399, 2, 400), 1u);
  for (const unsigned threads : {1u, 2u, 3u}) {
    WorkerPool pool(threads - 1);
    const PoolScope scope(&pool);
    for (const std::size_t n : {0u, 1u, 7u, 100u, 1001u}) {
      const std::size_t slices = parallel_slices(n, threads, 3);
      std::vector<std::pair<std::size_t, std::size_t>> seen(std::max<std::size_t>(slices, 1), {n + 1, n + 1});
      std::vector<std::atomic<int>> visits(n);
      roomsense::detail::parallel_for(n, threads, 3, [&](std::size_t begin, std::size_t end, std::size_t slice) {
        seen[slice] = {begin, end};  // each slice's own entry
        for (std::size_t i = begin; i < end; ++i) ++visits[i];
      });
      for (std::size_t k = 0; k < slices; ++k)
        EXPECT_EQ(seen[k], std::pair(n * k / slices, n * (k + 1) / slices)) << n << " items, slice " << k;
      for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(visits[i].load(), 1) << n << " items, item " << i;
    }
  }
}

TEST(ParallelFor, AThreadHeldInOneSliceLeavesTheOthersToTheOtherThread) {
  // Slice 0 ends only once every other slice has (waiting up to 10 s): with a slice fixed per thread, the thread
  // holding slice 0 would hold half of them and the loop would wait out; taken by whichever thread is free, the
  // other thread runs them all.
  WorkerPool pool(1);
  const PoolScope scope(&pool);
  const std::size_t slices = roomsense::detail::parallel_slices(64, 2, 1);
  ASSERT_GT(slices, 2u);
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t others_ended = 0;
  bool waited_out = false;
  roomsense::detail::parallel_for(64, 2, 1, [&](std::size_t, std::size_t, std::size_t slice) {
    std::unique_lock lock(mutex);
    if (slice == 0) {
      waited_out = !changed.wait_for(lock, std::chrono::seconds(10), [&] { return others_ended == slices - 1; });
      return;
    }
    ++others_ended;
    changed.notify_all();
  });
  EXPECT_FALSE(waited_out);
  EXPECT_EQ(others_ended, slices - 1);
}

// parallel_for_apart runs every slice once, with parallel_for's bounds, on any number of threads and slices; a
// worker held in its first slice leaves the rest of its run to the others (taken from the far end); and a slice's
// exception reaches the caller.
TEST(ParallelForApart, EverySliceOnceAndAHeldWorkersRunTakenByTheOthers) {
  using roomsense::detail::parallel_for_apart;
  for (const unsigned threads : {1u, 2u, 3u, 5u}) {
    WorkerPool pool(threads - 1);
    const PoolScope scope(&pool);
    for (const std::size_t n : {0u, 1u, 7u, 100u, 1001u})
      for (const std::size_t slices : {1u, 2u, 3u, 7u, 32u}) {
        std::vector<std::pair<std::size_t, std::size_t>> seen(slices, {n + 1, n + 1});
        std::vector<std::atomic<int>> visits(slices);
        parallel_for_apart(n, threads, slices, [&](std::size_t begin, std::size_t end, std::size_t slice) {
          seen[slice] = {begin, end};
          ++visits[slice];
        });
        for (std::size_t k = 0; k < slices; ++k) {
          EXPECT_EQ(seen[k], std::pair(n * k / slices, n * (k + 1) / slices)) << n << " items, slice " << k;
          EXPECT_EQ(visits[k].load(), 1) << n << " items, " << slices << " slices, slice " << k;
        }
      }
  }
  // Two workers, 16 slices: whichever holds slice 0 (the first of worker 0's run) waits until every other slice
  // has ended, which only the other worker can do, its own run and then the rest of the first from its end.
  WorkerPool pool(1);
  const PoolScope scope(&pool);
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::size_t> order;  // of the slices but 0, as they ended
  bool waited_out = false;
  parallel_for_apart(160, 2, 16, [&](std::size_t, std::size_t, std::size_t slice) {
    std::unique_lock lock(mutex);
    if (slice == 0) {
      waited_out = !changed.wait_for(lock, std::chrono::seconds(10), [&] { return order.size() == 15; });
      return;
    }
    order.push_back(slice);
    changed.notify_all();
  });
  EXPECT_FALSE(waited_out);
  const std::vector<std::size_t> expected = {8, 9, 10, 11, 12, 13, 14, 15, 7, 6, 5, 4, 3, 2, 1};
  EXPECT_EQ(order, expected);
  try {
    parallel_for_apart(100, 2, 8, [&](std::size_t, std::size_t, std::size_t slice) {
      if (slice == 5) throw std::runtime_error("slice 5");
    });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "slice 5");
  }
}

}  // namespace
