#include "libshapeproc/fit/density_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/random.hpp"
#include "tests/point_model.hpp"

namespace shapeproc::fit {
namespace {

// 100 uniform points in a 100 x 100 window: density 0.01.
geometry::Scene poisson_exemplar() { return testing::uniform_points({{"points", 100}}, 100, 7); }

TEST(DensityCalibration, APoissonModelsWrongIntensityIsCorrectedToTheExemplarsDensity) {
  model::ShapeProcessModel model = testing::point_model(0.004);
  CalibrationOptions options;
  options.seed = 3;
  const model::CalibrationRecord record = calibrate_density(model, poisson_exemplar(), options);
  // The first chain sees 0.4 of the density (400 expected, Poisson SE 20: ±0.05 is 1 SE);
  // then β × 2.5 brings it within the tolerance: 0.08, or two Monte Carlo standard errors of the
  // chain's mean count if wider.
  ASSERT_EQ(record.ratio_before.size(), 1u);
  EXPECT_NEAR(record.ratio_before[0], 0.4, 0.15);
  EXPECT_TRUE(record.converged);
  EXPECT_GE(record.rounds, 2);
  EXPECT_NEAR(record.ratio_after[0], 1.0, 0.1);
  // β: 0.01 within three Poisson standard errors of each of the two counts behind it.
  EXPECT_NEAR(model.categories[0].beta, 0.01, 0.01 * 3 * 2 * 0.05);
  EXPECT_FALSE(record.ran_away);
  EXPECT_DOUBLE_EQ(record.attraction_shrink, 1.0);
}

TEST(DensityCalibration, AModelThatAgreesIsLeftAlone) {
  model::ShapeProcessModel model = testing::point_model(0.01);
  const model::CalibrationRecord record = calibrate_density(model, poisson_exemplar(), {});
  EXPECT_TRUE(record.converged);
  EXPECT_EQ(record.rounds, 1);
  EXPECT_DOUBLE_EQ(model.categories[0].beta, 0.01);
  EXPECT_DOUBLE_EQ(record.beta_factor[0], 1.0);
}

// `bases` bases and `points` points in a 100 x 100 window, each category uniform.
geometry::Scene two_layer_exemplar(int bases, int points) {
  return testing::uniform_points({{"bases", bases}, {"points", points}}, 100, 11);
}

TEST(DensityCalibration, AFewBasesBelowManyPointsAreMeasuredOnTheirOwnLayersChain) {
  // Two layers: 40 bases expected on the torus of 2 x 2 windows, then 4,000 points. β of the
  // bases is 1.3 times the exemplar's density. Judged by one state, the bases' tolerance would be
  // two Poisson standard errors of 40, ±0.32, and ×1.3 would pass; the layer's own chain,
  // observed once per 40 of its steps, measures its mean count to a few per cent, so β is
  // corrected.
  model::ShapeProcessModel model = testing::point_model(0.001 * 1.3);
  model.categories.push_back({"points", 0.1});
  model.categories[1].layer = 1;
  CalibrationOptions options;
  options.seed = 5;
  const model::CalibrationRecord record =
      calibrate_density(model, two_layer_exemplar(10, 1000), options);
  ASSERT_EQ(record.ratio_before.size(), 2u);
  // 40 expected: one Poisson standard error of a state is 0.16; the time average's is smaller.
  EXPECT_NEAR(record.ratio_before[0], 1.3, 0.16);
  EXPECT_TRUE(record.converged);
  EXPECT_GE(record.rounds, 2);
  EXPECT_LT(record.beta_factor[0], 0.9);
  EXPECT_NEAR(record.ratio_after[0], 1.0, 0.1);
}

TEST(DensityCalibration, ErrorsOfBasesAndOfWhatTheyCarryThatCompoundAreCorrected) {
  // Points anchored within 1 of a base: each base carries about π r² β_points of them, so the
  // points' count follows the bases'. On the torus, 100 bases and 1,000 points are expected.
  // Bases at ×0.94 carrying ×0.94 per base agree each within the tolerance of 8%, but the points
  // come out at ×0.88 overall: both β step.
  const geometry::Scene exemplar = two_layer_exemplar(25, 250);
  const double bases = 25.0 / 1e4, reach = 1.0;
  const double covered = 1.0 - std::exp(-bases * M_PI * reach * reach);
  model::ShapeProcessModel model = testing::point_model(bases * 0.94);
  model.categories.push_back({"points", 250.0 / 1e4 / covered * 0.94});
  model.categories[1].layer = 1;
  model.categories[1].anchor = 0;
  model.categories[1].anchor_reach = reach;
  model::PairInteraction pair;
  pair.first = 0;
  pair.second = 1;
  model::AxisParameters axis;
  axis.thresholds = {0.0, reach};
  axis.gammas = {1.0};
  pair.axes = {axis};
  model.interactions = {pair};
  CalibrationOptions options;
  options.seed = 9;
  const model::CalibrationRecord record = calibrate_density(model, exemplar, options);
  EXPECT_TRUE(record.converged);
  EXPECT_GE(record.rounds, 2);
  EXPECT_GT(record.beta_factor[0] * record.beta_factor[1], 1.05);
}

TEST(DensityCalibration, ARunawayChainShrinksTheAttraction) {
  // Strong attraction and no hard core: the chain condenses far past 8 times the 400 expected.
  model::ShapeProcessModel model = testing::point_model(0.01, {0.0, 3.0}, {30.0});
  CalibrationOptions options;
  options.rounds = 2;
  const model::CalibrationRecord record = calibrate_density(model, poisson_exemplar(), options);
  EXPECT_TRUE(record.ran_away);
  EXPECT_LT(record.attraction_shrink, 1.0);
  EXPECT_LT(model.interactions[0].axes[0].gammas[0], 30.0);
  EXPECT_NEAR(std::log(model.interactions[0].axes[0].gammas[0]),
              record.attraction_shrink * std::log(30.0), 1e-9);
}

TEST(DensityCalibration, AShrunkAttractionLeavesTheBandsThatPlaceAnchoredElementsOnTheirBases) {
  // Bases that attract each other without a hard core run away; points anchored within 2 of a
  // base, with γ 5 on [0, 2) to it. The bases' attraction is shrunk; the anchor band is not.
  model::ShapeProcessModel model = testing::point_model(0.0025, {0.0, 3.0}, {30.0});
  model.categories.push_back({"points", 0.1});
  model.categories[1].layer = 1;
  model.categories[1].anchor = 0;
  model.categories[1].anchor_reach = 2.0;
  model::PairInteraction pair;
  pair.first = 0;
  pair.second = 1;
  model::AxisParameters axis;
  axis.thresholds = {0.0, 2.0};
  axis.gammas = {5.0};
  pair.axes = {axis};
  model.interactions.push_back(pair);
  EXPECT_TRUE(model.anchors(model.interactions[1]));
  EXPECT_FALSE(model.anchors(model.interactions[0]));
  CalibrationOptions options;
  options.rounds = 2;
  const model::CalibrationRecord record =
      calibrate_density(model, two_layer_exemplar(25, 250), options);
  EXPECT_TRUE(record.ran_away);
  EXPECT_LT(model.interactions[0].axes[0].gammas[0], 30.0);
  EXPECT_DOUBLE_EQ(model.interactions[1].axes[0].gammas[0], 5.0);
}

}  // namespace
}  // namespace shapeproc::fit
