#include "libshapeproc/model/model_edits.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::model {
namespace {

ShapeProcessModel squares() { return io::parse_model(testing::kSquaresModel, "squares.json"); }

// The squares model's four axes have thresholds (2, 6), (4, 6), (8, 10), (4, 6) and γ 0.5 each:
// one axis holds their means.
TEST(ModelEdits, IsotropicAveragesTheAxes) {
  ShapeProcessModel m = squares();
  make_isotropic(m);
  ASSERT_EQ(m.interactions[0].axes.size(), 1u);
  EXPECT_EQ(m.measurement.directions, 1);
  EXPECT_EQ(m.interactions[0].axes[0].thresholds, (std::vector<double>{4.5, 7}));
  EXPECT_EQ(m.interactions[0].axes[0].gammas, (std::vector<double>{0.5}));
  EXPECT_EQ(m.interactions[0].axes[0].status[0], ParameterStatus::fixed);
  validate(m);
  ShapeProcessModel uneven = squares();
  uneven.interactions[0].axes[1].thresholds = {4, 5, 6};
  uneven.interactions[0].axes[1].gammas = {0.5, 0.5};
  uneven.interactions[0].axes[1].gamma_standard_errors = {NAN, NAN};
  uneven.interactions[0].axes[1].status.assign(2, ParameterStatus::fixed);
  EXPECT_THROW(make_isotropic(uneven), core::ArgumentError);
}

TEST(ModelEdits, ScalingKeepsTheModelFiniteOrRefuses) {
  ShapeProcessModel m = squares();
  scale_intensities(m, 3.0);
  EXPECT_DOUBLE_EQ(m.categories[0].beta, 0.6);
  scale_thresholds(m, 0.5);
  EXPECT_EQ(m.interactions[0].axes[2].thresholds, (std::vector<double>{4, 5}));
  scale_intensities(m, 1e308);  // 6e307: finite (the output's budget refuses to sample it)
  const ShapeProcessModel before = m;
  EXPECT_THROW(scale_intensities(m, 10.0), core::ArgumentError);  // 6e308 overflows
  EXPECT_THROW(scale_intensities(m, HUGE_VAL), core::ArgumentError);
  EXPECT_THROW(scale_intensities(m, -1.0), core::ArgumentError);
  EXPECT_THROW(scale_thresholds(m, 0.0), core::ArgumentError);
  EXPECT_EQ(m.categories[0].beta, before.categories[0].beta);  // a refused edit changes nothing
}

TEST(ModelEdits, ParametersSetByHandAreFixed) {
  ShapeProcessModel m = squares();
  set_intensity(m, 0, 0.7);
  EXPECT_EQ(m.categories[0].beta, 0.7);
  EXPECT_EQ(m.categories[0].beta_status, ParameterStatus::fixed);
  EXPECT_TRUE(std::isnan(m.categories[0].beta_standard_error));
  set_gamma(m, 0, 2, 0, 3.0);
  EXPECT_EQ(m.interactions[0].axes[2].gammas[0], 3.0);
  set_threshold(m, 0, 1, 1, 9.0);
  EXPECT_EQ(m.interactions[0].axes[1].thresholds, (std::vector<double>{4, 9}));
  EXPECT_THROW(set_intensity(m, 1, 0.7), core::ArgumentError);    // one category
  EXPECT_THROW(set_intensity(m, 0, -1.0), core::ArgumentError);   // β < 0
  EXPECT_THROW(set_gamma(m, 0, 4, 0, 1.0), core::ArgumentError);  // four axes
  EXPECT_THROW(set_gamma(m, 0, 0, 1, 1.0), core::ArgumentError);  // one band
  EXPECT_THROW(set_gamma(m, 0, 0, 0, -2.0), core::ArgumentError);
  EXPECT_THROW(set_threshold(m, 1, 0, 0, 1.0), core::ArgumentError);  // one pair
}

}  // namespace
}  // namespace shapeproc::model
