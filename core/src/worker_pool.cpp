#include "worker_pool.h"

#include "parallel.h"

#include <algorithm>
#include <chrono>
#include <exception>

namespace roomsense::detail {
namespace {
thread_local WorkerPool* t_current = nullptr;

// A thread that would sleep on the condition variable first watches for its wake-up this long. Waking a
// sleeping thread took some 50 us on this project's 2-core VM, about a small loop's whole share, and most of an
// update's loops begin within this time of the one before: a pool thread still watching takes the next loop's
// jobs at once (a median 0.3 us after the loop began, against 37-51 us asleep), and a caller whose last job
// runs elsewhere sees it end. Short enough that a pool left idle costs a core this long after its last loop.
constexpr auto kSpin = std::chrono::microseconds(100);

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// Watches ready() for up to kSpin, without the lock.
template <class Ready>
void spin_until(Ready ready) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (;;) {
    for (int i = 0; i < 64; ++i) {
      if (ready()) return;
      cpu_relax();
    }
    if (std::chrono::steady_clock::now() >= until) return;
  }
}
}  // namespace

// Lives on the stack of run(), which returns only once every job has ended and it has taken the lock since;
// another thread touches it only under the lock, and not after counting its job ended. `ended` is also read
// without the lock, while its caller spins.
struct WorkerPool::Batch {
  const std::function<void(std::size_t)>* job = nullptr;
  std::size_t n = 0, taken = 0;
  std::atomic<std::size_t> ended = 0;
  std::exception_ptr failure;
};

WorkerPool::WorkerPool(unsigned threads) {
  threads_.reserve(threads);
  for (unsigned t = 0; t < threads; ++t) threads_.emplace_back([this] { serve(); });
}

WorkerPool::~WorkerPool() {
  release();
  threads_.clear();  // joins
}

void WorkerPool::release() {
  {
    const std::lock_guard lock(mutex_);
    ending_ = true;
  }
  work_.notify_all();
}

WorkerPool* WorkerPool::current() { return t_current; }

void WorkerPool::execute(Batch& b, std::size_t i) {
  std::exception_ptr error;
  try {
    (*b.job)(i);
  } catch (...) {
    error = std::current_exception();
  }
  const std::lock_guard lock(mutex_);
  if (error && !b.failure) b.failure = error;
  if (++b.ended == b.n) work_.notify_all();  // its caller may wait among the pool's threads
}

void WorkerPool::run(std::size_t n, const std::function<void(std::size_t)>& job) {
  if (n == 0) return;
  Batch b;
  b.job = &job, b.n = n;
  if (n > 1 && !threads_.empty()) {
    {
      const std::lock_guard lock(mutex_);
      queue_.push_back(&b);
      queued_ = queue_.size();
    }
    if (n == 2) work_.notify_one();
    else work_.notify_all();
  }
  for (;;) {
    std::size_t i = 0;
    {
      const std::lock_guard lock(mutex_);
      if (b.taken == n) break;
      i = b.taken++;
      if (b.taken == n && n > 1 && !threads_.empty()) {
        queue_.erase(std::find(queue_.begin(), queue_.end(), &b));
        queued_ = queue_.size();
      }
    }
    execute(b, i);
  }
  // Until the pool's threads end this batch's last jobs, this thread takes any other batch's (a loop inside one
  // of them, or beside this one), rather than wait idle.
  spin_until([&] { return b.ended == n || queued_ != 0; });
  std::unique_lock lock(mutex_);
  for (;;) {
    work_.wait(lock, [&] { return b.ended == n || !queue_.empty(); });
    if (b.ended == n) break;
    run_front(lock);
  }
  if (b.failure) std::rethrow_exception(b.failure);
}

void WorkerPool::serve() {
  t_current = this;
  std::unique_lock lock(mutex_);
  for (;;) {
    if (queue_.empty() && !ending_) {
      lock.unlock();
      spin_until([&] { return queued_ != 0 || ending_; });
      lock.lock();
    }
    work_.wait(lock, [&] { return ending_ || !queue_.empty(); });
    if (queue_.empty()) return;  // ending, and no batch waits
    run_front(lock);
  }
}

void WorkerPool::run_front(std::unique_lock<std::mutex>& lock) {
  Batch& b = *queue_.front();
  const std::size_t i = b.taken++;
  if (b.taken == b.n) {
    queue_.pop_front();
    queued_ = queue_.size();
  }
  lock.unlock();
  execute(b, i);
  lock.lock();
}

WorkerPool* pool_for(std::unique_ptr<WorkerPool>& slot, unsigned threads) {
  threads = resolve_threads(threads);
  if (threads == 1) slot.reset();
  else if (!slot || slot->threads() != threads - 1) slot = std::make_unique<WorkerPool>(threads - 1);
  return slot.get();
}

PoolScope::PoolScope(WorkerPool* pool) : previous_(t_current) { t_current = pool; }

PoolScope::~PoolScope() { t_current = previous_; }

StagePool::StagePool(unsigned threads) {
  if (WorkerPool::current() != nullptr || resolve_threads(threads) <= 1) return;
  pool_for(own_, threads);
  scope_.emplace(own_.get());
}

}  // namespace roomsense::detail
