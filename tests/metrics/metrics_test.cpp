// Metrics on configurations whose answers are known: overlapping squares, lattices, Poisson
// patterns (G(r) = 1 − exp(−λπr²), g(r) = 1), and the neighbourhood distance of a stretched
// lattice.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/io/svg_reader.hpp"
#include "libshapeproc/metrics/neighbourhood_distance.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "tests/metrics/metric_scenes.hpp"

namespace shapeproc::metrics {
namespace {

// These scenes stand for placements that may overlap: each drawable is one element (visual
// reading would join overlapping ones).
io::ReaderOptions each_drawable() {
  io::ReaderOptions options;
  options.elements = io::ElementRule::paths;
  return options;
}

using geometry::Vec3;
using testing::lattice;
using testing::point_scene;
using testing::poisson;

StatisticsOptions torus(double range) {
  StatisticsOptions o;
  o.measurement.periodic = true;
  o.range = range;
  return o;
}

TEST(Wasserstein, PointMassesAndMixtures) {
  Distribution a{{1.0}, {1.0}, 1}, b{{3.0}, {1.0}, 1};
  EXPECT_DOUBLE_EQ(wasserstein1(a, b), 2.0);
  Distribution c{{1.0, 3.0}, {0.5, 0.5}, 2};
  EXPECT_DOUBLE_EQ(wasserstein1(a, c), 1.0);
  EXPECT_DOUBLE_EQ(wasserstein1(c, c), 0.0);
}

TEST(CensoredDistribution, HanischWeightsOnAHandMadeCase) {
  // Values 1, 2, 5 with borders 10, 1.5, 10: the second is censored (2 > 1.5). At t = 1 three
  // elements are at risk, at t = 5 two: weights 1/3 and 1/2, normalised to 0.4 and 0.6.
  const Distribution d = censored_distribution({1.0, 2.0, 5.0}, {10.0, 1.5, 10.0}, 8.0);
  ASSERT_EQ(d.values.size(), 2u);
  EXPECT_DOUBLE_EQ(d.values[0], 1.0);
  EXPECT_DOUBLE_EQ(d.values[1], 5.0);
  EXPECT_NEAR(d.weights[0], 0.4, 1e-12);
  EXPECT_NEAR(d.weights[1], 0.6, 1e-12);
  // Truncation: a value above the range counts at the range.
  const Distribution t = censored_distribution({1.0, 20.0}, {100.0, 100.0}, 8.0);
  EXPECT_DOUBLE_EQ(t.values[1], 8.0);
}

TEST(Collisions, TwoOverlappingSquaresAndOneApart) {
  const std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
    <rect x="10" y="10" width="20" height="20"/><rect x="25" y="25" width="20" height="20"/>
    <rect x="70" y="70" width="20" height="20"/></svg>)";
  const geometry::Scene scene = io::parse_svg(svg, "squares.svg", each_drawable());
  const SceneStatistics s = compute_statistics(scene, StatisticsOptions{}, core::Random(1));
  ASSERT_EQ(s.collisions.pairs.size(), 1u);
  EXPECT_EQ(s.collisions.elements, 2);
  EXPECT_EQ(std::count(s.collisions.colliding.begin(), s.collisions.colliding.end(), true), 2);
  EXPECT_FALSE(s.collisions.colliding[2]);
  EXPECT_DOUBLE_EQ(s.intensity.at(0), 3.0 / 10000.0);
}

TEST(Collisions, NestedShapesOverlapTouchingOnesAreCountedApart) {
  const std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
    <rect x="10" y="10" width="40" height="40"/><rect x="20" y="20" width="10" height="10"/>
    <rect x="60" y="10" width="10" height="10"/><rect x="70" y="10" width="10" height="10"/>
    <rect x="60" y="60" width="10" height="10"/><rect x="71" y="60" width="10" height="10"/></svg>)";
  const SceneStatistics s = compute_statistics(io::parse_svg(svg, "nested.svg", each_drawable()),
                                               StatisticsOptions{}, core::Random(1));
  EXPECT_EQ(s.collisions.pairs.size(), 1u);     // nested: overlapping
  EXPECT_EQ(s.collisions.touching.size(), 1u);  // sharing an edge; the last two are 1 apart
  EXPECT_EQ(s.collisions.elements, 2);
}

// Outlines that meet up to rounding touch: two triangles of a touching tiling placed at offsets
// that are no whole numbers (as a crystal's growth places them), the second's corner 3.6e-15
// past the first's edge.
TEST(Collisions, OutlinesThatMeetUpToRoundingTouch) {
  const std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 -10 70 60">
    <path d="M38.18442218197183 17.072894230672286L58.18442218197183 17.072894230672286L38.18442218197183 37.07289423067229Z"/>
    <path d="M38.18442218197183 -2.92710576932771L58.18442218197183 -2.92710576932771L38.18442218197183 17.07289423067229Z"/></svg>)";
  const SceneStatistics s = compute_statistics(io::parse_svg(svg, "meet.svg", each_drawable()),
                                               StatisticsOptions{}, core::Random(1));
  EXPECT_TRUE(s.collisions.pairs.empty());
  EXPECT_EQ(s.collisions.touching.size(), 1u);
}

TEST(SceneStatistics, LatticeNearestNeighboursPerAxis) {
  const double spacing = 10.0;
  const SceneStatistics s =
      compute_statistics(lattice(spacing, 12, 12), torus(2.0 * spacing), core::Random(1));
  EXPECT_DOUBLE_EQ(s.intensity.at(0), 1.0 / (spacing * spacing));
  EXPECT_TRUE(s.collisions.pairs.empty());
  ASSERT_EQ(s.axes.size(), 4u);  // 8 directions: axes at 0°, 45°, 90°, 135°
  EXPECT_NEAR(s.all.nearest.mean(), spacing, 1e-9);
  EXPECT_NEAR(s.axes[0].nearest.mean(), spacing, 1e-9);
  EXPECT_NEAR(s.axes[2].nearest.mean(), spacing, 1e-9);
  EXPECT_NEAR(s.axes[1].nearest.mean(), spacing * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(s.axes[3].nearest.mean(), spacing * std::sqrt(2.0), 1e-9);
  // Within 2 spacings: 4 neighbours at the spacing and 4 on the diagonals, 2 per axis.
  EXPECT_NEAR(s.all.neighbours, 8.0, 1e-9);
  for (const DirectionalStatistics& a : s.axes) EXPECT_NEAR(a.neighbours, 2.0, 1e-9);

  // A lattice of spacing 11 against it: W1 of the nearest distances is 1 / 10 of the mean
  // nearest distance; a shifted copy of the same lattice is at distance 0.
  const SceneStatistics wider =
      compute_statistics(lattice(11.0, 12, 12), torus(2.0 * spacing), core::Random(1));
  EXPECT_NEAR(compare(wider, s).all.nearest, 0.1, 1e-9);
  geometry::Scene shifted = lattice(spacing, 12, 12);
  for (geometry::Element& e : shifted.elements) e.position += Vec3(3.0, 4.0, 0.0);
  const SceneStatistics same = compute_statistics(shifted, torus(2.0 * spacing), core::Random(1));
  const Comparison c = compare(same, s);
  EXPECT_NEAR(c.all.nearest, 0.0, 1e-9);
  EXPECT_NEAR(c.all.pairs, 0.0, 1e-9);
  EXPECT_NEAR(c.intensity_ratio.at(0), 1.0, 1e-12);
}

// G(r) of a Poisson pattern against 1 − exp(−λπr²), on a torus and with the border correction of
// an open window; tolerance 4 binomial standard errors of the empirical CDF.
TEST(SceneStatistics, PoissonNearestNeighbourDistribution) {
  const int n = 2000;
  const double side = 100.0, lambda = n / (side * side);
  const geometry::Scene scene = poisson(side, side, n, 7);
  for (const bool periodic : {true, false}) {
    StatisticsOptions o = torus(4.0);
    o.measurement.periodic = periodic;
    const SceneStatistics s = compute_statistics(scene, o, core::Random(1));
    const double used = s.all.nearest.samples;
    ASSERT_GT(used, periodic ? n - 1 : 0.8 * n);
    for (double r = 0.25; r < 4.0; r += 0.25) {
      const double expected = 1.0 - std::exp(-lambda * core::kPi * r * r);
      const double se = std::sqrt(expected * (1.0 - expected) / used);
      EXPECT_NEAR(s.all.nearest.cdf(r), expected, 4.0 * se + 1e-3)
          << "r = " << r << (periodic ? " torus" : " open");
    }
  }
}

// g(r) = 1 for Poisson points and for squares placed independently (overlaps allowed), which checks
// the Monte-Carlo offset measure of shaped elements. Counts per bin are Poisson-like: the tolerance
// is 4 relative standard errors of the bin's pair count (plus the offset measure's own error).
TEST(SceneStatistics, PairCorrelationOfIndependentPlacementsIsOne) {
  const geometry::Scene points = poisson(100.0, 100.0, 2000, 11);
  StatisticsOptions o = torus(5.0);
  o.correlation_bins = 10;
  const SceneStatistics s = compute_statistics(points, o, core::Random(1));
  for (std::size_t k = 0; k < s.correlation.size(); ++k) {
    const double expected_pairs = 2000.0 * (2000.0 - 1) / 10000.0 * core::kPi *
                                  (std::pow((static_cast<double>(k) + 1) * 0.5, 2) -
                                   std::pow(static_cast<double>(k) * 0.5, 2));  // ordered pairs
    EXPECT_NEAR(s.correlation[k], 1.0, 4.0 * std::sqrt(2.0 / expected_pairs)) << "bin " << k;
  }

  std::ostringstream svg;
  svg << R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 400 400">)";
  core::Random random(5);
  for (int i = 0; i < 3000; ++i) {
    svg << "<rect x=\"" << random.uniform(0, 392) << "\" y=\"" << random.uniform(0, 396)
        << "\" width=\"8\" height=\"4\"/>";
  }
  svg << "</svg>";
  const geometry::Scene squares = io::parse_svg(svg.str(), "squares.svg", each_drawable());
  StatisticsOptions so = torus(10.0);
  so.correlation_bins = 5;
  const SceneStatistics q = compute_statistics(squares, so, core::Random(1));
  for (std::size_t k = 0; k < q.correlation.size(); ++k) {
    // Offsets u with d in [2k, 2k + 2) between two 8 x 4 rectangles (Steiner: the 16 x 8 Minkowski
    // sum grown by r has area 128 + 48 r + π r²; bin 0 also holds the overlaps).
    const double band =
        96.0 + 4.0 * core::kPi * (2.0 * static_cast<double>(k) + 1.0) + (k == 0 ? 128.0 : 0.0);
    const double expected_pairs = 3000.0 * 2999.0 / 160000.0 * band;
    EXPECT_NEAR(q.correlation[k], 1.0, 4.0 * std::sqrt(2.0 / expected_pairs) + 0.03) << "bin " << k;
  }
}

TEST(NeighbourhoodDistance, ZeroAgainstItselfAndStretchedLatticeExact) {
  const geometry::Scene exemplar = lattice(10.0, 21, 21);
  const NeighbourhoodDistance self = average_neighbourhood_distance(
      exemplar, geometry::Boundary::open, exemplar, geometry::Boundary::open);
  EXPECT_DOUBLE_EQ(self.mean, 0.0);
  EXPECT_DOUBLE_EQ(self.radius, 20.0);
  EXPECT_GT(self.output_centres, 100);

  // A torus lattice 2% wider: every neighbour o' at lattice offset (i, j) pairs with the exemplar's
  // (i, j), costing (0.2)² (i² + j²); neighbourhood radius 25.
  const double eps = 0.02, spacing = 10.0, radius = 25.0;
  const geometry::Scene output = lattice(spacing * (1 + eps), 10, 10);
  double expected = 0.0;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) {
      const double len = spacing * (1 + eps) * std::hypot(i, j);
      if ((i != 0 || j != 0) && len < radius)
        expected += std::pow(eps * spacing, 2) * (i * i + j * j);
    }
  const NeighbourhoodDistance d = average_neighbourhood_distance(
      output, geometry::Boundary::torus, exemplar, geometry::Boundary::open, radius);
  EXPECT_NEAR(d.mean, expected, 1e-9 * expected);
  EXPECT_EQ(d.output_centres, 100);
}

TEST(NeighbourhoodDistance, CategoriesArePairedByName) {
  geometry::Scene a = lattice(10.0, 8, 8);
  a.categories.push_back({"other"});
  for (std::size_t i = 0; i < a.elements.size(); i += 2) a.elements[i].category = 1;
  geometry::Scene b = a;
  std::swap(b.categories[0], b.categories[1]);  // same names, other numbering
  for (geometry::Element& e : b.elements) e.category = 1 - e.category;
  EXPECT_DOUBLE_EQ(
      average_neighbourhood_distance(b, geometry::Boundary::torus, a, geometry::Boundary::torus)
          .mean,
      0.0);
  geometry::Scene renamed = a;
  renamed.categories[1].name = "unknown";
  EXPECT_GT(average_neighbourhood_distance(renamed, geometry::Boundary::torus, a,
                                           geometry::Boundary::torus)
                .mean,
            0.0);
}

}  // namespace
}  // namespace shapeproc::metrics
