#include "libshapeproc/fit/parameter_budget.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "tests/disc_scene.hpp"

namespace shapeproc::fit {
namespace {

using V = std::vector<double>;

TEST(ParameterBudget, RangeCapIsSpacingsOfTheDenserCategory) {
  ParameterBudget budget;
  budget.max_range_spacings = 2.5;
  EXPECT_DOUBLE_EQ(range_cap(budget, 10000.0, 2, 100.0), 25.0);  // spacing 10
  EXPECT_DOUBLE_EQ(range_cap(budget, 1000.0, 3, 1.0), 25.0);     // spacing 10
}

TEST(ParameterBudget, CapRangeCutsThresholdsAndDropsBandsBeyond) {
  V t = {1, 4, 9, 16};
  cap_range(t, 10);
  EXPECT_EQ(t, (V{1, 4, 9, 10}));
  t = {1, 4, 12, 16};
  cap_range(t, 10);
  EXPECT_EQ(t, (V{1, 4, 10}));
  t = {1, 4, 9};
  cap_range(t, 3);
  EXPECT_EQ(t, (V{1, 3}));
  t = {1, 4, 9};
  cap_range(t, 20);  // within the cap: unchanged
  EXPECT_EQ(t, (V{1, 4, 9}));
  t = {12, 14};
  cap_range(t, 10);  // the hard core beyond the cap: a hard core alone
  EXPECT_EQ(t, (V{12}));
}

TEST(ParameterBudget, KeepBandsKeepsContactThenRangeThenNearest) {
  V t = {-5, -2, 0, 3, 8};
  keep_bands(t, 3);
  EXPECT_EQ(t, (V{-5, -2, 0, 8}));
  t = {-5, -2, 0, 3, 8};
  keep_bands(t, 2);
  EXPECT_EQ(t, (V{-5, 0, 8}));
  t = {-5, -2, 0, 3, 8};
  keep_bands(t, 1);  // the split at contact alone, ending a hair beyond it
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0], -5);
  EXPECT_GT(t[1], 0);
  EXPECT_LT(t[1], 1e-6);
  t = {1, 4, 9};
  keep_bands(t, 1);
  EXPECT_EQ(t, (V{1, 9}));
  keep_bands(t, 0);
  EXPECT_EQ(t, (V{1}));
}

TEST(ParameterBudget, ApplyBudgetPoolsAxesOnlyWhenTheyNeedMore) {
  const std::vector<V> axes = {{1, 2, 3}, {1, 2, 3}};  // 4 γ along every axis
  PairThresholds kept = apply_budget(axes, {1, 2, 3}, 4, "8 elements of 'a'");
  EXPECT_EQ(kept.axes.size(), 2u);
  EXPECT_TRUE(kept.choice.empty());
  PairThresholds pooled = apply_budget(axes, {1, 2, 3}, 3, "8 elements of 'a'");
  ASSERT_EQ(pooled.axes.size(), 1u);
  EXPECT_EQ(pooled.axes[0], (V{1, 2, 3}));
  EXPECT_NE(pooled.choice.find("isotropic, 2 of 2 band(s)"), std::string::npos) << pooled.choice;
  PairThresholds none = apply_budget(axes, {1, 2, 3}, 0, "3 elements of 'a'");
  EXPECT_EQ(none.axes[0], (V{1}));
  EXPECT_NE(none.choice.find("hard core only"), std::string::npos) << none.choice;
}

using testing::add_disc;

// Ten large discs, each holding a small one and with another straddling its rim: a drawing of
// nested and overlapping elements, which the fit takes (no refusal) with negative hard cores.
geometry::Scene nested_discs() {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(500, 200, 0));
  scene.category_index("base");
  scene.category_index("dot");
  for (int k = 0; k < 10; ++k) {
    const double x = 25 + 50 * (k % 10), y = k % 2 ? 60 : 140;
    add_disc(scene, x, y, 18, 0);
    add_disc(scene, x + 3, y - 2, 3, 1);   // inside
    add_disc(scene, x + 18, y + 1, 3, 1);  // on the rim
  }
  return scene;
}

TEST(ParameterBudget, ANestedDrawingFitsWithHardCoresBelowItsDeepestOverlap) {
  const geometry::Scene scene = nested_discs();
  FitOptions options;
  const FitResult fit = fit_shape_process(scene, options);
  const model::ShapeProcessModel& m = fit.model;
  const int pair = m.interaction_index(0, 1);
  ASSERT_GE(pair, 0);
  const model::PairInteraction& bd = m.interactions[static_cast<std::size_t>(pair)];
  // Dots nest about 17 deep in bases (a dot of radius 3 at 3.6 from the centre of a base of 18
  // overlaps it by 18 − 3.6 + 3 = 17.4, less the proxies' chords): every axis's hard core lies
  // below that, and its bands reach past contact.
  for (const model::AxisParameters& axis : bd.axes) {
    EXPECT_LT(axis.thresholds.front(), -16.0);
    EXPECT_GT(axis.thresholds.back(), 0.0);
  }
  // The bases' own 45 pairs put 17 within the range: 3 γ, fewer than its 4 axes need, so one
  // isotropic axis.
  const model::PairInteraction& bases =
      m.interactions[static_cast<std::size_t>(m.interaction_index(0, 0))];
  ASSERT_TRUE(bases.isotropic());
  EXPECT_EQ(bases.axes[0].thresholds.size(), 2u);
  EXPECT_NE(bases.choice.find("17 exemplar pairs within its range carry 3 γ"), std::string::npos)
      << bases.choice;
  // The pairs the drawing never overlaps keep their hard cores at or above 0.
  for (const model::PairInteraction& p : m.interactions)
    if (&p != &bd) EXPECT_GE(p.axes[0].thresholds.front(), 0.0);
  const model::Interaction interaction(m);
  EXPECT_EQ(interaction.band(0, 1, 0, -30.0), model::Interaction::kHardCore);
  EXPECT_GE(interaction.band(0, 1, 0, -10.0), 0);
  EXPECT_EQ(interaction.band(0, 0, 0, 100.0), model::Interaction::kBeyond);
}

// The Wald pruning on log γ: strengths within 2 standard errors of 1 leave the pair its hard
// core alone, one isotropic axis at the smallest of its axes' hard cores; a strength 4 standard
// errors off keeps every band; so does a flat estimate, whose standard error says nothing.
TEST(ParameterBudget, PruneNeutralPairsOnlyOnEvidence) {
  const auto axis = [](double d0, std::vector<double> gammas, double log_se) {
    model::AxisParameters a;
    a.thresholds = {d0};
    for (std::size_t k = 0; k < gammas.size(); ++k) {
      a.thresholds.push_back(d0 + 10.0 * static_cast<double>(k + 1));
      a.gamma_standard_errors.push_back(log_se * gammas[k]);
      a.status.push_back(model::ParameterStatus::free);
      a.observed_pairs.push_back(20);
    }
    a.gammas = std::move(gammas);
    return a;
  };
  model::ShapeProcessModel m;
  m.categories = {{"a"}, {"b"}};
  const auto pair = [](int first, int second, std::vector<model::AxisParameters> axes) {
    model::PairInteraction p;
    p.first = first;
    p.second = second;
    p.axes = std::move(axes);
    return p;
  };
  m.interactions = {pair(0, 0, {axis(5, {1.1, 0.9}, 0.1), axis(4, {1.0, 1.15}, 0.1)}),
                    pair(0, 1, {axis(5, {1.5, 1.0}, 0.1)}),
                    pair(1, 1, {axis(5, {1.0, 1.0}, 1e15)})};
  const std::vector<std::string> notes = prune_neutral_pairs(m);
  ASSERT_EQ(notes.size(), 1u);
  const model::PairInteraction& neutral = m.interactions[0];
  ASSERT_EQ(neutral.axes.size(), 1u);
  EXPECT_EQ(neutral.axes[0].thresholds, std::vector<double>{4.0});
  EXPECT_TRUE(neutral.axes[0].gammas.empty());
  EXPECT_NE(neutral.choice.find("hard core only"), std::string::npos);
  EXPECT_EQ(m.interactions[1].axes[0].gammas.size(), 2u);  // |log 1.5| = 4.05 standard errors
  EXPECT_EQ(m.interactions[2].axes[0].gammas.size(), 2u);  // no information
  EXPECT_TRUE(m.interactions[2].choice.empty());
}

// 400 points on a jittered grid of spacing 5 in a 100 x 100 window: the 20% quantile of every
// pair's distance (about 45) lies far past the range cap (2.5 spacings, 12.5), so the bands come
// from the pairs within the cap and divide it, rather than one band from the hard core to it.
TEST(ParameterBudget, BandsOfAManyElementExemplarDivideTheCappedRange) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(100, 100, 0));
  scene.category_index("points");
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  core::Random random(5);
  for (int k = 0; k < 400; ++k) {
    geometry::Element e;
    e.position = geometry::Vec3(2.5 + 5 * (k % 20) + random.uniform(-1.5, 1.5),
                                2.5 + 5 * (k / 20) + random.uniform(-1.5, 1.5), 0);
    scene.elements.push_back(e);
  }
  const FitResult fit = fit_shape_process(scene, FitOptions{});
  ASSERT_EQ(fit.model.interactions.size(), 1u);
  for (const model::AxisParameters& axis : fit.model.interactions[0].axes) {
    EXPECT_GE(axis.thresholds.size(), 3u);  // a hard core and two bands at least
    EXPECT_LT(axis.thresholds.back(), 12.5 + 1e-9);
    EXPECT_LT(axis.thresholds[1], 7.0);  // the first band ends within about one spacing
  }
}

}  // namespace
}  // namespace shapeproc::fit
