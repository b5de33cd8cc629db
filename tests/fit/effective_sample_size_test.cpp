#include "libshapeproc/fit/effective_sample_size.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "libshapeproc/core/random.hpp"

namespace {

using shapeproc::core::Random;
using shapeproc::fit::effective_size;
using shapeproc::fit::EffectiveSize;

using Chains = std::vector<std::pair<int, int>>;

Chains equal_chains(int chains, int length) {
  Chains rows;
  for (int c = 0; c < chains; ++c) rows.emplace_back(c * length, (c + 1) * length);
  return rows;
}

double normal(Random& random) {  // Box-Muller
  const double u = 1.0 - random.uniform(), v = random.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
}

// `chains` AR(1) series x_t = φ x_{t−1} + e_t of `length` each, started at stationarity, in one
// column: their integrated autocorrelation time is (1 + φ) / (1 − φ).
std::vector<double> autoregressive(Random& random, int chains, int length, double phi) {
  std::vector<double> x;
  for (int c = 0; c < chains; ++c) {
    double value = normal(random) / std::sqrt(1.0 - phi * phi);
    for (int t = 0; t < length; ++t) {
      x.push_back(value);
      value = phi * value + normal(random);
    }
  }
  return x;
}

TEST(EffectiveSampleSize, ExactOnTinyChains) {
  // Two chains of two observations: means 1.5 and 3.5; W = 0.5, B/n = 2, var⁺ = 0.25 + 2 = 2.25.
  // ρ_1 = 1 − (0.5 − (−0.125)) / 2.25 = 13/18, so the first pair is 1 + 13/18 and τ = 1 + 26/18.
  const std::vector<double> samples = {1, 2, 3, 4};
  const EffectiveSize e = effective_size(samples, 1, 0, equal_chains(2, 2));
  EXPECT_DOUBLE_EQ(e.variance, 2.25);
  EXPECT_DOUBLE_EQ(e.autocorrelation, 1.0 + 26.0 / 18.0);
  EXPECT_DOUBLE_EQ(e.effective, 4.0 / (1.0 + 26.0 / 18.0));
  EXPECT_DOUBLE_EQ(e.standard_error, std::sqrt(2.25 / e.effective));
}

TEST(EffectiveSampleSize, AConstantStatisticHasNoError) {
  const std::vector<double> samples(40, 3.0);
  const EffectiveSize e = effective_size(samples, 1, 0, equal_chains(4, 10));
  EXPECT_EQ(e.standard_error, 0.0);
  EXPECT_EQ(e.effective, 40.0);
}

TEST(EffectiveSampleSize, FindsTheAutocorrelationTimeOfAnAutoregressiveSeries) {
  Random random(5);
  for (const double phi : {0.0, 0.5, 0.9}) {
    const std::vector<double> x = autoregressive(random, 4, 20000, phi);
    const EffectiveSize e = effective_size(x, 1, 0, equal_chains(4, 20000));
    const double tau = (1 + phi) / (1 - phi);
    EXPECT_NEAR(e.autocorrelation / tau, 1.0, 0.1) << "phi " << phi;
  }
}

// The point of the estimator: over many replicates, the spread of the chains' mean is the
// standard error it reports. 400 replicates pin the spread to ±3.5% (one standard error of a
// standard deviation, 1/√(2 × 400)); the test allows 4 of them.
TEST(EffectiveSampleSize, ItsErrorIsTheSpreadOfTheMean) {
  Random random(11);
  const int replicates = 400;
  for (const double phi : {0.5, 0.95}) {
    double sum = 0.0, squares = 0.0, reported = 0.0;
    for (int r = 0; r < replicates; ++r) {
      const std::vector<double> x = autoregressive(random, 4, 500, phi);
      double mean = 0.0;
      for (double v : x) mean += v / static_cast<double>(x.size());
      sum += mean;
      squares += mean * mean;
      reported += effective_size(x, 1, 0, equal_chains(4, 500)).standard_error / replicates;
    }
    const double mean = sum / replicates;
    const double spread =
        std::sqrt((squares / replicates - mean * mean) * replicates / (replicates - 1));
    EXPECT_NEAR(spread / reported, 1.0, 0.14) << "phi " << phi;
  }
}

// Chains that each sit in their own state (a packed exemplar held by some and lost by others)
// are worth about one observation each, however long they run.
TEST(EffectiveSampleSize, DisagreeingChainsAreWorthAboutOneObservationEach) {
  Random random(3);
  std::vector<double> x;
  for (int c = 0; c < 4; ++c)
    for (int t = 0; t < 1000; ++t) x.push_back(10.0 * c + 0.1 * normal(random));
  const EffectiveSize e = effective_size(x, 1, 0, equal_chains(4, 1000));
  EXPECT_LT(e.effective, 8.0);
  EXPECT_GT(e.standard_error, 5.0);  // the chain means' spread, 12.9, over √4
}

}  // namespace
