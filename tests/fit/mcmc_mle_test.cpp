#include "libshapeproc/fit/mcmc_mle.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tests/point_model.hpp"

namespace shapeproc::fit {
namespace {

// Two chains of 2,000 steps of burn-in, then `steps` observed every `every`.
ChainsSetting two_chains(long long steps, long long every) {
  ChainsSetting setting;
  setting.chains = 2;
  setting.burn_in = 2000;
  setting.steps = steps;
  setting.observe_every = every;
  return setting;
}

// The MLE's chains for the Strauss-type models below: two of 10,000 steps of burn-in, then 40,000
// observed every 50.
MleOptions strauss_fit() {
  MleOptions options;
  options.sampling.chains = 2;
  options.sampling.burn_in = 10000;
  options.sampling.steps = 40000;
  options.sampling.observe_every = 50;
  return options;
}

TEST(MaximumLikelihood, PoissonIsClosedForm) {
  const geometry::Domain window = geometry::Domain::from_sizes({100, 50}, geometry::Boundary::open);
  const MleResult mle =
      maximise_likelihood(testing::point_model(1.0), window, {37.0}, MleOptions{});
  ASSERT_TRUE(mle.converged);
  EXPECT_DOUBLE_EQ(std::exp(mle.theta[0]), 37.0 / 5000.0);
  EXPECT_DOUBLE_EQ(with_estimates(testing::point_model(1.0), mle).categories[0].beta,
                   37.0 / 5000.0);
  EXPECT_THROW(maximise_likelihood(testing::point_model(1.0), window, {0.0}, MleOptions{}),
               core::ArgumentError);
  EXPECT_THROW(maximise_likelihood(testing::point_model(1.0), window, {1.0, 2.0}, MleOptions{}),
               core::ArgumentError);
}

// A Strauss-type point process with two bands on a torus, sampled at known θ: the MLE from its
// statistics, started at γ = 1, lands within 3 standard errors of the truth, and the fitted
// model's expected statistics match the observed ones.
TEST(MaximumLikelihood, RecoversAPiecewiseStraussModelOnATorus) {
  const model::ShapeProcessModel truth = testing::point_model(0.03, {0.0, 3.0, 6.0}, {0.3, 0.7});
  const geometry::Domain window = geometry::Domain::from_sizes({70, 70}, geometry::Boundary::torus);
  sample::SamplerOptions sampler_options;
  sampler_options.iterations = 60000;
  core::Random random(5);
  const sample::SampleResult z =
      sample::sample_shape_process(truth, window, sampler_options, random);
  const std::vector<double>& observed = z.statistics;
  ASSERT_GT(observed[0], 60.0);
  ASSERT_GT(observed[1], 3.0);

  model::ShapeProcessModel start = truth;
  start.categories[0].beta = observed[0] / window.measure();
  start.interactions[0].axes[0].gammas = {1.0, 1.0};
  MleOptions options = strauss_fit();
  const MleResult mle = maximise_likelihood(start, window, observed, options);
  ASSERT_TRUE(mle.converged) << mle.iterations << " iterations";
  const std::vector<double> true_theta = {std::log(0.03), std::log(0.3), std::log(0.7)};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(mle.theta[k], true_theta[k], 3 * mle.standard_errors[k]) << "parameter " << k;
    EXPECT_NEAR(mle.expected[k], observed[k], mle.tolerance * mle.expected_error[k] + 1e-9) << k;
  }
}

// A jammed exemplar: a square lattice of spacing 10 on a 100 x 100 torus under a hard core of 9.5,
// where a new point fits only within 0.5 of an empty lattice site, and one band [9.5, 12) holding
// each point's four neighbours. Chains from empty, with or without the compressing burn-in, stay
// below its 100 points even at β = 10⁶ (the lattice is the densest state the hard core allows, and
// no chain finds it). The fit then never presents the exemplar's counts as reached: it gives up,
// saying so, and its expected count is the one the chains reach.
TEST(MaximumLikelihood, AJammedLatticeIsNotReachedFromEmptyAndTheFitSaysSo) {
  const model::ShapeProcessModel start = testing::point_model(0.01, {9.5, 12.0}, {1.0});
  const geometry::Domain window =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::torus);
  const std::vector<double> observed = {100.0, 200.0};  // points; pairs at distance 10
  MleOptions options;
  options.sampling.chains = 2;
  options.sampling.burn_in = 4000;
  options.sampling.steps = 8000;
  options.sampling.observe_every = 50;
  options.sampling.burn_in_kind = model::BurnIn::compressing;
  options.max_iterations = 12;

  model::ShapeProcessModel dense = start;
  dense.categories[0].beta = 1e6;
  const StatisticsMoments reached = statistics_moments(dense, window, options.sampling);
  EXPECT_GT(reached.mean[0], 70.0);  // well past half the lattice
  EXPECT_LT(reached.mean[0], 97.0);

  const MleResult mle = maximise_likelihood(start, window, observed, options);
  EXPECT_FALSE(mle.converged);
  EXPECT_LT(mle.expected[0], 97.0);
  // It gives up once 4 simulations in a row, after at least 8, have stayed short of 90% of the
  // count without gaining 2% on those before (seed 1: 0.32, 0.57, 0.80, 0.79, 0.84, 0.83, 0.87,
  // then 0.84, 0.84, 0.86, 0.84 of it: it gives up at the 11th).
  EXPECT_NE(mle.abandoned.find("stay short of the exemplar's count"), std::string::npos)
      << mle.abandoned;
  EXPECT_LT(mle.iterations, 12);
}

// R-hat on hand-made chains of 4 observations: chains that alternate alike agree (within
// variance 1/3, between 0: sqrt(3/4)); chains around 1.5 and 5.5 do not; chains constant at
// different values disagree without limit; a constant statistic has R-hat 1.
TEST(MaximumLikelihood, PotentialScaleReductionTellsChainsThatDisagree) {
  StatisticsMoments m;
  m.parameters = 3;
  m.observations = 8;
  m.samples = {1, 7, 2, 2, 7, 2, 1, 7, 2, 2, 7, 2,   // chain 1: (1, 2, 1, 2), 7, 2
               2, 7, 2, 1, 7, 2, 2, 7, 2, 1, 7, 2};  // chain 2: (2, 1, 2, 1), 7, 2
  const std::vector<std::pair<int, int>> chains = {{0, 4}, {4, 8}};
  std::vector<double> r = potential_scale_reduction(m, chains);
  EXPECT_NEAR(r[0], std::sqrt(0.75), 1e-12);
  EXPECT_EQ(r[1], 1.0);
  EXPECT_EQ(r[2], 1.0);
  for (int i = 12; i < 24; i += 3) m.samples[static_cast<std::size_t>(i)] += 4;  // 5.5 on average
  m.samples[14] = m.samples[17] = m.samples[20] = m.samples[23] = 3;             // constant 3
  r = potential_scale_reduction(m, chains);
  EXPECT_GT(r[0], 3.0);
  EXPECT_TRUE(std::isinf(r[2]));
}

// Importance reweighting: a Poisson sample of mean μ reweighted by δ in log β has mean μ e^δ
// (within 4 standard errors of the sample), δ = 0 gives the sample's own moments, and the
// effective sample size shrinks as δ grows.
TEST(MaximumLikelihood, ReweightingMovesAPoissonMeanByExpDelta) {
  const geometry::Domain window = geometry::Domain::from_sizes({10, 10}, geometry::Boundary::torus);
  const ChainsSetting setting = two_chains(60000, 50);
  const StatisticsMoments sample = statistics_moments(testing::point_model(0.5), window, setting);
  EXPECT_NEAR(sample.mean[0], 50.0, 4 * sample.standard_error[0]);
  double share = 0.0;
  const StatisticsMoments same = reweighted(sample, {0.0}, share);
  EXPECT_NEAR(share, 1.0, 1e-9);
  EXPECT_NEAR(same.mean[0], sample.mean[0], 1e-9);
  EXPECT_NEAR(same.covariance[0], sample.covariance[0], 1e-9);
  const StatisticsMoments moved = reweighted(sample, {0.1}, share);
  EXPECT_NEAR(moved.mean[0], sample.mean[0] * std::exp(0.1), 4 * sample.standard_error[0]);
  EXPECT_LT(share, 1.0);
  double farther = 0.0;
  reweighted(sample, {0.3}, farther);
  EXPECT_LT(farther, share);
}

// More chains pooled with a sample: the rows of the first sample, then those of the new chains,
// each chain's range after the last; the moments are those of all the rows together (exactly the
// mean and the unbiased variance of the concatenation), and the pooled error is smaller. A
// reweighted sample has lost its chains and cannot be pooled.
TEST(MaximumLikelihood, MoreChainsArePooledWithASample) {
  const geometry::Domain window = geometry::Domain::from_sizes({10, 10}, geometry::Boundary::torus);
  ChainsSetting setting = two_chains(20000, 50);
  const StatisticsMoments first = statistics_moments(testing::point_model(0.5), window, setting);
  setting.seed = 77;
  const StatisticsMoments added = statistics_moments(testing::point_model(0.5), window, setting);
  const StatisticsMoments pooled =
      statistics_moments(testing::point_model(0.5), window, setting, &first);
  ASSERT_EQ(pooled.chains(), 4);
  ASSERT_EQ(pooled.observations, first.observations + added.observations);
  EXPECT_EQ(pooled.chain_rows[1], first.chain_rows[1]);
  EXPECT_EQ(pooled.chain_rows[2].first, first.observations);
  EXPECT_EQ(pooled.chain_rows[3].second, pooled.observations);
  std::vector<double> rows = first.samples;
  rows.insert(rows.end(), added.samples.begin(), added.samples.end());
  EXPECT_EQ(pooled.samples, rows);
  double sum = 0.0;
  double squares = 0.0;
  for (double t : rows) {
    sum += t;
    squares += t * t;
  }
  const double n = static_cast<double>(rows.size());
  EXPECT_NEAR(pooled.mean[0], sum / n, 1e-9);
  EXPECT_NEAR(pooled.covariance[0], (squares - sum * sum / n) / (n - 1), 1e-6);
  EXPECT_LT(pooled.standard_error[0], first.standard_error[0]);
  double share = 0.0;
  const StatisticsMoments moved = reweighted(first, {0.1}, share);
  EXPECT_THROW(statistics_moments(testing::point_model(0.5), window, setting, &moved),
               core::ArgumentError);
}

// The stationary window: a 100 x 50 window inside a 150 x 100 torus. Without interaction the
// estimate is still the closed form, n / |W| of the window, not of the torus.
TEST(StationaryWindow, PoissonIsClosedFormOnTheWindow) {
  const geometry::Domain torus(
      geometry::Box3(geometry::Vec3(-25, -25, 0), geometry::Vec3(125, 75, 0)), 2,
      geometry::Boundary::torus);
  MleOptions options;
  options.sampling.observe_region =
      geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(100, 50, 0));
  const MleResult mle = maximise_likelihood(testing::point_model(1.0), torus, {37.0}, options);
  ASSERT_TRUE(mle.converged);
  EXPECT_DOUBLE_EQ(std::exp(mle.theta[0]), 37.0 / 5000.0);
}

// Observations of a window inside a larger torus: for a Poisson process of intensity β the
// window's count has mean and variance β|W|, the torus's mean β|T|, and the derivative
// Cov(t_W, t) equals Var(t_W) (the counts outside the window are independent of it). Batch-means
// errors bound the means; the variances are checked to 15% (about four standard errors of a
// variance from some 1,200 nearly independent observations: √(2/1200) ≈ 4%).
TEST(StationaryWindow, AWindowsStatisticsAndTheirDerivative) {
  const geometry::Domain torus = geometry::Domain::from_sizes({20, 20}, geometry::Boundary::torus);
  ChainsSetting setting = two_chains(120000, 200);
  setting.observe_region = geometry::Box3(geometry::Vec3(5, 5, 0), geometry::Vec3(15, 15, 0));
  const StatisticsMoments m = statistics_moments(testing::point_model(0.5), torus, setting);
  ASSERT_EQ(m.density_samples.size(), m.samples.size());
  EXPECT_NEAR(m.mean[0], 50.0, 4 * m.standard_error[0]);
  double whole = 0.0;
  for (double t : m.density_samples) whole += t / static_cast<double>(m.observations);
  EXPECT_NEAR(whole, 200.0, 4 * m.standard_error[0] * 2.0);  // √(|T| / |W|) = 2 times the error
  EXPECT_NEAR(m.covariance[0], 50.0, 0.15 * 50.0);
  EXPECT_NEAR(m.information[0], m.covariance[0], 0.15 * 50.0);
  // Reweighting goes by the torus's count: exp(δ) scales the window's mean too.
  double share = 0.0;
  const StatisticsMoments moved = reweighted(m, {0.05}, share);
  EXPECT_NEAR(moved.mean[0], m.mean[0] * std::exp(0.05), 4 * m.standard_error[0]);
}

// A Strauss-type process sampled on a 150 x 150 torus; the exemplar is its central 70 x 70 window,
// cut out (an open window whose elements had neighbours beyond its edge). Fitted on the
// stationary window (the window's own torus, fit::stationary_domain, its statistics without the
// pairs across the seam), the estimate lands within 3 of its standard errors (the sandwich's) of
// the truth.
TEST(StationaryWindow, RecoversAStraussModelFromAPieceOfALargerPattern) {
  const model::ShapeProcessModel truth = testing::point_model(0.03, {0.0, 3.0, 6.0}, {0.3, 0.7});
  const geometry::Box3 window(geometry::Vec3(40, 40, 0), geometry::Vec3(110, 110, 0));
  sample::SamplerOptions sampler_options;
  sampler_options.iterations = 200000;
  sampler_options.observe_every = sampler_options.iterations;
  sampler_options.observe_region = window;
  core::Random random(7);
  const sample::SampleResult z = sample::sample_shape_process(
      truth, geometry::Domain::from_sizes({150, 150}, geometry::Boundary::torus), sampler_options,
      random);
  ASSERT_EQ(z.observations.size(), 1u);
  const std::vector<double> observed(z.observations[0].begin(), z.observations[0].begin() + 3);
  ASSERT_GT(observed[0], 60.0);
  ASSERT_GT(observed[1], 3.0);

  model::ShapeProcessModel start = truth;
  start.categories[0].beta = observed[0] / 4900.0;
  start.interactions[0].axes[0].gammas = {1.0, 1.0};
  MleOptions options = strauss_fit();
  options.sampling.observe_region = window;
  const geometry::Domain torus(window, 2, geometry::Boundary::torus);
  const MleResult mle = maximise_likelihood(start, torus, observed, options);
  ASSERT_TRUE(mle.converged) << mle.iterations << " iterations";
  const std::vector<double> true_theta = {std::log(0.03), std::log(0.3), std::log(0.7)};
  for (std::size_t k = 0; k < 3; ++k) {
    ASSERT_TRUE(std::isfinite(mle.standard_errors[k])) << k;
    EXPECT_NEAR(mle.theta[k], true_theta[k], 3 * mle.standard_errors[k]) << "parameter " << k;
    EXPECT_NEAR(mle.expected[k], observed[k], mle.tolerance * mle.expected_error[k] + 1e-9) << k;
  }
}

}  // namespace
}  // namespace shapeproc::fit
