// A shape's size, unchanged by moving or turning it.
#include "libshapeproc/geometry/shape_size.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace shapeproc::geometry {
namespace {

Shape polygon(const std::vector<Vec2>& corners) {
  Path2 path;
  for (std::size_t i = 0; i < corners.size(); ++i)
    path.segments.push_back(Segment2::line(corners[i], corners[(i + 1) % corners.size()]));
  path.closed = true;
  Drawable2 drawable;
  drawable.paths = {path};
  drawable.style["fill"] = "#000000";
  Shape shape;
  shape.geometry = PlanarShape{{drawable}};
  return shape;
}

TEST(ShapeSize, SquareAreaAndRadiusExactly) {
  const ShapeSize s = shape_size(polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  EXPECT_NEAR(s.area, 4.0, 1e-9);
  EXPECT_NEAR(s.radius, std::sqrt(2.0), 1e-9);
}

TEST(ShapeSize, TurnedAndMovedCopiesAreTheSameSizeAndDoublingIsNot) {
  const ShapeSize square = shape_size(polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  const double c = std::cos(0.3), s = std::sin(0.3);
  std::vector<Vec2> turned;
  for (const Vec2& p : std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}})
    turned.emplace_back(10 + c * p.x() - s * p.y(), -4 + s * p.x() + c * p.y());
  EXPECT_NEAR(size_distance(square, shape_size(polygon(turned))), 0.0, 1e-9);
  const ShapeSize twice = shape_size(polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  // |log 2| for the radius plus |log 4| for the area.
  EXPECT_NEAR(size_distance(square, twice), std::log(2.0) + std::log(4.0), 1e-9);
  EXPECT_DOUBLE_EQ(size_distance(square, twice), size_distance(twice, square));
}

}  // namespace
}  // namespace shapeproc::geometry
