// The stopwatch counts wall time from its start or restart.
#include "libshapeproc/core/stopwatch.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace shapeproc::core {
namespace {

TEST(Stopwatch, CountsFromItsStartAndRestart) {
  Stopwatch watch;
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const double first = watch.seconds();
  EXPECT_GE(first, 0.02);
  EXPECT_GE(watch.seconds(), first);  // never runs backwards
  watch.restart();
  EXPECT_LT(watch.seconds(), first);
}

}  // namespace
}  // namespace shapeproc::core
