#include "libshapeproc/fit/independent_marks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "tests/thomas_pattern.hpp"

namespace shapeproc::fit {
namespace {

using geometry::Vec3;

// Three categories of 1, 2 and 3 points, and a point model of one pooled category, anchored to a
// second (hidden) one.
geometry::Scene marked_exemplar() {
  geometry::Scene scene;
  scene.window = geometry::Box3(Vec3(0, 0, 0), Vec3(10, 10, 0));
  for (const char* name : {"a", "b", "c"}) scene.category_index(name);
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  for (int c : {0, 1, 1, 2, 2, 2}) scene.elements.push_back({0, c, Vec3(c, 2 * c, 0)});
  return scene;
}

model::ShapeProcessModel pooled_model() {
  model::ShapeProcessModel m;
  m.categories.resize(2);
  m.categories[0].name = "pooled";
  m.categories[0].beta = 0.6;
  m.categories[0].beta_standard_error = 0.06;
  m.categories[0].layer = 1;
  m.categories[0].anchor = 1;
  m.categories[0].anchor_reach = 4.0;
  m.categories[1].name = "centre";
  m.categories[1].beta = 0.01;
  m.categories[1].hidden = true;
  const auto pair = [](int a, int b, double gamma) {
    model::PairInteraction p;
    p.first = a;
    p.second = b;
    model::AxisParameters axis;
    axis.thresholds = {0.5, 3.0};
    axis.gammas = {gamma};
    axis.gamma_standard_errors = {0.1};
    axis.status = {model::ParameterStatus::free};
    p.axes = {axis};
    return p;
  };
  m.interactions = {pair(0, 0, 0.5), pair(0, 1, 4.0), pair(1, 1, 0.2)};
  m.neighbour_offsets.radii = {0.5};
  m.neighbour_offsets.offsets = {{0, 0, Vec3(1, 0, 0), 1.0}, {1, 0, Vec3(0, 1, 0), 2.0}};
  return m;
}

// Exact values on a tiny case: β in the categories' shares (1/6, 2/6, 3/6 of 0.6), the anchor
// moved to the centres' new index, every pair of categories the pooled pair, each category's pair
// with the centres the pooled one's, and the offsets towards a category weighted by its share.
TEST(IndependentMarks, SplitsBetaByShareAndCopiesThePairs) {
  model::ShapeProcessModel m = pooled_model();
  split_into_marks(m, 0, marked_exemplar());
  ASSERT_EQ(m.categories.size(), 4u);
  const double betas[] = {0.1, 0.2, 0.3};
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(m.categories[c].name, std::string(1, static_cast<char>('a' + c)));
    EXPECT_NEAR(m.categories[c].beta, betas[c], 1e-15);
    EXPECT_NEAR(m.categories[c].beta_standard_error, betas[c] / 10, 1e-15);
    EXPECT_EQ(m.categories[c].anchor, 3);
    EXPECT_EQ(m.categories[c].layer, 1);
    EXPECT_EQ(m.categories[c].anchor_reach, 4.0);
  }
  EXPECT_EQ(m.categories[3].name, "centre");
  EXPECT_TRUE(m.categories[3].hidden);
  EXPECT_EQ(m.categories[3].anchor, -1);
  // 6 pairs among a, b, c; 3 with the centres; the centres' own.
  ASSERT_EQ(m.interactions.size(), 10u);
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      const int k = m.interaction_index(a, b);
      ASSERT_GE(k, 0) << a << "-" << b;
      const double want = b < 3 ? 0.5 : (a < 3 ? 4.0 : 0.2);
      EXPECT_EQ(m.interactions[static_cast<std::size_t>(k)].axes[0].gammas[0], want);
      EXPECT_EQ(m.interactions[static_cast<std::size_t>(k)].choice.find("independent marks") !=
                    std::string::npos,
                a < 3);
    }
  model::validate(m);
  // Offsets: pooled→pooled becomes 9 (weights 1/6, 2/6, 3/6 by target), centre→pooled 3.
  ASSERT_EQ(m.neighbour_offsets.offsets.size(), 12u);
  double towards_c = 0.0;
  for (const model::NeighbourOffset& o : m.neighbour_offsets.offsets)
    if (o.to == 2) towards_c += o.weight;
  EXPECT_NEAR(towards_c, 3 * 0.5 + 2.0 * 0.5, 1e-12);
}

TEST(IndependentMarks, RefusesShapesAndCategoriesOutOfRange) {
  model::ShapeProcessModel m = pooled_model();
  EXPECT_THROW(split_into_marks(m, 2, marked_exemplar()), std::invalid_argument);
  m.shapes.push_back({geometry::Shape{geometry::PointShape{}, "point"}, 0, -1});
  EXPECT_THROW(split_into_marks(m, 0, marked_exemplar()), std::invalid_argument);
}

TEST(IndependentMarks, PoolingKeepsElementsInOneCategory) {
  const geometry::Scene pooled = pool_categories(marked_exemplar());
  ASSERT_EQ(pooled.categories.size(), 1u);
  EXPECT_EQ(pooled.categories[0].name, "a+b+c");
  ASSERT_EQ(pooled.elements.size(), 6u);
  for (const geometry::Element& e : pooled.elements) EXPECT_EQ(e.category, 0);
}

// 10 groups of 12 points (Thomas, σ 2) in 3 categories, drawn at random in shares 1/6, 1/3, 1/2:
// the fit pools them around hidden centres, and an output's categories keep their shares. On a
// torus of 4 windows the count of category c is about 40 n_c; its share of the output is checked
// within 4 binomial standard errors of the exemplar's (the clusters make the total vary, not the
// shares).
TEST(IndependentMarks, AClusteredExemplarOfSeveralCategoriesKeepsTheirShares) {
  const geometry::Scene exemplar =
      testing::thomas_pattern(7, {"a", "b", "c"}, {1.0 / 6, 1.0 / 3, 1.0 / 2});
  const ExemplarFit fit = testing::fit_by_pseudo_likelihood(exemplar);
  const model::ShapeProcessModel& m = fit.result.model;
  ASSERT_EQ(m.categories.size(), 4u);
  EXPECT_TRUE(m.categories[3].hidden);
  EXPECT_EQ(m.fit->elements, static_cast<long long>(exemplar.elements.size()));
  const std::vector<std::size_t> counts = geometry::category_counts(exemplar);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(m.categories[c].anchor, 3);
  const geometry::Domain domain(geometry::Box3(Vec3(0, 0, 0), Vec3(200, 200, 0)), 2,
                                geometry::Boundary::torus);
  core::Random chain(3);
  const sample::SampleResult out = output_sampler(m, domain).sample(chain);
  const std::vector<std::size_t> got = geometry::category_counts(out.scene);
  const double n = static_cast<double>(out.scene.elements.size());
  ASSERT_GT(n, 200.0);
  for (int c = 0; c < 3; ++c) {
    const double p = static_cast<double>(counts[c]) / static_cast<double>(exemplar.elements.size());
    EXPECT_NEAR(static_cast<double>(got[c]) / n, p, 4 * std::sqrt(p * (1 - p) / n)) << c;
  }
}

}  // namespace
}  // namespace shapeproc::fit
