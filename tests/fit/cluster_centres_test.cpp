#include "libshapeproc/fit/cluster_centres.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "tests/thomas_pattern.hpp"

namespace shapeproc::fit {
namespace {

using geometry::Vec3;

geometry::Scene points_on(const std::vector<Vec3>& positions) {
  geometry::Scene scene;
  scene.window = geometry::Box3(Vec3(0, 0, 0), Vec3(100, 100, 0));
  scene.category_index("point");
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  for (const Vec3& p : positions) scene.elements.push_back({0, 0, p});
  return scene;
}

geometry::Scene thomas(std::uint64_t seed) { return testing::thomas_pattern(seed); }

// The Thomas fit finds the clusters of Thomas patterns (3 seeds). Parents that fall close
// together make, to any estimator, one larger cluster (seed 2: σ 3.5 and 5 centres), so the bounds
// are wide: σ within a factor of 2 of 2, and 5 to 15 centres. Uniform points (3 seeds) and a grid
// are not clustered.
TEST(ClusterCentres, ThomasPatternsAreClusteredAndRandomOrRegularOnesAreNot) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const ClusterFit fit = find_clusters(thomas(seed), false);
    EXPECT_TRUE(fit.clustered) << fit.note;
    EXPECT_GE(fit.centres.size(), 5u) << fit.note;
    EXPECT_LE(fit.centres.size(), 15u) << fit.note;
    EXPECT_GT(fit.sigma, 2.0 / 2) << fit.note;
    EXPECT_LT(fit.sigma, 2.0 * 2) << fit.note;
    core::Random random(seed);
    std::vector<Vec3> uniform;
    for (int k = 0; k < 120; ++k)
      uniform.emplace_back(random.uniform(0, 100), random.uniform(0, 100), 0);
    EXPECT_FALSE(find_clusters(points_on(uniform), false).clustered) << "seed " << seed;
  }
  std::vector<Vec3> grid;
  for (int i = 0; i < 11; ++i)
    for (int j = 0; j < 11; ++j) grid.emplace_back(5 + 9 * i, 5 + 9 * j, 0);
  EXPECT_FALSE(find_clusters(points_on(grid), false).clustered);
}

// The fitted model places the centres as a hidden category below the points, which are anchored
// to them; an output draws the points only, and they lie in clusters: their mean nearest
// neighbour is within 1.5 times the exemplar's, where uniform points of the same density would
// lie 2.5 times as far (0.5 / √density against about 1.6).
TEST(ClusterCentres, AClusteredExemplarIsSampledAroundHiddenCentres) {
  const geometry::Scene exemplar = thomas(4);
  const ExemplarFit fit = testing::fit_by_pseudo_likelihood(exemplar);
  const model::ShapeProcessModel& m = fit.result.model;
  ASSERT_EQ(m.categories.size(), 2u);
  EXPECT_TRUE(m.categories[1].hidden);
  EXPECT_EQ(m.categories[0].anchor, 1);
  EXPECT_EQ(m.categories[0].layer, 1);
  const geometry::Domain domain(geometry::Box3(Vec3(0, 0, 0), Vec3(200, 200, 0)), 2,
                                geometry::Boundary::torus);
  core::Random random(5);
  const sample::SampleResult out = output_sampler(m, domain).sample(random);
  ASSERT_GT(out.scene.elements.size(), 100u);
  EXPECT_FALSE(out.hidden.empty());
  const auto mean_nearest = [](const std::vector<geometry::Element>& elements, double side) {
    double total = 0.0;
    for (const geometry::Element& a : elements) {
      double nearest = 1e9;
      for (const geometry::Element& b : elements) {
        if (&a == &b) continue;
        const Vec3 d = geometry::minimum_image(b.position - a.position, Vec3(side, side, 0));
        nearest = std::min(nearest, d.norm());
      }
      total += nearest;
    }
    return total / static_cast<double>(elements.size());
  };
  for (const geometry::Element& e : out.scene.elements) EXPECT_EQ(e.category, 0);
  EXPECT_LT(mean_nearest(out.scene.elements, 200), 1.5 * mean_nearest(exemplar.elements, 1e9));
}

// Two tight groups of six points: clustered, but too few points to bound the points' bands around
// two centres (the pseudo-likelihood has no finite maximum and the chains run away). The fit
// falls back to the model without centres, and says so.
TEST(ClusterCentres, CentresThatRunAwayAreDropped) {
  core::Random random(1);
  std::vector<Vec3> points;
  for (const Vec3& centre : {Vec3(20, 20, 0), Vec3(80, 70, 0)})
    for (int k = 0; k < 6; ++k) {
      const double r = std::sqrt(-2 * std::log(1 - random.uniform()));
      const double a = 2 * 3.14159265358979 * random.uniform();
      points.push_back(centre + Vec3(r * std::cos(a), r * std::sin(a), 0));
    }
  const geometry::Scene exemplar = points_on(points);
  ASSERT_TRUE(find_clusters(exemplar, false).clustered);
  const ExemplarFit fit = testing::fit_by_pseudo_likelihood(exemplar);
  ASSERT_EQ(fit.result.model.categories.size(), 1u);
  EXPECT_FALSE(fit.result.model.categories[0].hidden);
  const std::vector<std::string>& notes = fit.result.model.fit->notes;
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.find("fitted without them") != std::string::npos;
  }));
}

}  // namespace
}  // namespace shapeproc::fit
