// Saturated bands in the sampler's state (model/saturation.hpp): exact values on a row of points,
// and the incremental statistics and intensities against a recount after random births, deaths
// and moves.
#include "libshapeproc/model/saturation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/sample/configuration.hpp"
#include "tests/point_model.hpp"

namespace shapeproc::sample {
namespace {

// Points with one band [0, 1.5) of γ = 2, saturated at s, on a 20 x 20 window.
struct SaturatedPoints {
  model::ShapeProcessModel m;
  std::unique_ptr<model::Interaction> interaction;
  geometry::Scene space;
  std::unique_ptr<geometry::PairMeasurer> measurer;
  std::unique_ptr<Configuration> c;

  SaturatedPoints(int saturation, geometry::Boundary boundary = geometry::Boundary::open,
                  std::vector<double> thresholds = {0.0, 1.5}, std::vector<double> gammas = {2.0}) {
    m = testing::point_model(0.1, std::move(thresholds), std::move(gammas));
    m.interactions[0].axes[0].saturations.assign(m.interactions[0].axes[0].gammas.size(),
                                                 saturation);
    interaction = std::make_unique<model::Interaction>(m);
    space.window = geometry::Box3(Vec3(0, 0, 0), Vec3(20, 20, 0));
    space.categories.push_back({"points"});
    space.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
    const geometry::Domain domain(space.window, 2, boundary);
    measurer =
        std::make_unique<geometry::PairMeasurer>(space, m.measurement_options(domain.periodic()));
    c = std::make_unique<Configuration>(*interaction, *measurer, nullptr, domain,
                                        interaction->range());
  }
  // log λ(ξ | x) − log β.
  double log_lambda(const Vec3& p) const {
    std::vector<Link> links;
    return c->log_interaction({0, 0, p}, -1, links);
  }
  void add(const Vec3& p) {
    std::vector<Link> links;
    c->log_interaction({0, 0, p}, -1, links);
    c->add({0, 0, p}, 0.0, links);
  }
};

// Points at 0, 1 and 2 along a line: neighbours counts 1, 2, 1. With s = 1, S = 1 + 1 + 1 = 3.
// A point at 0.5 has 2 neighbours (capped to 1) and neither has room: S grows by 1. With s = 2,
// S = 1 + 2 + 1 = 4, and the point at 0.5 adds min(2, 2) + 1 (the point at 0 had room) = 3.
TEST(Saturation, ARowOfPointsCountsEachNeighbourUpToItsSaturation) {
  for (const auto& [s, statistic, change] :
       std::vector<std::tuple<int, double, int>>{{1, 3, 1}, {2, 4, 3}, {9, 4, 4}}) {
    SaturatedPoints points(s);
    for (double x : {5.0, 6.0, 7.0}) points.add(Vec3(x, 5, 0));
    EXPECT_EQ(points.c->statistics(), (std::vector<double>{3, statistic})) << "s = " << s;
    EXPECT_NEAR(points.log_lambda(Vec3(5.5, 5, 0)), change * std::log(2.0), 1e-12) << "s = " << s;
    // The element's own intensity from its links: the middle point, without itself, has the two
    // others of 0 neighbours each: min(s, 2) + 2.
    const int middle = 1;
    EXPECT_NEAR(points.c->log_lambda_over_beta(middle), (std::min(s, 2) + 2) * std::log(2.0),
                1e-12);
  }
}

TEST(Saturation, ChangeIsTheCappedOwnCountAndTheNeighboursWithRoom) {
  const model::ShapeProcessModel m = [] {
    model::ShapeProcessModel out = testing::point_model(0.1, {0.0, 1.0, 2.0}, {2.0, 0.5});
    out.interactions[0].axes[0].saturations = {2, 0};
    return out;
  }();
  const model::Interaction interaction(m);
  // Three neighbours in the saturated band (own counts 0, 1, 2), two in the pairwise one.
  const std::vector<std::pair<int, int>> neighbours{{0, 1}, {1, 1}, {2, 1}, {3, 2}, {4, 2}};
  const std::vector<int> own{0, 1, 2, 5, 5};
  const model::InteractionCounts counts = model::saturated_counts(
      interaction, neighbours, [&](int j, int) { return own[static_cast<std::size_t>(j)]; });
  EXPECT_EQ(counts.count_of(1), 2 + 2);  // min(2, 3) + two with fewer than 2
  EXPECT_EQ(counts.count_of(2), 2);      // pairwise: one per neighbour
}

// After random births, deaths and moves on a torus, the tracked statistics equal a recount, and
// Σ log λ over the births equals θ · t(x): the saturated sum telescopes as the density does.
TEST(Saturation, IncrementalStatisticsAndDensityAgreeWithARecount) {
  for (int s : {1, 2, 4}) {
    SaturatedPoints points(s, geometry::Boundary::torus, {0.0, 1.0, 2.5}, {3.0, 1.5});
    points.m.interactions[0].axes[0].saturations = {s, 0};
    points.interaction = std::make_unique<model::Interaction>(points.m);
    const geometry::Domain domain(points.space.window, 2, geometry::Boundary::torus);
    points.c = std::make_unique<Configuration>(*points.interaction, *points.measurer, nullptr,
                                               domain, points.interaction->range());
    core::Random random(7);
    double log_density = 0.0;
    std::vector<Link> links;
    for (int step = 0; step < 3000; ++step) {
      Configuration& c = *points.c;
      const double u = random.uniform();
      if (u < 0.5 || c.size() < 5) {
        const Element e{0, 0, Vec3(random.uniform(0, 20), random.uniform(0, 20), 0)};
        log_density += c.log_interaction(e, -1, links);
        c.add(e, 0.0, links);
      } else if (u < 0.8) {
        const int slot = c.slot_of_rank(random.index(static_cast<std::uint64_t>(c.size())));
        log_density -= c.log_lambda_over_beta(slot);
        c.remove(slot);
      } else {
        const int slot = c.slot_of_rank(random.index(static_cast<std::uint64_t>(c.size())));
        const Vec3 to = domain.wrap(c.at(slot).position + Vec3(random.uniform(-1, 1), 0.3, 0));
        const double before = c.log_lambda_over_beta(slot);
        const double after = c.log_interaction({0, 0, to}, slot, links);
        log_density += after - before;
        c.move(slot, to, 0.0, links);
        ASSERT_NEAR(c.log_lambda_over_beta(slot), after, 1e-9);
      }
    }
    const Configuration& c = *points.c;
    SaturatedPoints recount(s, geometry::Boundary::torus, {0.0, 1.0, 2.5}, {3.0, 1.5});
    recount.m = points.m;
    recount.interaction = std::make_unique<model::Interaction>(recount.m);
    recount.c = std::make_unique<Configuration>(*recount.interaction, *recount.measurer, nullptr,
                                                domain, recount.interaction->range());
    for (const Element& e : c.elements()) recount.add(e.position);
    EXPECT_EQ(c.statistics(), recount.c->statistics()) << "s = " << s;
    const std::vector<double>& t = c.statistics();
    EXPECT_NEAR(log_density, t[1] * std::log(3.0) + t[2] * std::log(1.5), 1e-6) << "s = " << s;
    EXPECT_GT(t[1], 0.0);
  }
}

}  // namespace
}  // namespace shapeproc::sample
