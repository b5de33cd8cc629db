// What an output will need, before it is sampled.
#include "libshapeproc/sample/output_estimate.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/io/model_io.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::sample {
namespace {

TEST(OutputEstimate, DensityTimesMeasureAndBytesPerElementPerChain) {
  const geometry::Domain domain =
      geometry::Domain::from_sizes({100, 50}, geometry::Boundary::torus);
  const core::ResourceEstimate e = estimate_output(0.02, domain, 2, 3);
  EXPECT_DOUBLE_EQ(e.elements, 100.0);
  EXPECT_DOUBLE_EQ(e.bytes, 100.0 * kBytesPerElement * 3);
  EXPECT_FALSE(e.basis.empty());
}

TEST(OutputEstimate, WithoutARecordedDensityThePoissonCountBoundsIt) {
  const model::ShapeProcessModel model = io::parse_model(testing::kSquaresModel, "squares.json");
  const geometry::Domain domain =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::torus);
  double beta = 0.0;
  for (const auto& c : model.categories) beta += c.beta;
  EXPECT_DOUBLE_EQ(estimate_output(model, domain, std::nullopt, 1).elements, beta * 1e4);
  EXPECT_DOUBLE_EQ(estimate_output(model, domain, 0.001, 1).elements, 10.0);
}

}  // namespace
}  // namespace shapeproc::sample
