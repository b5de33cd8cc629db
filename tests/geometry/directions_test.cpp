#include "libshapeproc/geometry/directions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::geometry {
namespace {

Vec3 at_angle(double degrees) {
  return Vec3(std::cos(degrees * core::kPi / 180), std::sin(degrees * core::kPi / 180), 0);
}

TEST(DirectionBins, PlanarAxes) {
  const DirectionBins bins(2, 8);
  EXPECT_EQ(bins.axis_count(), 4);
  EXPECT_EQ(bins.axis_of(at_angle(0)), 0);
  EXPECT_EQ(bins.axis_of(at_angle(22)), 0);
  EXPECT_EQ(bins.axis_of(at_angle(23)), 1);
  EXPECT_EQ(bins.axis_of(at_angle(90)), 2);
  EXPECT_EQ(bins.axis_of(at_angle(135)), 3);
  EXPECT_EQ(bins.axis_of(at_angle(180)), 0);
  EXPECT_EQ(bins.axis_of(at_angle(-45)), 3);
  for (double angle = -179; angle < 180; angle += 7.3) {
    EXPECT_EQ(bins.axis_of(at_angle(angle)), bins.axis_of(-at_angle(angle))) << angle;
  }
  EXPECT_NEAR(bins.axis_direction(1).x(), std::sqrt(0.5), 1e-15);
  EXPECT_EQ(DirectionBins(2, 1).axis_count(), 1);
  EXPECT_EQ(DirectionBins(2, 2).axis_of(at_angle(80)), 0);
  EXPECT_THROW(DirectionBins(2, 3), std::invalid_argument);
  EXPECT_THROW(DirectionBins(2, 0), std::invalid_argument);
  EXPECT_THROW(DirectionBins(3, 8), std::invalid_argument);
}

// An arc has an axis only when it stays within one sector; sectors are 45° wide, centred on
// multiples of 45°, and the two sectors at ±180° are one.
TEST(DirectionBins, AnArcHasTheAxisOfEveryDirectionOnItOrNone) {
  const DirectionBins bins(2, 8);
  const double degree = core::kPi / 180;
  EXPECT_EQ(bins.arc_axis(at_angle(0), 22 * degree), 0);
  EXPECT_EQ(bins.arc_axis(at_angle(0), 23 * degree), std::nullopt);
  EXPECT_EQ(bins.arc_axis(at_angle(40), 4 * degree), 1);
  EXPECT_EQ(bins.arc_axis(at_angle(40), 17 * degree), 1);
  EXPECT_EQ(bins.arc_axis(at_angle(40), 18 * degree), std::nullopt);
  EXPECT_EQ(bins.arc_axis(at_angle(179), 10 * degree), 0);  // across ±180°
  EXPECT_EQ(bins.arc_axis(at_angle(-100), 5 * degree), 2);
  // Every arc that has an axis holds it at both ends and in the middle.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> angle(-180, 180), width(0, 30);
  int answered = 0;
  for (int k = 0; k < 20000; ++k) {
    const double a = angle(rng), w = width(rng);
    const std::optional<int> axis = bins.arc_axis(at_angle(a), w * degree);
    if (!axis) continue;
    ++answered;
    ASSERT_EQ(bins.axis_of(at_angle(a - w)), *axis) << a << " ± " << w;
    ASSERT_EQ(bins.axis_of(at_angle(a + w)), *axis) << a << " ± " << w;
    ASSERT_EQ(bins.axis_of(at_angle(a)), *axis) << a << " ± " << w;
  }
  // A uniform arc of half-width w in [0, 30]° stays in its 45° sector with probability
  // E[max(0, 1 − 2w/45)] = 0.375: the rule is not stricter than the sectors.
  EXPECT_NEAR(answered / 20000.0, 0.375, 0.02);
  EXPECT_EQ(DirectionBins(3, 12).arc_axis(Vec3::UnitX(), 0.01), std::nullopt);
}

TEST(DirectionBins, HealpixBasePixelsHaveEqualAreas) {
  std::mt19937 rng(12);
  std::normal_distribution<double> normal;
  const int samples = 120000;
  std::vector<int> counts(12, 0);
  const DirectionBins bins(3, 12);
  for (int s = 0; s < samples; ++s) {
    const Vec3 u = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    const int pixel = healpix_base_pixel(u);
    ASSERT_GE(pixel, 0);
    ASSERT_LT(pixel, 12);
    ++counts[pixel];
    EXPECT_EQ(bins.axis_of(u), bins.axis_of(-u));
  }
  // Binomial(samples, 1/12): 5 standard errors.
  const double expected = samples / 12.0, se = std::sqrt(samples * (1.0 / 12) * (11.0 / 12));
  for (int p = 0; p < 12; ++p) EXPECT_NEAR(counts[p], expected, 5 * se) << p;
  for (int p = 0; p < 12; ++p) EXPECT_EQ(healpix_base_pixel(healpix_base_pixel_centre(p)), p);
  EXPECT_EQ(bins.axis_count(), 6);
}

}  // namespace
}  // namespace shapeproc::geometry
