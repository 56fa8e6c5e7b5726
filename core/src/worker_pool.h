// Threads kept for the parallel loops of parallel.h, so that an analysis does not start and join a thread per
// loop: about 75 us each on this project's 2-core VM, and an IncrementalAnalysis's update of a few
// milliseconds ran eight or so loops. An analysis makes its pool current on its thread (PoolScope) for as long
// as it runs; an IncrementalAnalysis keeps its pool between results. No pool outlives its owner, so a layer
// unloaded from an app leaves no thread behind.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace roomsense::detail {

class WorkerPool {
 public:
  explicit WorkerPool(unsigned threads);  // threads beside the callers'
  ~WorkerPool();                          // ends and joins them
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned threads() const { return unsigned(threads_.size()); }
  // Runs job(i) for every i in [0, n) on the calling thread and the pool's, and returns once all have ended;
  // the first exception of a job is rethrown then. The caller runs every job no pool thread has taken, so it
  // never waits for a pool thread that is busy elsewhere: a loop inside another loop's job cannot deadlock.
  // While the last of its jobs run elsewhere, the caller runs other batches' jobs.
  void run(std::size_t n, const std::function<void(std::size_t)>& job);

  // No loop comes after those that ran: the threads end once idle, while the caller goes on (their join, in the
  // destructor, then waits less). A loop that still comes runs on the caller alone.
  void release();

  // The pool parallel.h's loops use on this thread: the innermost PoolScope's, or on a pool's own thread that
  // pool; null where there is none.
  static WorkerPool* current();

 private:
  struct Batch;
  void serve();
  // Runs job i of b (taken under the lock, which is not held here), then counts it ended.
  void execute(Batch& b, std::size_t i);
  // Takes the next job of the oldest batch in the queue (not empty) and runs it, the lock released meanwhile.
  void run_front(std::unique_lock<std::mutex>& lock);

  std::mutex mutex_;
  std::condition_variable work_;  // a batch has jobs not taken, a batch ended, or the pool ends
  std::deque<Batch*> queue_;      // batches with jobs not taken, oldest first
  std::atomic<std::size_t> queued_ = 0;  // queue_.size(), read without the lock while spinning
  std::atomic<bool> ending_ = false;     // also read without the lock while spinning, so ~WorkerPool joins at once
  std::vector<std::jthread> threads_;
};

// A pool for `threads` workers in all (the caller and threads - 1 of the pool's; 0: one per core), kept in
// `slot` and made anew there when it has another size; null for one worker.
WorkerPool* pool_for(std::unique_ptr<WorkerPool>& slot, unsigned threads);

// Makes `pool` (null: none) the current pool of this thread until the scope ends.
class PoolScope {
 public:
  explicit PoolScope(WorkerPool* pool);
  ~PoolScope();
  PoolScope(const PoolScope&) = delete;
  PoolScope& operator=(const PoolScope&) = delete;

 private:
  WorkerPool* previous_;
};

// For a public stage called on its own (build_bounds, mesh_volume, ...), outside any analysis: a pool for its
// loops where this thread has none and several workers are asked for, so that the loops start one thread between
// them rather than one each (some 75 us apiece); else nothing.
class StagePool {
 public:
  explicit StagePool(unsigned threads);
  StagePool(const StagePool&) = delete;
  StagePool& operator=(const StagePool&) = delete;

 private:
  std::unique_ptr<WorkerPool> own_;
  std::optional<PoolScope> scope_;  // ends before own_
};

}  // namespace roomsense::detail
