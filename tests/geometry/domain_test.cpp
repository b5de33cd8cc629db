#include "libshapeproc/geometry/domain.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::geometry {
namespace {

TEST(Domain, MeasurePeriodAndMinimumImage) {
  const Domain torus = Domain::from_sizes({10, 4}, Boundary::torus);
  EXPECT_EQ(torus.dimension(), 2);
  EXPECT_DOUBLE_EQ(torus.measure(), 40.0);
  EXPECT_EQ(torus.period(), Vec3(10, 4, 0));
  EXPECT_TRUE(torus.minimum_image(Vec3(9, -3, 0)).isApprox(Vec3(-1, 1, 0)));
  EXPECT_TRUE(torus.minimum_image(Vec3(4, 1.5, 0)).isApprox(Vec3(4, 1.5, 0)));
  const Domain open = Domain::from_sizes({10, 4}, Boundary::open);
  EXPECT_EQ(open.period(), Vec3::Zero());
  EXPECT_EQ(open.minimum_image(Vec3(9, -3, 0)), Vec3(9, -3, 0));
  const Domain box = Domain::from_sizes({2, 3, 4}, Boundary::torus);
  EXPECT_DOUBLE_EQ(box.measure(), 24.0);
  EXPECT_TRUE(box.minimum_image(Vec3(1.5, -2, 3)).isApprox(Vec3(-0.5, 1, -1)));
}

TEST(Domain, WrapAndContain) {
  const Domain torus = Domain::from_sizes({10, 4}, Boundary::torus);
  EXPECT_TRUE(torus.wrap(Vec3(-1, 9, 0)).isApprox(Vec3(9, 1, 0)));
  EXPECT_TRUE(torus.wrap(Vec3(10, 4, 0)).isApprox(Vec3(0, 0, 0)));
  const Domain open = Domain::from_sizes({10, 4}, Boundary::open);
  EXPECT_EQ(open.wrap(Vec3(-1, 9, 0)), Vec3(-1, 9, 0));
  EXPECT_TRUE(open.contains(Vec3(0, 4, 0)));
  EXPECT_FALSE(open.contains(Vec3(-0.01, 2, 0)));
  EXPECT_FALSE(open.contains(Vec3(5, 4.01, 0)));
}

TEST(Domain, MaskContainsAProxyOnlyWhenItsOutlineIsInside) {
  // Left half inside (x < 5 of 10), 10 x 10 pixels over a 10 x 10 domain.
  auto mask = std::make_shared<Raster>();
  mask->width = mask->height = 10;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) mask->values.push_back(x < 5 ? 1.0f : 0.0f);
  Domain domain = Domain::from_sizes({10, 10}, Boundary::open);
  domain.set_mask(mask);
  Proxy2 square;  // a 2 x 2 square around its reference position
  const Vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k) {
    square.segment_start.push_back(corners[k]);
    square.segment_end.push_back(corners[(k + 1) % 4]);
  }
  EXPECT_TRUE(domain.contains(square, Vec2(2, 5)));
  EXPECT_FALSE(domain.contains(square, Vec2(4.5, 5)));  // centre inside, right edge outside
  EXPECT_FALSE(domain.contains(square, Vec2(7, 5)));
  EXPECT_DOUBLE_EQ(domain.intensity_at(Vec2(7, 5)), 1.0);
}

TEST(Domain, BadArgumentsThrowWithTheReason) {
  EXPECT_THROW(Domain::from_sizes({0, 4}, Boundary::torus), core::ArgumentError);
  EXPECT_THROW(Domain::from_sizes({1, -4}, Boundary::open), core::ArgumentError);
  EXPECT_THROW(Domain::from_sizes({1}, Boundary::open), core::ArgumentError);
  EXPECT_THROW(Domain::from_sizes({1, 2, 0}, Boundary::open), core::ArgumentError);
  EXPECT_THROW(parse_boundary("periodic"), core::ArgumentError);
  EXPECT_EQ(parse_boundary("open"), Boundary::open);
  Domain torus = Domain::from_sizes({1, 1}, Boundary::torus);
  EXPECT_THROW(torus.set_mask(std::make_shared<Raster>()), core::ArgumentError);
  Domain box = Domain::from_sizes({1, 1, 1}, Boundary::open);
  EXPECT_THROW(box.set_mask(std::make_shared<Raster>()), core::ArgumentError);
  EXPECT_THROW(box.set_intensity(std::make_shared<Raster>()), core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::geometry
