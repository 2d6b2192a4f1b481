// A fixed set of worker threads the fast path hands jobs to, so a frame does not pay for
// starting and joining threads. The calling thread works too: a pool of N threads starts
// N - 1 workers.
//
// A sleeping worker takes a while to start: measured on a 2-core KVM guest, about 55 us after a
// run a moment ago and over 500 us after 20 ms of sleep, when its virtual CPU had halted. A
// frame makes several runs (vertex stage, front end, bins), so a worker waits for the next run
// spinning, for kSpinAfterRun after a run and from wake() until rest(), and sleeps otherwise.
// A pool with more threads than the machine has CPUs never spins: its spinning workers would
// take the CPUs from the ones working.
#pragma once

#include <atomic>
#include <chrono>
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
  // use per-thread scratch space. An exception from a job is rethrown here. A worker that
  // wakes after the caller has taken every task is not waited for.
  void run(int taskCount, const std::function<void(int task, int thread)>& job);

  // Runs are coming (a frame starts): the workers wake now, while the caller prepares the
  // first one, and wait spinning until rest() or kWakeSpin has passed.
  void wake();
  // No run is coming soon (the frame is done): the workers sleep now instead of spinning.
  void rest();

  // How long workers spin after wake() without rest(), and after each run.
  static constexpr std::chrono::milliseconds kWakeSpin{20};
  static constexpr std::chrono::microseconds kSpinAfterRun{500};

 private:
  void workerLoop(int thread);
  void waitForRun(std::uint64_t seen);
  void work(int thread);
  void spinFor(std::chrono::nanoseconds duration);
  bool spinning() const;

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int, int)>* job_ = nullptr;  // guarded by mutex_, as are the next three
  int taskCount_ = 0;
  int nextTask_ = 0;
  std::exception_ptr error_;
  // Changed under mutex_, also read without it by spinning threads.
  std::atomic<std::uint64_t> generation_{0};  // bumped per run, so a worker joins each run once
  std::atomic<int> activeWorkers_{0};         // workers inside the current run's tasks
  std::atomic<bool> stopping_{false};
  // Until when workers spin (steady_clock, nanoseconds since its epoch; 0: sleep).
  std::atomic<std::int64_t> spinUntil_{0};
  bool spinAllowed_ = false;  // no more threads than online CPUs
};

}  // namespace twr
