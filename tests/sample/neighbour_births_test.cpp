#include "libshapeproc/sample/neighbour_births.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tests/point_model.hpp"

namespace shapeproc::sample {
namespace {

using geometry::Vec3;

// A point model with a hard core and an attracting band, and offsets at the band's distance
// along the axes (the kind of a square lattice).
model::ShapeProcessModel lattice_points() {
  model::ShapeProcessModel m = testing::point_model(20.0, {0.1, 0.2}, {1.5});
  for (const Vec3& d : {Vec3(0.15, 0, 0), Vec3(-0.15, 0, 0), Vec3(0, 0.15, 0), Vec3(0, -0.15, 0)})
    m.neighbour_offsets.offsets.push_back({0, 0, d, 1.0});
  m.neighbour_offsets.radii = {0.005, 0.03};
  return m;
}

double core_area(double radius) { return 3.14159265358979323846 * radius * radius; }

struct Moments {
  double count = 0, count_error = 0, pairs = 0, pairs_error = 0;
};

// The mean element count and band pairs over `runs` independent chains, with their standard
// errors.
Moments moments(const model::ShapeProcessModel& m, double share, int runs) {
  const geometry::Domain domain = geometry::Domain::from_sizes({1, 1}, geometry::Boundary::torus);
  std::vector<double> counts, pairs;
  for (int seed = 1; seed <= runs; ++seed) {
    SamplerOptions options;
    options.iterations = 20000;
    options.near_birth_share = share;
    core::Random random(static_cast<std::uint64_t>(seed));
    const SampleResult result = sample_shape_process(m, domain, options, random);
    counts.push_back(static_cast<double>(result.scene.elements.size()));
    pairs.push_back(result.statistics.at(1));
  }
  const auto mean_error = [](const std::vector<double>& v, double& mean, double& error) {
    const double n = static_cast<double>(v.size());
    mean = 0;
    for (double x : v) mean += x / n;
    double spread = 0;
    for (double x : v) spread += (x - mean) * (x - mean);
    error = std::sqrt(spread / (n - 1) / n);
  };
  Moments out;
  mean_error(counts, out.count, out.count_error);
  mean_error(pairs, out.pairs, out.pairs_error);
  return out;
}

TEST(NeighbourBirths, TheChainsTargetDoesNotDependOnTheShare) {
  // The same model sampled with uniform births only and with 90% of them near a neighbour: the
  // mean count and the mean number of attracted pairs agree within 4 standard errors of their
  // difference. Without the proposal's density in the ratio, near births pile elements at the
  // offsets and the pairs differ by many errors.
  const model::ShapeProcessModel m = lattice_points();
  const Moments uniform = moments(m, 0.0, 200);
  const Moments near = moments(m, 0.9, 200);
  EXPECT_NEAR(near.count, uniform.count, 4 * std::hypot(near.count_error, uniform.count_error));
  EXPECT_NEAR(near.pairs, uniform.pairs, 4 * std::hypot(near.pairs_error, uniform.pairs_error));
}

TEST(NeighbourBirths, DensityIsTheMixtureOfBallsAroundEveryAnchor) {
  const model::ShapeProcessModel m = lattice_points();
  const model::Interaction interaction(m);
  const geometry::Domain domain = geometry::Domain::from_sizes({1, 1}, geometry::Boundary::torus);
  const std::unique_ptr<const NeighbourBirths> births = NeighbourBirths::make(m, 0.2);
  ASSERT_NE(births, nullptr);
  geometry::Scene space;
  space.window = domain.box();
  const geometry::PairMeasurer measurer(space, m.measurement_options(true));
  Configuration state(interaction, measurer, nullptr, domain, 0.2);
  Element a;
  a.position = Vec3(0.5, 0.5, 0);
  state.add(a, 0.0, {});
  // 0.004 from the anchor's offset (0.15, 0): inside both balls, each offset ¼ and each ball ½.
  Element xi;
  xi.position = Vec3(0.654, 0.5, 0);
  const double small = core_area(0.005), large = core_area(0.03);
  EXPECT_NEAR(births->density(xi, state, -1), 0.25 * (0.5 / small + 0.5 / large), 1e-9);
  // 0.01 away: in the large ball only; with the anchor skipped, nothing.
  xi.position = Vec3(0.66, 0.5, 0);
  EXPECT_NEAR(births->density(xi, state, -1), 0.25 * 0.5 / large, 1e-9);
  EXPECT_EQ(births->density(xi, state, 0), 0.0);
  // Across the torus's seam: the anchor at 0.95 has its offset at 0.1 (mod 1).
  Element b;
  b.position = Vec3(0.95, 0.2, 0);
  state.add(b, 0.0, {});
  xi.position = Vec3(0.1, 0.2, 0);
  EXPECT_NEAR(births->density(xi, state, -1), 0.5 * 0.25 * (0.5 / small + 0.5 / large), 1e-6);
}

TEST(NeighbourBirths, NoneWhereAnOffsetOutreachesTheGridOrAKindHasNone) {
  model::ShapeProcessModel m = lattice_points();
  EXPECT_EQ(NeighbourBirths::make(m, 0.1), nullptr);  // 0.15 + 0.03 > 0.1
  m.neighbour_offsets = {};
  EXPECT_EQ(NeighbourBirths::make(m, 1.0), nullptr);
  m = lattice_points();
  m.categories.push_back({"others", 1.0});  // a kind without offsets
  EXPECT_EQ(NeighbourBirths::make(m, 1.0), nullptr);
}

}  // namespace
}  // namespace shapeproc::sample
