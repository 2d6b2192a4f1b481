#include "softrender/worker_pool.h"

#include <algorithm>

namespace twr {

namespace {

std::int64_t steadyNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// One iteration of a spin: tells the core (and a hypervisor) that this thread is waiting.
void spinPause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

}  // namespace

WorkerPool::WorkerPool(int threads) {
  const int workers = std::max(threads, 1) - 1;
  spinAllowed_ = static_cast<unsigned>(workers + 1) <= std::max(std::thread::hardware_concurrency(), 1u);
  for (int i = 0; i < workers; ++i) workers_.emplace_back(&WorkerPool::workerLoop, this, i + 1);
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_.store(true, std::memory_order_relaxed);
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

bool WorkerPool::spinning() const {
  return steadyNanoseconds() < spinUntil_.load(std::memory_order_relaxed);
}

void WorkerPool::spinFor(std::chrono::nanoseconds duration) {
  if (!spinAllowed_) return;
  const std::int64_t until = steadyNanoseconds() + duration.count();
  std::int64_t current = spinUntil_.load(std::memory_order_relaxed);
  while (current < until && !spinUntil_.compare_exchange_weak(current, until, std::memory_order_relaxed)) {
  }
}

void WorkerPool::wake() {
  if (workers_.empty()) return;
  {
    // Under the lock: a worker about to sleep either sees the new deadline or is notified.
    const std::lock_guard lock(mutex_);
    spinFor(kWakeSpin);
  }
  wake_.notify_all();
}

void WorkerPool::rest() { spinUntil_.store(0, std::memory_order_relaxed); }

void WorkerPool::run(int taskCount, const std::function<void(int task, int thread)>& job) {
  if (taskCount <= 0) return;
  {
    const std::lock_guard lock(mutex_);
    job_ = &job;
    taskCount_ = taskCount;
    nextTask_ = 0;
    error_ = nullptr;
    generation_.fetch_add(1, std::memory_order_release);
  }
  if (!workers_.empty()) wake_.notify_all();
  work(0);
  // Every task is handed out; wait for the workers still inside one, spinning a while first.
  const std::int64_t spinEnd =
      spinAllowed_ ? steadyNanoseconds() + std::chrono::duration_cast<std::chrono::nanoseconds>(kSpinAfterRun).count()
                   : 0;
  while (activeWorkers_.load(std::memory_order_acquire) != 0 && steadyNanoseconds() < spinEnd) spinPause();
  std::exception_ptr error;
  {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return activeWorkers_.load(std::memory_order_relaxed) == 0; });
    job_ = nullptr;
    error = error_;
  }
  spinFor(kSpinAfterRun);
  if (error) std::rethrow_exception(error);
}

void WorkerPool::work(int thread) {
  for (;;) {
    int task = 0;
    {
      const std::lock_guard lock(mutex_);
      if (nextTask_ >= taskCount_) return;
      task = nextTask_++;
    }
    try {
      (*job_)(task, thread);
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      nextTask_ = taskCount_;  // hand out nothing more
    }
  }
}

void WorkerPool::waitForRun(std::uint64_t seen) {
  for (;;) {
    while (spinning()) {
      if (generation_.load(std::memory_order_acquire) != seen || stopping_.load(std::memory_order_relaxed)) return;
      spinPause();
    }
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [&] { return stopping_ || generation_.load(std::memory_order_relaxed) != seen || spinning(); });
    if (stopping_ || generation_.load(std::memory_order_relaxed) != seen) return;
    // Woken by wake(): spin again.
  }
}

void WorkerPool::workerLoop(int thread) {
  std::uint64_t seen = 0;
  for (;;) {
    waitForRun(seen);
    {
      const std::lock_guard lock(mutex_);
      if (stopping_) return;
      seen = generation_.load(std::memory_order_relaxed);
      // The caller may have taken every task while this worker woke: it does not wait for it.
      if (nextTask_ >= taskCount_) continue;
      activeWorkers_.fetch_add(1, std::memory_order_relaxed);
    }
    work(thread);
    bool last = false;
    {
      const std::lock_guard lock(mutex_);
      last = activeWorkers_.fetch_sub(1, std::memory_order_release) == 1;
    }
    if (last) done_.notify_one();
  }
}

}  // namespace twr
