#include "softrender/worker_pool.h"

#include <algorithm>

namespace twr {

WorkerPool::WorkerPool(int threads) {
  const int workers = std::max(threads, 1) - 1;
  for (int i = 0; i < workers; ++i) workers_.emplace_back(&WorkerPool::workerLoop, this, i + 1);
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void WorkerPool::run(int taskCount, const std::function<void(int task, int thread)>& job) {
  if (taskCount <= 0) return;
  {
    const std::lock_guard lock(mutex_);
    job_ = &job;
    taskCount_ = taskCount;
    nextTask_ = 0;
    busyWorkers_ = static_cast<int>(workers_.size());
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  work(0);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return busyWorkers_ == 0; });
  job_ = nullptr;
  if (error_) std::rethrow_exception(error_);
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

void WorkerPool::workerLoop(int thread) {
  std::uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    work(thread);
    {
      const std::lock_guard lock(mutex_);
      --busyWorkers_;
    }
    done_.notify_one();
  }
}

}  // namespace twr
