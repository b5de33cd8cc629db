#include "libshapeproc/fit/pseudo_likelihood.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/random.hpp"

namespace shapeproc::fit {
namespace {

// β and two interaction parameters, a few quadrature points with mixed statistics.
PseudoLikelihoodDesign small_design() {
  PseudoLikelihoodDesign d;
  d.parameter_count = 3;
  d.data_sum = {5.0, 3.0, 1.0};
  d.points = {{2.0, 0, {}}, {1.5, 0, {{1, 1}}}, {0.5, 0, {{1, 2}, {2, 1}}}, {0.25, 0, {{2, 3}}}};
  return d;
}

TEST(PseudoLikelihood, ExactValueOnATinyDesign) {
  const PseudoLikelihoodDesign d = small_design();
  const std::vector<double> theta = {0.1, -0.3, 0.2};
  const double expected = 5 * 0.1 + 3 * -0.3 + 1 * 0.2 -
                          (2.0 * std::exp(0.1) + 1.5 * std::exp(0.1 - 0.3) +
                           0.5 * std::exp(0.1 - 0.6 + 0.2) + 0.25 * std::exp(0.1 + 0.6));
  EXPECT_NEAR(log_pseudo_likelihood(d, theta), expected, 1e-12);
}

TEST(PseudoLikelihood, GradientAndHessianMatchFiniteDifferences) {
  const PseudoLikelihoodDesign d = small_design();
  core::Random random(3);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> theta(3);
    for (double& t : theta) t = random.uniform(-1, 1);
    std::vector<double> gradient, hessian;
    log_pseudo_likelihood(d, theta, &gradient, &hessian);
    ASSERT_EQ(gradient.size(), 3u);
    ASSERT_EQ(hessian.size(), 9u);
    const double h = 1e-5;
    for (std::size_t i = 0; i < 3; ++i) {
      std::vector<double> up = theta, down = theta;
      up[i] += h;
      down[i] -= h;
      // Central differences: error O(h²) times the third derivative (order 1 here).
      const double numeric =
          (log_pseudo_likelihood(d, up) - log_pseudo_likelihood(d, down)) / (2 * h);
      EXPECT_NEAR(gradient[i], numeric, 1e-7) << "parameter " << i;
      std::vector<double> g_up, g_down;
      log_pseudo_likelihood(d, up, &g_up);
      log_pseudo_likelihood(d, down, &g_down);
      for (std::size_t j = 0; j < 3; ++j) {
        EXPECT_NEAR(hessian[i * 3 + j], (g_up[j] - g_down[j]) / (2 * h), 1e-6) << i << "," << j;
      }
    }
    // Concave: the Hessian's diagonal is negative.
    for (std::size_t i = 0; i < 3; ++i) EXPECT_LT(hessian[i * 3 + i], 0.0);
  }
}

TEST(PseudoLikelihood, MaximumHasZeroGradient) {
  const PseudoLikelihoodDesign d = small_design();
  const MpleResult mple = maximise_pseudo_likelihood(d, {0.0, 0.0, 0.0});
  std::vector<double> gradient;
  log_pseudo_likelihood(d, mple.theta, &gradient);
  for (double g : gradient) EXPECT_NEAR(g, 0.0, 1e-6);
  for (double se : mple.standard_errors) EXPECT_GT(se, 0.0);
}

TEST(PseudoLikelihood, ParameterWithExposureButNoDataIsOnTheBoundary) {
  PseudoLikelihoodDesign d = small_design();
  d.data_sum[2] = 0.0;
  const MpleResult mple = maximise_pseudo_likelihood(d, {0.0, 0.0, 0.0});
  EXPECT_EQ(mple.status[2], model::ParameterStatus::boundary);
  EXPECT_EQ(mple.theta[2], -INFINITY);
}

}  // namespace
}  // namespace shapeproc::fit
