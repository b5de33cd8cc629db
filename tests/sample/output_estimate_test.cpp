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

// Short of the exemplar's count by more than chance: below 0.9 of it and more than 3 √wanted
// below it. 120 of 136 is neither by chance (3 √136 = 35); 251 of 405 is; 7 of 16 is below 0.9
// but within 3 √16 = 12; nothing is short of an empty exemplar.
TEST(OutputEstimate, AnOutputFallsShortOnlyBeyondChance) {
  EXPECT_FALSE(falls_short(120, 136));
  EXPECT_TRUE(falls_short(100, 136));
  EXPECT_TRUE(falls_short(251, 405));
  EXPECT_FALSE(falls_short(7, 16));
  EXPECT_TRUE(falls_short(3, 16));
  EXPECT_FALSE(falls_short(0, 0));
  EXPECT_FALSE(falls_short(370, 405));  // 0.91 of it
}

}  // namespace
}  // namespace shapeproc::sample
