#include "libshapeproc/fit/saturation_choice.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tests/point_model.hpp"

namespace shapeproc::fit {
namespace {

geometry::Scene points_scene(const std::vector<geometry::Vec3>& positions, double side) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(side, side, 0));
  scene.category_index("points");
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  for (const geometry::Vec3& p : positions) scene.elements.push_back({0, 0, p});
  return scene;
}

// A row of three points 1 apart under one band [0, 1.5): own counts 1, 2, 1. The quantiles 0.5,
// 0.75, 0.9 and 1 of {1, 1, 2} round to 1, 2, 2 and 2: two distinct candidates, then none.
TEST(SaturationChoice, CandidatesAreQuantilesOfTheOwnCountsThenPairwise) {
  const geometry::Scene scene =
      points_scene({geometry::Vec3(5, 5, 0), geometry::Vec3(6, 5, 0), geometry::Vec3(7, 5, 0)}, 20);
  const model::ShapeProcessModel m = testing::point_model(0.01, {0.0, 1.5}, {2.0});
  const model::Interaction interaction(m);
  const geometry::PairMeasurer measurer(scene, m.measurement_options(false));
  const std::vector<std::vector<int>> candidates = saturation_candidates(
      measurer.all_pairs(scene.elements), scene, interaction, {1}, {0.5, 0.75, 0.9, 1.0});
  EXPECT_EQ(candidates, (std::vector<std::vector<int>>{{1}, {2}, {kPairwise}}));
}

// Fit, sample, refit: points under a saturated attraction (γ = 4 per neighbour within 3, s = 1:
// each point gains from its nearest partner only, so the pattern is pairs and not clumps) on a
// torus, after 10^6 steps (2·10^5 left seed 11's chain short of stationary, its γ 3.4 standard
// errors low). The fit prefers saturation to the pairwise model, and finds γ within three of its
// standard errors (seeds 11–13 all do).
TEST(SaturationChoice, ASaturatedPatternIsFittedSaturatedAndItsGammaRecovered) {
  model::ShapeProcessModel truth = testing::point_model(0.003, {0.0, 3.0}, {4.0});
  truth.interactions[0].axes[0].saturations = {1};
  const double side = 200;
  const geometry::Domain domain(
      geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(side, side, 0)), 2,
      geometry::Boundary::torus);
  sample::SamplerOptions sampling;
  sampling.iterations = 1000000;
  sampling.shift_radius = 3.0;
  core::Random random(11);
  const sample::SampleResult drawn =
      sample::ShapeProcessSampler(truth, domain, sampling).sample(random);
  ASSERT_GT(drawn.scene.elements.size(), 100u);
  geometry::Scene exemplar = points_scene({}, side);
  exemplar.elements = drawn.scene.elements;

  FitOptions options;
  options.thresholds = {0.0, 3.0};
  options.measurement.directions = 1;
  options.boundary = geometry::Boundary::torus;
  const FitResult fit = fit_shape_process(exemplar, options);
  const model::AxisParameters& axis = fit.model.interactions.at(0).axes.at(0);
  ASSERT_EQ(axis.saturation(0), 1);
  const double log_se = axis.gamma_standard_errors[0] / axis.gammas[0];
  EXPECT_LT(std::abs(std::log(axis.gammas[0]) - std::log(4.0)), 3 * log_se)
      << "gamma " << axis.gammas[0] << ", se of log gamma " << log_se;

  // Without attraction nothing is saturated.
  options.saturation = true;
  const FitResult poisson =
      fit_shape_process(points_scene({geometry::Vec3(10, 10, 0), geometry::Vec3(60, 150, 0),
                                      geometry::Vec3(120, 40, 0), geometry::Vec3(170, 170, 0)},
                                     side),
                        options);
  EXPECT_EQ(poisson.model.interactions.at(0).axes.at(0).saturation(0), 0);
}

}  // namespace
}  // namespace shapeproc::fit
