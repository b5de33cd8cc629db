// The automatic stopping rule (sample/stationarity.hpp): where it finds a count stationary, and
// that a chain with a run-on then runs as long again before it stops.
#include "libshapeproc/sample/stationarity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

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

// A statistic other than a count has no floor of one: a mean nearest distance of about 2 whose
// quarters differ by 0.04 (a drift of 0.004 per value) is not stationary, where a count's floor,
// a quarter of one, would have passed it; the same values without the drift are stationary; with
// fewer than `least` values in the second half there is no verdict.
TEST(Stationarity, AValuesTrendHasNoFloorOfOne) {
  std::vector<double> drifting, level;
  for (int i = 0; i < 40; ++i) {
    const double noise = 0.0005 * ((i * 7) % 5 - 2);
    drifting.push_back(2.0 + 0.004 * i + noise);
    level.push_back(2.0 + noise);
  }
  const CountTrend drift = value_trend(drifting, 10);
  EXPECT_FALSE(drift.stationary);
  EXPECT_LT(drift.second - drift.first, 0.25);
  EXPECT_TRUE(value_trend(level, 10).stationary);
  EXPECT_NEAR(value_trend(level, 10).first, 2.0, 0.002);
  EXPECT_FALSE(value_trend(level, 30).stationary);
  EXPECT_EQ(value_trend(level, 30).first, 0.0);
}

// A rare category that creeps up while a common one gives way, the total steady (40 large trees
// turning into 60 among 1,000 elements by step 1,200,000): the total alone passes at the first
// check after 1,000 steps per element, the rule of two categories keeps the chain going past the
// trees' rise.
TEST(Stationarity, ACategoryCreepingUnderASteadyTotalKeepsTheChainGoing) {
  const auto trees = [](long long step) {
    return std::min(60.0, 40.0 + static_cast<double>(step) / 60000.0);
  };
  const auto run = [&](StationarityRule& rule) {
    for (long long step = 1; step <= 5000000; ++step) {
      const std::vector<double> counts{trees(step), 1000.0 - trees(step)};
      if (rule.after_step(step, 1000, counts) != StationarityRule::Verdict::keep_going) return step;
    }
    return -1LL;
  };
  StationarityRule total(5000000);
  const long long steady = run(total);
  EXPECT_GE(steady, 1000000);  // 1,000 steps per element
  EXPECT_LT(steady, 1200000);  // the trees still rising
  StationarityRule categories(5000000, false, 2);
  EXPECT_GT(run(categories), 1200000);  // after the rise
}

TEST(Stationarity, TheStepLimitCapsTheRunOn) {
  StationarityRule rule(30000, true);
  EXPECT_EQ(stopping_step(
                rule, [](long long) { return 10; }, 1000000),
            30000);
}

}  // namespace
}  // namespace shapeproc::sample
