// Simulation envelopes on patterns whose answer is known: a Poisson pattern lies inside the
// envelope of its Poisson model, a lattice far outside it.
#include "libshapeproc/evaluation/envelope.hpp"

#include <gtest/gtest.h>

#include "tests/metrics/metric_scenes.hpp"
#include "tests/point_model.hpp"

namespace shapeproc::evaluation {
namespace {

using geometry::Boundary;

TEST(Envelope, APoissonPatternLiesInsideItsModelsEnvelope) {
  // 100 points in 100 x 100: β = 0.01.
  const model::ShapeProcessModel poisson = testing::point_model(0.01);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto curves =
        nearest_envelopes(testing::poisson(100.0, 100.0, 100, seed), Boundary::torus, poisson);
    ASSERT_FALSE(curves.empty());
    EXPECT_EQ(curves[0].label, "G, all directions");
    EXPECT_EQ(curves[0].r.size(), 32u);
    for (const EnvelopeCurve& c : curves) EXPECT_TRUE(c.passes()) << c.label << " " << c.outside;
  }
}

TEST(Envelope, ALatticeLeavesThePoissonEnvelope) {
  // Spacing 10: no neighbour nearer than 10, all of them at 10 (R = 10): G is 0 up to R, where a
  // Poisson pattern of the same density has G(r) = 1 − exp(−0.01 π r²), 0.96 at R.
  const auto curves = nearest_envelopes(testing::lattice(10.0, 10, 10), Boundary::torus,
                                        testing::point_model(0.01));
  EXPECT_GT(curves[0].outside, 0.75);
  EXPECT_FALSE(curves[0].passes());
  for (std::size_t i = 0; i < curves[0].r.size(); ++i)
    EXPECT_LE(curves[0].low[i], curves[0].high[i]);
}

}  // namespace
}  // namespace shapeproc::evaluation
