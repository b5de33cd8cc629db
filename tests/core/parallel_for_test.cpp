// The parallel loop: every index once, its thread count, and the first exception rethrown.
#include "libshapeproc/core/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace shapeproc::core {
namespace {

TEST(ParallelFor, RunsEveryIndexOnce) {
  for (const int threads : {0, 1, 2, 7}) {
    std::vector<std::atomic<int>> hits(1000);
    parallel_for(1000, threads, [&](long long i) { ++hits[static_cast<std::size_t>(i)]; });
    for (const auto& h : hits) EXPECT_EQ(h.load(), 1) << threads << " threads";
  }
  int calls = 0;
  parallel_for(0, 4, [&](long long) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, ThreadsAreBoundedByTheWork) {
  EXPECT_EQ(loop_threads(4, 2), 2);
  EXPECT_EQ(loop_threads(3, 100), 3);
  EXPECT_EQ(loop_threads(5, 0), 1);
  EXPECT_GE(loop_threads(0, 1'000'000), 1);  // one per core
}

TEST(ParallelFor, RethrowsTheLowestIndexsExceptionAfterAllStopped) {
  std::atomic<int> done{0};
  try {
    parallel_for(200, 2, [&](long long i) {
      ++done;
      if (i == 50 || i == 150) throw std::runtime_error("index " + std::to_string(i));
    });
    FAIL() << "nothing was thrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "index 50");
  }
  EXPECT_GE(done.load(), 2);
}

}  // namespace
}  // namespace shapeproc::core
