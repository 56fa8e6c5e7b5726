// One computation at a time on a worker thread, shared by both C APIs: start it, poll or wait for it,
// read its result under a lock, clear it. The thesis API keeps two of these in function-local statics;
// each rs_analyzer owns one.
//
// The worker is started by the first start() and serves every computation after it until clear() (or the
// destructor) ends it: starting a thread per computation took some 75 us on this project's VM, three times an
// unchanged room's compute of chunks through the handle API (bench/README.md, stop 94).
//
// Two locks: `control_` serialises whoever starts, joins or clears (the only ones touching thread_), and
// `mutex_` guards the phase, the result and the work handed over, which the worker takes and sets. The worker
// takes only `mutex_`, so joining it while holding `control_` cannot deadlock. The destructor and clear() ask
// the worker to stop (its work gets the worker's std::stop_token; the analysis returns within ~100 ms) and
// join it: the worker never outlives the Job it writes to.
//
// The idle worker waits on a std::condition_variable for work or `ending_`, never on a stop token: waiting on one
// registers a std::stop_callback, and the MinGW-w64 GCC 12 libstdc++ that builds the Windows DLL can lose the
// wake-up its removal waits for (its atomic wait without a futex), which hung rs_analyzer_destroy under Wine.
#pragma once
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <utility>

namespace roomsense::capi {

enum class JobPhase { Idle, Running, Done };

// Result must be default-constructible, and its default value must mean "failed": it is what a job holds
// when its work throws.
template <class Result>
class Job {
 public:
  Job() = default;
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;
  ~Job() { clear(); }

  // Hands work() to the worker (started here the first time) and keeps what it returns. Starts nothing and
  // returns false while the job runs, or while it holds a result and replace_result is false. Throws
  // std::system_error when no worker can be started; the job is then as it was.
  bool start(std::function<Result(std::stop_token)> work, bool replace_result) {
    std::lock_guard control(control_);
    {
      std::lock_guard lock(mutex_);
      if (phase_ == JobPhase::Running || (phase_ == JobPhase::Done && !replace_result)) return false;
    }
    // Started before anything changes; it waits for the work below, under mutex_.
    if (!thread_.joinable()) thread_ = std::jthread([this](std::stop_token stop) { serve(stop); });
    {
      std::lock_guard lock(mutex_);
      result_.reset();
      pending_ = std::move(work);
      phase_ = JobPhase::Running;
    }
    work_.notify_one();
    return true;
  }

  // Sets a result without running anything, as if a job had finished with it. False unless Idle.
  bool finish_now(Result result) {
    std::lock_guard control(control_);
    std::lock_guard lock(mutex_);
    if (phase_ != JobPhase::Idle) return false;
    result_.emplace(std::move(result));
    phase_ = JobPhase::Done;
    return true;
  }

  JobPhase phase() const {
    std::lock_guard lock(mutex_);
    return phase_;
  }

  // Blocks until the job is not running or `timeout` passes (none: no limit), then calls f(phase, result) under
  // the same lock: f sees the state the wait ended on, not one a compute started on another thread since.
  template <class F>
  decltype(auto) wait_and_inspect(std::optional<std::chrono::milliseconds> timeout, F&& f) {
    std::unique_lock lock(mutex_);
    const auto not_running = [this] { return phase_ != JobPhase::Running; };
    if (timeout) cv_.wait_for(lock, *timeout, not_running);
    else cv_.wait(lock, not_running);
    return std::forward<F>(f)(phase_, result_ ? &*result_ : static_cast<Result*>(nullptr));
  }

  // Calls f(phase, result) under the lock; result is null unless the phase is Done.
  template <class F>
  decltype(auto) inspect(F&& f) {
    std::lock_guard lock(mutex_);
    return std::forward<F>(f)(phase_, result_ ? &*result_ : static_cast<Result*>(nullptr));
  }

  // Stops a running computation, ends the worker (the next start() starts one again), drops the result, and
  // makes the job Idle.
  void clear() {
    std::lock_guard control(control_);
    {
      std::lock_guard lock(mutex_);
      ending_ = true;
    }
    work_.notify_one();
    thread_.request_stop();
    if (thread_.joinable()) thread_.join();
    std::optional<Result> old;
    {
      std::lock_guard lock(mutex_);
      old.swap(result_);
      pending_ = nullptr;
      phase_ = JobPhase::Idle;
      ending_ = false;
    }
  }

 private:
  // The worker: each work start() hands over, until clear() ends it. A stop that comes while work runs ends that
  // work (it returns, or throws Cancelled: the job then holds the failed result) and then the worker.
  void serve(std::stop_token stop) {
    for (;;) {
      std::function<Result(std::stop_token)> work;
      {
        std::unique_lock lock(mutex_);
        work_.wait(lock, [this] { return ending_ || pending_ != nullptr; });
        if (ending_) return;
        work.swap(pending_);
      }
      Result result;
      try {
        result = work(stop);
      } catch (...) {
        result = Result{};
      }
      work = nullptr;  // what it holds (the caller's scan) goes before the result is published
      finish(std::move(result));
    }
  }

  void finish(Result&& result) {
    {
      std::lock_guard lock(mutex_);
      result_.emplace(std::move(result));
      phase_ = JobPhase::Done;
    }
    cv_.notify_all();
  }

  std::mutex control_;
  mutable std::mutex mutex_;
  mutable std::condition_variable cv_;     // notified when a computation ends
  std::condition_variable work_;           // notified when start() hands over work, or clear() ends the worker
  bool ending_ = false;                     // set by clear() while it ends the worker
  JobPhase phase_ = JobPhase::Idle;
  std::optional<Result> result_;
  std::function<Result(std::stop_token)> pending_;  // the work the worker has yet to take
  std::jthread thread_;
};

}  // namespace roomsense::capi
