// The one ParallelFor of every `--threads` option (model/util/parallel.h): every job once, each
// in its own slot whatever the thread count; a ParallelFor inside a job of a threaded one runs
// its jobs in turn on that job's thread (one level of threads: the schedule's DOFs, the
// verdict's box points, the loop's candidates each run identification and diagnosis, which
// are ParallelFors themselves); a job's exception rethrown after the others, in job order.
#include "uuvplan/model/util/parallel.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace uuvplan::model {
namespace {

TEST(ParallelForTest, EveryJobRunsOnceInItsOwnSlotWhateverTheThreads) {
  constexpr std::size_t kJobs = 101;  // odd: the last worker's share is not a full one
  for (int threads : {1, 2, 4, 0}) {
    std::vector<int> runs(kJobs, 0);
    std::vector<double> out(kJobs, 0.0);
    ParallelFor(kJobs, threads, [&](std::size_t i) {
      ++runs[i];
      out[i] = 0.5 * static_cast<double>(i * i);
    });
    for (std::size_t i = 0; i < kJobs; ++i) {
      EXPECT_EQ(runs[i], 1) << "job " << i << ", threads " << threads;
      EXPECT_EQ(out[i], 0.5 * static_cast<double>(i * i)) << "job " << i << ", threads " << threads;
    }
  }
}

// Inner jobs on the outer job's own thread (no threads × threads on the same cores), every
// inner slot filled; after the outer loop the caller's thread may use threads again.
TEST(ParallelForTest, ANestedLoopRunsItsJobsInTurnOnItsJobsThread) {
  constexpr std::size_t kOuter = 6, kInner = 5;
  std::vector<std::thread::id> outer_thread(kOuter);
  std::vector<std::vector<std::thread::id>> inner_thread(kOuter,
                                                         std::vector<std::thread::id>(kInner));
  std::vector<std::vector<int>> inner_runs(kOuter, std::vector<int>(kInner, 0));
  ParallelFor(kOuter, 2, [&](std::size_t i) {
    outer_thread[i] = std::this_thread::get_id();
    ParallelFor(kInner, 4, [&](std::size_t j) {
      inner_thread[i][j] = std::this_thread::get_id();
      ++inner_runs[i][j];
      // Long enough that threads of the inner loop, were there any, would take some jobs.
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    });
  });
  for (std::size_t i = 0; i < kOuter; ++i) {
    for (std::size_t j = 0; j < kInner; ++j) {
      EXPECT_EQ(inner_runs[i][j], 1) << i << ", " << j;
      EXPECT_EQ(inner_thread[i][j], outer_thread[i]) << i << ", " << j;
    }
  }
  // The caller's thread is not left marked as inside a job (its later loops use threads again).
  EXPECT_FALSE(internal::in_parallel_job);
}

TEST(ParallelForTest, AFailingJobsExceptionIsRethrownAfterTheOthersInJobOrder) {
  for (int threads : {1, 3}) {
    std::vector<int> runs(8, 0);
    try {
      ParallelFor(runs.size(), threads, [&](std::size_t i) {
        ++runs[i];
        if (i == 2 || i == 6) throw std::runtime_error("job " + std::to_string(i));
      });
      ADD_FAILURE() << "no exception, threads " << threads;
    } catch (const std::runtime_error& e) {
      // A serial loop stops at job 2; the threaded one runs every job and then rethrows the
      // first in job order, so the message is the same.
      EXPECT_STREQ(e.what(), "job 2") << "threads " << threads;
    }
    if (threads > 1) {
      for (int r : runs) EXPECT_EQ(r, 1);
    }
  }
}

}  // namespace
}  // namespace uuvplan::model
