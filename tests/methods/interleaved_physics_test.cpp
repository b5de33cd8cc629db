#include "libshapeproc/methods/physics/interleaved_physics.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/methods/ma2011/neighbourhood_em.hpp"
#include "tests/methods/method_scenes.hpp"

namespace shapeproc::methods {
namespace {

using geometry::Boundary;
using geometry::Domain;

// Pairs of axis-aligned squares of side `side` whose interiors overlap (minimum image).
int overlapping_squares(const geometry::Scene& scene, const Domain& domain, double side) {
  int pairs = 0;
  for (std::size_t i = 0; i < scene.elements.size(); ++i)
    for (std::size_t j = i + 1; j < scene.elements.size(); ++j) {
      const Vec3 d = domain.minimum_image(scene.elements[j].position - scene.elements[i].position);
      pairs += std::abs(d.x()) < side - 1e-9 && std::abs(d.y()) < side - 1e-9;
    }
  return pairs;
}

TEST(InterleavedPhysics, ElementsMeetAcrossTheTorusSeam) {
  const EmExemplar exemplar = analyse_exemplar(testing::rectangle_lattice(6, 10.0, 3.0, 3.0),
                                               Boundary::torus, 2.0, SampleOptions{});
  const Domain domain = Domain::from_sizes({100, 100}, Boundary::torus);
  OutputSamples output;
  output.add(exemplar, 0, Vec3(0.5, 50, 0));
  output.add(exemplar, 0, Vec3(99.0, 50.5, 0));  // 1.5 to the left across the seam: overlapping
  output.add(exemplar, 0, Vec3(50, 20, 0));
  const Vec3 alone = output.samples.positions[2];
  const InterleavedPhysics physics(exemplar, 30);
  ASSERT_EQ(physics.shapes().size(), 1u);
  EXPECT_NEAR(physics.unit(), 3.0 * std::sqrt(2.0), 1e-9);
  EXPECT_TRUE(physics.settle(exemplar, output, domain, OrientationField{}));
  const Vec3 d = domain.minimum_image(output.samples.positions[1] - output.samples.positions[0]);
  EXPECT_GE(std::abs(d.x()), 3.0);
  EXPECT_LT(std::abs(d.x()), 3.5);
  for (const Vec3& p : output.samples.positions) EXPECT_TRUE(domain.contains(p));
  EXPECT_EQ(output.samples.positions[2], alone);
  // Nothing overlaps now: a second settling moves nothing.
  EXPECT_FALSE(physics.settle(exemplar, output, domain, OrientationField{}));
}

TEST(InterleavedPhysics, TheEmWithPhysicsLeavesNoOverlaps) {
  // Random element copies at the exemplar's density overlap; the EM alone leaves some.
  const geometry::Scene exemplar = testing::rectangle_scatter(40, 100.0, 6.0, 9.0, 3);
  const Domain domain = Domain::from_sizes({200, 200}, Boundary::torus);
  EmOptions options;
  options.initialisation = Initialisation::random_copy;
  const NeighbourhoodEm plain(exemplar, Boundary::torus, domain, options);
  options.physics_steps = kPhysicsSubSteps;
  const NeighbourhoodEm settled(exemplar, Boundary::torus, domain, options);
  int without = 0, with = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    core::Random a(seed), b(seed);
    without += overlapping_squares(plain.synthesize(a, {}).scene, domain, 6.0);
    const synthesis::SynthesisResult result = settled.synthesize(b, {});
    with += overlapping_squares(result.scene, domain, 6.0);
    EXPECT_EQ(result.record.options.back().second, "5");
  }
  EXPECT_GT(without, 0);
  EXPECT_EQ(with, 0);
}

}  // namespace
}  // namespace shapeproc::methods
