// A fixed set of worker threads the fast path hands jobs to, so a frame does not pay for
// starting and joining threads. The calling thread works too: a pool of N threads starts
// N - 1 workers.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace twr {

class WorkerPool {
 public:
  explicit WorkerPool(int threads);  // values below 1 mean 1
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls job(task, thread) once for every task in [0, taskCount) (exclusive end) and returns
  // when all have finished. Tasks go out in increasing order to whichever thread is free;
  // `thread` in [0, threads()) names the thread running it (0 is the caller), so a job can
  // use per-thread scratch space. An exception from a job is rethrown here.
  void run(int taskCount, const std::function<void(int task, int thread)>& job);

 private:
  void workerLoop(int thread);
  void work(int thread);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int, int)>* job_ = nullptr;
  int taskCount_ = 0;
  int nextTask_ = 0;        // guarded by mutex_
  int busyWorkers_ = 0;     // workers inside the current run
  std::uint64_t generation_ = 0;  // bumped per run, so a worker joins each run once
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace twr
