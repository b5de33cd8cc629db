// The two-sample W1 test: its size on samples of one distribution, its power on shifted ones, and
// a nearest-distance sample's repeated values counted once.
#include "libshapeproc/metrics/wasserstein_test.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/random.hpp"

namespace shapeproc::metrics {
namespace {

// `n` draws of an exponential distribution of mean 1, moved by `shift`, each value `repeat` times.
Distribution exponential(int n, double shift, core::Random& random, int repeat = 1) {
  std::vector<double> values, borders;
  for (int i = 0; i < n; ++i) {
    const double x = shift - std::log(1.0 - random.uniform());
    for (int r = 0; r < repeat; ++r) values.push_back(x);
  }
  borders.assign(values.size(), std::numeric_limits<double>::infinity());
  return censored_distribution(values, borders, 1e9);
}

// 400 pairs of samples (30 and 120) of one distribution: the figure at level 0.05 is exceeded
// about 20 times; the binomial's 99.9% bounds for 400 trials at 0.05 are 8 and 35.
TEST(WassersteinTest, SamplesOfOneDistributionExceedItAtItsLevel) {
  core::Random random(5);
  WassersteinTestOptions options;
  options.level = 0.05;
  options.resamples = 199;
  int exceeded = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Distribution a = exponential(30, 0.0, random), b = exponential(120, 0.0, random);
    options.seed = static_cast<std::uint64_t>(trial) + 1;
    exceeded += wasserstein1(a, b) > wasserstein_test(a, b, options).critical;
  }
  EXPECT_GE(exceeded, 8);
  EXPECT_LE(exceeded, 35);
}

// Samples of 100 moved apart by the distribution's standard deviation: W1 is about 1, the figure
// at 1% about 0.4; 20 of 20 pairs are found apart (at half the deviation, 18 of 20).
TEST(WassersteinTest, SamplesMovedApartExceedIt) {
  core::Random random(6);
  for (int trial = 0; trial < 20; ++trial) {
    const Distribution a = exponential(100, 0.0, random), b = exponential(100, 1.0, random);
    EXPECT_GT(wasserstein1(a, b), wasserstein_test(a, b).critical) << trial;
  }
}

// Each value twice (a mutual nearest pair measures one distance from both ends) is one sample:
// the figure is the same as for the values once, and sizes are capped.
TEST(WassersteinTest, RepeatedValuesCountOnceAndSizesAreCapped) {
  core::Random r1(7), r2(7);
  const Distribution once = exponential(40, 0.0, r1), twice = exponential(40, 0.0, r2, 2);
  ASSERT_EQ(twice.samples, 80);
  const WassersteinTest a = wasserstein_test(once, once), b = wasserstein_test(twice, twice);
  EXPECT_EQ(b.sizes[0], 40);
  EXPECT_DOUBLE_EQ(a.critical, b.critical);
  WassersteinTestOptions capped;
  capped.largest_sample = 16;
  EXPECT_EQ(wasserstein_test(once, twice, capped).sizes[1], 16);
  EXPECT_THROW(wasserstein_test(Distribution{}, once), core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::metrics
