// One computation at a time on a worker thread, shared by both C APIs: start it, poll or wait for it,
// read its result under a lock, clear it. The thesis API keeps two of these in function-local statics;
// each rs_analyzer owns one.
//
// Two locks: `control_` serialises whoever starts, joins or clears (the only ones touching thread_), and
// `mutex_` guards the phase and the result, which the worker sets once at its end. The worker takes only
// `mutex_`, so joining it while holding `control_` cannot deadlock. The destructor and clear() ask the
// worker to stop (its work gets a std::stop_token; the analysis returns within ~100 ms) and join it: the
// worker never outlives the Job it writes to.
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

  // Runs work() on a new thread and keeps what it returns. Starts nothing and returns false while the job
  // runs, or while it holds a result and replace_result is false. Throws std::system_error when no thread
  // can be started; the job is then Idle.
  bool start(std::function<Result(std::stop_token)> work, bool replace_result) {
    std::lock_guard control(control_);
    {
      std::lock_guard lock(mutex_);
      if (phase_ == JobPhase::Running || (phase_ == JobPhase::Done && !replace_result)) return false;
    }
    if (thread_.joinable()) thread_.join();  // the previous worker, finished or about to return
    {
      std::lock_guard lock(mutex_);
      result_.reset();
      phase_ = JobPhase::Running;
    }
    try {
      thread_ = std::jthread([this, work = std::move(work)](std::stop_token stop) {
        Result result;
        try {
          result = work(stop);
        } catch (...) {
          result = Result{};
        }
        finish(std::move(result));
      });
    } catch (...) {
      std::lock_guard lock(mutex_);
      phase_ = JobPhase::Idle;
      throw;
    }
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

  // Stops a running worker, drops the result, and makes the job Idle.
  void clear() {
    std::lock_guard control(control_);
    thread_.request_stop();
    if (thread_.joinable()) thread_.join();
    std::optional<Result> old;
    {
      std::lock_guard lock(mutex_);
      old.swap(result_);
      phase_ = JobPhase::Idle;
    }
  }

 private:
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
  mutable std::condition_variable cv_;
  JobPhase phase_ = JobPhase::Idle;
  std::optional<Result> result_;
  std::jthread thread_;
};

}  // namespace roomsense::capi
