// The thread pool: every index once, on any pool size; exceptions after all tasks finished.
#include "worker/env/vector_env/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace rlpos {
namespace {

TEST(ThreadPool, RunsEveryIndexOnceWhateverItsSize) {
  for (std::size_t threads : {1, 2, 3, 4, 8}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.Size(), threads);
    for (std::size_t n : {0, 1, 2, 7, 100}) {
      std::vector<int> runs(n, 0);  // each index written by one task only
      pool.ForEach(n, [&](std::size_t i) { ++runs[i]; });
      EXPECT_EQ(runs, std::vector<int>(n, 1)) << threads << " threads, n = " << n;
    }
  }
}

TEST(ThreadPool, RethrowsTheLowestIndexAfterEveryTaskFinished) {
  ThreadPool pool(4);
  std::atomic<int> finished{0};
  try {
    pool.ForEach(40, [&](std::size_t i) {
      ++finished;
      if (i == 13 || i == 31)
        throw std::runtime_error("task " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 13");
  }
  EXPECT_EQ(finished.load(), 40);
  std::vector<int> runs(9, 0);  // the pool still works after a failed call
  pool.ForEach(9, [&](std::size_t i) { ++runs[i]; });
  EXPECT_EQ(runs, std::vector<int>(9, 1));
}

TEST(ThreadPool, DefaultSizeIsTheCoresButNoMoreThanTheTasks) {
  EXPECT_EQ(DefaultThreadCount(1), 1u);
  EXPECT_EQ(DefaultThreadCount(0), 1u);
  EXPECT_LE(DefaultThreadCount(1000), std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_GE(DefaultThreadCount(1000), 1u);
}

}  // namespace
}  // namespace rlpos
