// The hand-over between the UI thread and one render worker: at most one job waits while
// one runs, a newer job replaces the waiting one, and finished results wait for the UI to
// take them. The worker asks superseded() between steps of a long job (the pixel probe's
// views) to cut it short when something newer waits.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <vector>

namespace twr::gui {

template <typename Job, typename Result>
class JobQueue {
 public:
  // UI side. Queues `job`, replacing a queued job that has not started.
  void submit(Job job) {
    {
      const std::lock_guard lock(mutex_);
      queued_ = std::move(job);
    }
    changed_.notify_all();
  }
  // True when no job is queued or running.
  bool idle() const {
    const std::lock_guard lock(mutex_);
    return !queued_ && !running_;
  }
  // True when a job waits for the running one to finish.
  bool hasQueued() const {
    const std::lock_guard lock(mutex_);
    return queued_.has_value();
  }
  // True when a finished job waits to be taken: the UI has something new to show.
  bool hasFinished() const {
    const std::lock_guard lock(mutex_);
    return !finished_.empty();
  }
  // Finished jobs not yet taken, oldest first.
  std::vector<Result> takeFinished() {
    const std::lock_guard lock(mutex_);
    std::vector<Result> results = std::move(finished_);
    finished_.clear();
    return results;
  }
  // Blocks until idle or `timeout` passes; true when idle.
  bool waitIdle(std::chrono::milliseconds timeout) const {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, timeout, [this] { return !queued_ && !running_; });
  }
  // Drops a queued job and makes next() return nothing from now on.
  void stop() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
      queued_.reset();
    }
    changed_.notify_all();
  }

  // Worker side. Blocks for the next job; nullopt once stop() was called.
  std::optional<Job> next() {
    std::unique_lock lock(mutex_);
    ++waiting_;
    changed_.notify_all();  // for waitForWorker()
    changed_.wait(lock, [this] { return stopping_ || queued_.has_value(); });
    --waiting_;
    if (stopping_) return std::nullopt;
    std::optional<Job> job = std::move(queued_);
    queued_.reset();
    running_ = true;
    return job;
  }
  // Blocks until the worker waits in next() for a job, or `timeout` passes; true if it waits.
  // Lets a caller (a test) stop or feed a worker known to be blocked rather than one that
  // has not yet asked.
  bool waitForWorker(std::chrono::milliseconds timeout) const {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, timeout, [this] { return waiting_ > 0; });
  }
  // True when a newer job waits or the worker is stopping: a long job should end early.
  bool superseded() const {
    const std::lock_guard lock(mutex_);
    return queued_.has_value() || stopping_;
  }
  // Hands the running job's result to the UI.
  void finish(Result result) {
    {
      const std::lock_guard lock(mutex_);
      finished_.push_back(std::move(result));
      running_ = false;
    }
    changed_.notify_all();
  }

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::optional<Job> queued_;
  bool running_ = false;
  bool stopping_ = false;
  int waiting_ = 0;  // workers blocked in next()
  std::vector<Result> finished_;
};

}  // namespace twr::gui
