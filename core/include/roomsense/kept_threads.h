// KeptThreads: an analysis's worker threads, kept for the next.
#pragma once
#include <memory>

namespace roomsense {

namespace detail {
class WorkerPool;
}

// Worker threads kept from one analysis to the next (issue 19). analyze() otherwise starts its threads and joins
// them when it ends: about 0.2 ms of thesis-room1's 5.5 ms on a 2-core machine. An app or engine that analyses
// again and again keeps one and passes it in AnalysisOptions::kept_threads; it must outlive the calls, which may
// come from several threads at once. `threads` as AnalysisOptions::threads (0: one per hardware thread); an
// analysis on another count starts its own.
class KeptThreads {
 public:
  explicit KeptThreads(unsigned threads = 0);
  ~KeptThreads();
  KeptThreads(const KeptThreads&) = delete;
  KeptThreads& operator=(const KeptThreads&) = delete;
  unsigned threads() const { return threads_; }
  detail::WorkerPool* pool() const { return pool_.get(); }  // null for one thread

 private:
  unsigned threads_;
  std::unique_ptr<detail::WorkerPool> pool_;
};

}  // namespace roomsense
