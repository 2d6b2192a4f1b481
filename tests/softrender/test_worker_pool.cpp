// The fast path's worker pool (softrender/worker_pool.h): every task of a run runs exactly once
// on a valid thread, whether the workers spin or sleep between runs (and with more threads than
// CPUs, where they only sleep); a job's exception reaches
// the caller and leaves the pool usable; a pool is destroyed cleanly in any state.
#include "softrender/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace twr {
namespace {

// Runs `taskCount` tasks and checks each ran once, on a thread the pool names.
void expectEveryTaskOnce(WorkerPool& pool, int taskCount) {
  std::vector<std::atomic<int>> runs(static_cast<std::size_t>(taskCount));
  std::atomic<int> badThread{0};
  pool.run(taskCount, [&](int task, int thread) {
    runs[static_cast<std::size_t>(task)].fetch_add(1);
    if (thread < 0 || thread >= pool.threads()) badThread.fetch_add(1);
  });
  for (int t = 0; t < taskCount; ++t) EXPECT_EQ(runs[static_cast<std::size_t>(t)].load(), 1) << "task " << t;
  EXPECT_EQ(badThread.load(), 0);
}

TEST(WorkerPool, EveryTaskRunsOnceForAnyThreadAndTaskCount) {
  for (const int threads : {0, 1, 2, 3, 8}) {
    WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads < 1 ? 1 : threads);
    for (const int tasks : {0, 1, 2, 3, 7, 64, 1000}) expectEveryTaskOnce(pool, tasks);
  }
}

// Thousands of tiny runs back to back (the worker spinning between them, often waking after
// the caller has taken every task), then runs between which it falls asleep, woken by wake()
// or by the run itself. Two threads: a pool with more threads than CPUs does not spin.
TEST(WorkerPool, RunsBackToBackAndAfterSleepingWorkers) {
  WorkerPool pool(2);
  for (int i = 0; i < 5000; ++i) expectEveryTaskOnce(pool, 1 + i % 5);
  pool.rest();
  for (int i = 0; i < 3; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (i == 1) pool.wake();
    expectEveryTaskOnce(pool, 16);
    pool.rest();
  }
}

// Tasks that take a while on every thread: the caller waits for the workers' last tasks.
TEST(WorkerPool, CallerWaitsForTasksStillRunningOnWorkers) {
  WorkerPool pool(4);
  pool.wake();
  std::atomic<int> finished{0};
  pool.run(8, [&](int, int) {
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    finished.fetch_add(1);
  });
  EXPECT_EQ(finished.load(), 8);
  pool.rest();
}

TEST(WorkerPool, AJobsExceptionReachesTheCallerAndThePoolGoesOn) {
  WorkerPool pool(2);
  EXPECT_THROW(pool.run(50,
                        [](int task, int) {
                          if (task == 10) throw std::runtime_error("task 10");
                        }),
               std::runtime_error);
  expectEveryTaskOnce(pool, 20);  // the next run starts afresh
}

TEST(WorkerPool, DestroyedWhileSpinningAsleepOrNeverUsed) {
  { WorkerPool unused(3); }
  {
    WorkerPool spinning(2);
    spinning.wake();
  }
  {
    WorkerPool afterRun(2);
    expectEveryTaskOnce(afterRun, 5);  // destroyed within the spin after a run
  }
  {
    WorkerPool asleep(2);
    expectEveryTaskOnce(asleep, 5);
    asleep.rest();
  }
}

}  // namespace
}  // namespace twr
