// The automatic stopping rule (sample/stationarity.hpp): where it finds a count stationary, and
// that a chain with a run-on then runs as long again before it stops.
#include "libshapeproc/sample/stationarity.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace shapeproc::sample {
namespace {

// Runs the rule on a count given per step until it stops; returns the stopping step (−1: never).
template <typename Count>
long long stopping_step(StationarityRule& rule, Count count, long long limit) {
  for (long long step = 1; step <= limit; ++step)
    if (rule.after_step(step, count(step)) != StationarityRule::Verdict::keep_going) return step;
  return -1;
}

TEST(Stationarity, AConstantCountStopsAtTheFirstCheckOrRunsAsLongAgain) {
  // 10 elements: 1,000 steps per element are reached before the first check at 20,000 steps.
  const auto ten = [](long long) { return 10; };
  StationarityRule held(5000000);
  EXPECT_EQ(stopping_step(held, ten, 1000000), 20000);
  StationarityRule from_empty(5000000, true);
  EXPECT_EQ(stopping_step(from_empty, ten, 1000000), 40000);
  EXPECT_TRUE(from_empty.last_check().stationary);
  EXPECT_EQ(from_empty.last_check().first, 10.0);
}

TEST(Stationarity, ARisingCountKeepsTheChainGoingUntilItLevelsOff) {
  // One element more every 1,000 steps up to 60, then level.
  const auto rising = [](long long step) { return static_cast<int>(std::min(60LL, step / 1000)); };
  StationarityRule held(5000000);
  const long long at = stopping_step(held, rising, 5000000);
  EXPECT_GT(at, 60000);
  StationarityRule from_empty(5000000, true);
  EXPECT_EQ(stopping_step(from_empty, rising, 5000000), 2 * at);
}

TEST(Stationarity, TheStepLimitCapsTheRunOn) {
  StationarityRule rule(30000, true);
  EXPECT_EQ(stopping_step(
                rule, [](long long) { return 10; }, 1000000),
            30000);
}

}  // namespace
}  // namespace shapeproc::sample
