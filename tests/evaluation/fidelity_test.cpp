#include "libshapeproc/evaluation/fidelity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/random.hpp"
#include "tests/point_model.hpp"

namespace shapeproc::evaluation {
namespace {

// `n` points uniformly on a `side` × `side` window.
geometry::Scene random_points(int n, double side, std::uint64_t seed) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(side, side, 0));
  scene.categories.push_back({"points"});
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  core::Random random(seed);
  for (int i = 0; i < n; ++i)
    scene.elements.push_back(
        {0, 0, geometry::Vec3(random.uniform(0, side), random.uniform(0, side), 0)});
  return scene;
}

// Exact values: with 2 degrees of freedom the upper tail is exp(−x/2); with 1, erfc(√(x/2)).
TEST(Fidelity, ChiSquareUpperTail) {
  EXPECT_NEAR(chi_square_upper_tail(3.0, 2), std::exp(-1.5), 1e-14);
  EXPECT_NEAR(chi_square_upper_tail(3.84, 1), std::erfc(std::sqrt(3.84 / 2)), 1e-14);
  EXPECT_EQ(chi_square_upper_tail(0.0, 4), 1.0);
}

// A Poisson exemplar checked against its own closed-form fit: every count within 4 standard
// errors over the chains, the output's density within 4 Poisson standard deviations of the
// exemplar's, and no collisions among points.
TEST(Fidelity, APoissonModelReproducesItsExemplar) {
  const geometry::Scene exemplar = random_points(60, 100.0, 7);
  const model::ShapeProcessModel model = testing::point_model(60.0 / 10000.0);
  FidelityOptions options;
  options.sampling.chains = 8;
  options.sampling.burn_in = 2000;
  const FidelityReport r = check_fidelity(exemplar, model, geometry::Boundary::open,
                                          geometry::EdgeTreatment::none, options);
  ASSERT_EQ(r.own_window.size(), 1u);
  EXPECT_EQ(r.own_window[0].exemplar, 60.0);
  EXPECT_LT(r.worst_count_z, 4.0);
  // Each output has 4 exemplars' area: 240 expected, sd √240; their mean of 4 within 4 of its
  // standard deviations √240 / 2, and the reported error near that (a standard deviation from 4
  // outputs is only good to about 40%).
  EXPECT_EQ(r.outputs, 4);
  EXPECT_NEAR(r.output_elements, 240.0, 4 * std::sqrt(240.0) / 2);
  EXPECT_NEAR(r.density_ratio, r.output_elements / 240.0, 1e-12);
  EXPECT_GT(r.density_ratio_error, 0.0);
  EXPECT_LT(r.density_ratio_error, 3 * std::sqrt(240.0) / 2 / 240.0);
  EXPECT_EQ(r.output_collisions, 0);
  EXPECT_TRUE(std::isnan(r.class_p_value));
  // One output: the first of the four (chain 0 keeps the seed), with no error.
  options.outputs = 1;
  const FidelityReport one = check_fidelity(exemplar, model, geometry::Boundary::open,
                                            geometry::EdgeTreatment::none, options);
  EXPECT_EQ(one.outputs, 1);
  EXPECT_EQ(one.density_ratio_error, 0.0);
  EXPECT_NEAR(one.output_elements, 240.0, 4 * std::sqrt(240.0));
}

// A maximum-likelihood fit with the attraction prior solves E[t] = t(z) − log γ / σ² in a band
// with log γ > 0: that band's mean is checked against that target (and counts in the worst),
// an inhibiting band's against the exemplar's count.
TEST(Fidelity, ABandTheAttractionPriorHoldsDownIsCheckedAgainstTheFitsTarget) {
  const geometry::Scene exemplar = random_points(20, 50.0, 3);
  FidelityOptions options;
  options.sampling.chains = 2;
  options.sampling.burn_in = 1000;
  options.sampling.steps = 4000;
  options.outputs = 1;
  for (const double log_gamma : {1.5, -0.7}) {
    model::ShapeProcessModel model =
        testing::point_model(20.0 / 2500.0, {2.0, 5.0}, {std::exp(log_gamma)});
    model.interactions[0].axes[0].observed_pairs = {7};
    model.fit.emplace().likelihood.emplace().attraction_prior_sd = 1.5;
    const FidelityReport r = check_fidelity(exemplar, model, geometry::Boundary::open,
                                            geometry::EdgeTreatment::none, options);
    ASSERT_EQ(r.own_window.size(), 2u);
    const StatisticCheck& band = r.own_window[1];
    EXPECT_EQ(band.exemplar, 7.0);
    EXPECT_DOUBLE_EQ(band.target, log_gamma > 0 ? 7.0 - 1.5 / (1.5 * 1.5) : 7.0);
    EXPECT_DOUBLE_EQ(band.z, (band.mean - band.target) / band.standard_error);
    EXPECT_EQ(r.penalised, log_gamma > 0 ? 1 : 0);
    EXPECT_GE(r.worst_pair_z, std::abs(band.z));
  }
}

}  // namespace
}  // namespace shapeproc::evaluation
