// Verdicts on hand-made outputs whose faults are known: twice the density, a shape mix moved
// from 25/25/25/25 to 100/0/0/0, a lattice turned into a random scatter.
#include "libshapeproc/evaluation/verdicts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "libshapeproc/core/random.hpp"
#include "tests/methods/method_scenes.hpp"

namespace shapeproc::evaluation {
namespace {

using geometry::Boundary;
using geometry::Vec3;

// An n x n lattice of spacing a in a window of side `side`, its squares of sides 2, 3, 4 and 5
// taken in turn (or all of side 2 with `smallest_only`), or at random positions with `scatter`.
geometry::Scene squares(int n, double a, double side, bool smallest_only = false,
                        bool scatter = false) {
  geometry::Scene scene;
  scene.window = geometry::Box3(Vec3(0, 0, 0), Vec3(side, side, 0));
  scene.categories = {{"a"}};
  for (const double s : {2.0, 3.0, 4.0, 5.0}) scene.shapes.push_back(testing::rectangle(s, s));
  core::Random random(11);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int shape = smallest_only ? 0 : (i + j * n) % 4;
      const Vec3 p = scatter ? Vec3(random.uniform(0, side), random.uniform(0, side), 0)
                             : Vec3((i + 0.5) * a, (j + 0.5) * a, 0);
      scene.elements.push_back({shape, 0, p});
    }
  return scene;
}

struct Judgement {
  std::vector<Verdict> verdicts;
  std::string line;
  const Verdict& operator[](const std::string& metric) const {
    for (const Verdict& v : verdicts)
      if (v.metric == metric) return v;
    throw std::out_of_range(metric);
  }
};

// A model of category "a" measured between centres in one direction: hard core below 0, bands
// [0, 8) and [8, 12), so that a lattice of spacing 10 has 2 pairs per element in the second.
model::ShapeProcessModel banded_model() {
  model::ShapeProcessModel m;
  m.categories.push_back({"a", 0.01});
  m.measurement.distance = geometry::DistanceKind::centroid;
  m.measurement.directions = 1;
  model::PairInteraction pair;
  model::AxisParameters axis;
  axis.thresholds = {0.0, 8.0, 12.0};
  axis.gammas = {1.0, 1.0};
  pair.axes = {axis};
  m.interactions = {pair};
  return m;
}

Judgement judge_against(const geometry::Scene& exemplar, const geometry::Scene& output,
                        const model::ShapeProcessModel* model = nullptr) {
  metrics::StatisticsOptions options;
  options.measurement.periodic = true;
  const metrics::SceneStatistics ex =
      metrics::compute_statistics(exemplar, options, core::Random(1));
  options.range = ex.range;
  const metrics::SceneStatistics out =
      metrics::compute_statistics(output, options, core::Random(1));
  const metrics::Comparison comparison = metrics::compare(out, ex);
  const Judged judged = measure_for_verdicts(exemplar, Boundary::torus, ex, output, Boundary::torus,
                                             out, comparison, nullptr, model);
  Judgement j;
  j.verdicts = judge(judged);
  j.line = summary(j.verdicts);
  return j;
}

// The exemplar is faithful to itself in every statistic, and a copy: novelty alone fails (its
// squares of four sizes in turn are no lattice of one element per cell).
TEST(Verdicts, TheExemplarItselfPassesEveryCheckButNovelty) {
  const geometry::Scene exemplar = squares(20, 10.0, 200.0);
  const Judgement j = judge_against(exemplar, exemplar);
  for (const Verdict& v : j.verdicts) {
    if (v.metric != "novelty") {
      EXPECT_NE(v.outcome, Outcome::fail) << v.metric << " " << v.shown;
    }
  }
  EXPECT_EQ(j["novelty"].outcome, Outcome::fail);
  EXPECT_EQ(j["novelty"].problem, "repeats the exemplar");
  EXPECT_DOUBLE_EQ(j["novelty"].value, 1.0);
  EXPECT_EQ(j.line.rfind("fails 1 of 7 checks: novelty", 0), 0u) << j.line;
  EXPECT_DOUBLE_EQ(j["density"].value, 1.0);
  EXPECT_NEAR(j["shape mix"].value, 1.0, 1e-12);  // 100 of each: χ² = 0
  EXPECT_NEAR(j["order"].value, 1.0, 1e-9);
}

TEST(Verdicts, TwiceTheDensityIsTooDense) {
  // 28 x 28 squares at spacing 200/28 in the same window: ×1.96.
  const Judgement j = judge_against(squares(20, 10.0, 200.0), squares(28, 200.0 / 28, 200.0));
  EXPECT_NEAR(j["density"].value, 784.0 / 400.0, 1e-12);
  EXPECT_EQ(j["density"].outcome, Outcome::fail);
  EXPECT_EQ(j["density"].problem, "too dense");
  EXPECT_EQ(j["order"].outcome, Outcome::pass);  // still a lattice
  EXPECT_NE(j.line.find("density ×1.96 (wanted ×0.8 to ×1.25): too dense"), std::string::npos)
      << j.line;
}

TEST(Verdicts, AShapeMixMovedToOneShapeFailsItsChiSquare) {
  // 400 elements all of the smallest class against shares of 1/4: χ² = 3 · 100 + 300²/100 = 1200.
  const Judgement j = judge_against(squares(20, 10.0, 200.0), squares(20, 10.0, 200.0, true));
  EXPECT_EQ(j["shape mix"].outcome, Outcome::fail);
  EXPECT_LT(j["shape mix"].value, 1e-100);
  EXPECT_NE(j["shape mix"].shown.find("100% against 25%"), std::string::npos)
      << j["shape mix"].shown;
  EXPECT_EQ(j["density"].outcome, Outcome::pass);
}

TEST(Verdicts, ALatticeTurnedIntoAScatterLosesItsOrder) {
  const Judgement j =
      judge_against(squares(20, 10.0, 200.0), squares(20, 10.0, 200.0, false, true));
  EXPECT_EQ(j["order"].outcome, Outcome::fail);
  EXPECT_EQ(j["order"].problem, "loses the exemplar's lattice");
  EXPECT_LT(j["order"].value, 0.2);
  EXPECT_EQ(j["density"].outcome, Outcome::pass);
  // A random scatter of squares at this density overlaps, and its spacing spreads.
  EXPECT_EQ(j["overlaps"].outcome, Outcome::fail);
  EXPECT_EQ(j.line.rfind("fails ", 0), 0u) << j.line;
}

// `n` squares of sides 6, 10 and 14 at random in a torus of side `side`, their centres at least
// `core` apart (random sequential adsorption; 0: a Poisson scatter).
geometry::Scene hard_core(int n, double side, double core, std::uint64_t seed) {
  geometry::Scene scene;
  scene.window = geometry::Box3(Vec3(0, 0, 0), Vec3(side, side, 0));
  scene.categories = {{"a"}};
  for (const double a : {6.0, 10.0, 14.0}) scene.shapes.push_back(testing::rectangle(a, a));
  core::Random random(seed);
  while (static_cast<int>(scene.elements.size()) < n) {
    const Vec3 p(random.uniform(0, side), random.uniform(0, side), 0);
    bool clear = true;
    for (const geometry::Element& e : scene.elements) {
      Vec3 d = (p - e.position).cwiseAbs();
      d.x() = std::min(d.x(), side - d.x());
      d.y() = std::min(d.y(), side - d.y());
      clear = clear && d.norm() >= core;
    }
    if (clear) scene.elements.push_back({static_cast<int>(random.index(3)), 0, p});
  }
  return scene;
}

// A small exemplar's nearest distances vary by chance more than the floor of 0.15 allows: a piece
// of 34 elements of a hard-core process against an output of four times its area from the same
// process stands at W1 0.09–0.23. The check compares W1 with what two samples of those sizes from
// one distribution exceed 1% of the time: 10 of 10 such outputs pass, and a Poisson scatter of
// the same density, whose nearest distances fall to 0, fails.
TEST(Verdicts, SpacingAllowsWhatChanceGivesSmallSamples) {
  const geometry::Scene exemplar = hard_core(34, 220.0, 19.0, 1);
  int passed = 0, above_floor = 0;
  for (std::uint64_t seed = 2; seed < 12; ++seed) {
    const Judgement j = judge_against(exemplar, hard_core(136, 440.0, 19.0, seed));
    passed += j["spacing"].outcome == Outcome::pass;
    above_floor += j["spacing"].value > 0.15;
    EXPECT_NE(j["spacing"].rule.find("the 1% chance level of"), std::string::npos)
        << j["spacing"].rule;
  }
  EXPECT_EQ(passed, 10);
  EXPECT_EQ(above_floor, 2);  // W1 0.17 and 0.23: the floor alone would fail them
  const Judgement scatter = judge_against(exemplar, hard_core(136, 440.0, 0.0, 2));
  EXPECT_EQ(scatter["spacing"].outcome, Outcome::fail) << scatter["spacing"].shown;
}

TEST(Verdicts, TheModelsPairCountsPerBandAgainstTheExemplars) {
  const model::ShapeProcessModel m = banded_model();
  // The exemplar against itself: every band's rate equal, z = 0.
  const Judgement same = judge_against(squares(20, 10.0, 200.0), squares(20, 10.0, 200.0), &m);
  EXPECT_EQ(same["model statistics"].outcome, Outcome::pass);
  EXPECT_DOUBLE_EQ(same["model statistics"].value, 0.0);
  // Spacing 200/28: 2 pairs per element at 7.1 (band 1, none in the exemplar) and 2 at 10.1.
  const Judgement dense =
      judge_against(squares(20, 10.0, 200.0), squares(28, 200.0 / 28, 200.0), &m);
  const Verdict& v = dense["model statistics"];
  EXPECT_EQ(v.outcome, Outcome::fail);
  EXPECT_NE(v.shown.find("pairs 0, axis 0, band 1: 2.00 against 0.00"), std::string::npos)
      << v.shown;
  // 1568 pairs against at least one: z = 2 / √(1/400² + 1568/784²) ≈ 2 / 0.051, far beyond.
  EXPECT_GT(v.value, 20.0);
  EXPECT_NE(v.rule.find("1% over 2 bands"), std::string::npos) << v.rule;
  // Without a model there is no such check.
  EXPECT_THROW(
      judge_against(squares(20, 10.0, 200.0), squares(20, 10.0, 200.0))["model statistics"],
      std::out_of_range);
}

}  // namespace
}  // namespace shapeproc::evaluation
