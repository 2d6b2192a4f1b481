// The hand-over between the UI and a render worker (gui/job_queue.h): a newer job
// replaces a waiting one, a running job learns it is superseded, results come out in order.
#include "gui/job_queue.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace twr::gui {
namespace {

TEST(JobQueue, NewerJobReplacesTheWaitingOne) {
  JobQueue<int, int> queue;
  EXPECT_TRUE(queue.idle());
  queue.submit(1);
  queue.submit(2);
  EXPECT_TRUE(queue.hasQueued());
  const std::optional<int> job = queue.next();
  ASSERT_TRUE(job);
  EXPECT_EQ(*job, 2);
  EXPECT_FALSE(queue.idle());
  EXPECT_FALSE(queue.superseded());
  queue.submit(3);
  EXPECT_TRUE(queue.superseded());
  EXPECT_FALSE(queue.hasFinished());
  queue.finish(20);
  EXPECT_TRUE(queue.hasFinished());  // an idle UI draws a frame for it
  EXPECT_FALSE(queue.idle());  // 3 still waits
  EXPECT_EQ(queue.next().value_or(0), 3);
  queue.finish(30);
  EXPECT_TRUE(queue.idle());
  EXPECT_EQ(queue.takeFinished(), (std::vector<int>{20, 30}));
  EXPECT_FALSE(queue.hasFinished());
  EXPECT_TRUE(queue.takeFinished().empty());
}

TEST(JobQueue, StopWakesTheWorkerAndDropsTheWaitingJob) {
  JobQueue<int, int> queue;
  std::optional<int> seen = 7;
  std::thread worker([&] { seen = queue.next(); });
  EXPECT_TRUE(queue.waitForWorker(std::chrono::milliseconds(60'000))) << "the worker never asked for a job";
  queue.stop();  // wakes a worker blocked in next(), not one that has yet to ask
  worker.join();
  EXPECT_FALSE(seen);
  queue.submit(1);
  EXPECT_FALSE(queue.next());  // a stopped queue hands out nothing more
  EXPECT_TRUE(queue.superseded());
}

TEST(JobQueue, WaitIdleReturnsOnceTheJobIsDone) {
  JobQueue<int, int> queue;
  queue.submit(1);
  std::thread worker([&] {
    const std::optional<int> job = queue.next();
    queue.finish(job.value_or(0) * 10);
  });
  EXPECT_TRUE(queue.waitIdle(std::chrono::milliseconds(5000)));
  worker.join();
  EXPECT_EQ(queue.takeFinished(), std::vector<int>{10});
}

}  // namespace
}  // namespace twr::gui
