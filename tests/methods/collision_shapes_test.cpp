#include "libshapeproc/methods/physics/collision_shapes.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/geometry/measurement_fixtures.hpp"

namespace shapeproc::methods {
namespace {

namespace fx = geometry::fixtures;
using geometry::Vec2;

double signed_area(const std::array<Vec2, 3>& t) {
  const Vec2 u = t[1] - t[0], v = t[2] - t[0];
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

double area(const CollisionShape& shape) {
  double sum = 0.0;
  for (const auto& t : shape.triangles) sum += signed_area(t);
  return sum;
}

bool covers(const CollisionShape& shape, const Vec2& p) {
  for (const auto& t : shape.triangles) {
    bool inside = true;
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec2 e = t[(k + 1) % 3] - t[k], q = p - t[k];
      inside = inside && e.x() * q.y() - e.y() * q.x() >= 0.0;
    }
    if (inside) return true;
  }
  return false;
}

TEST(CollisionShapes, FilledRectangleIsTiledExactlyCounterClockwise) {
  const CollisionShape shape = collision_shape(fx::planar({fx::rectangle(-2, -1, 2, 1)}), 1e-6);
  ASSERT_FALSE(shape.empty());
  for (const auto& t : shape.triangles) EXPECT_GT(signed_area(t), 0.0);
  EXPECT_NEAR(area(shape), 8.0, 1e-9);
  EXPECT_NEAR(shape.radius, std::sqrt(5.0), 1e-9);
}

TEST(CollisionShapes, HolesFollowTheFillRule) {
  // Nonzero with the hole drawn backwards: an annulus of area pi (R^2 - r^2), centre uncovered.
  const CollisionShape annulus = collision_shape(fx::ring(2.0, 1.0), 1e-6);
  // Within the proxy's error bound (0.01 of the diagonal) along both outlines.
  const double bound = 0.01 * std::sqrt(32.0) * 2.0 * M_PI * (2.0 + 1.0);
  EXPECT_NEAR(area(annulus), M_PI * 3.0, bound);
  EXPECT_FALSE(covers(annulus, Vec2(0, 0)));
  EXPECT_TRUE(covers(annulus, Vec2(1.5, 0)));
  // Even-odd with both outlines the same way round: the same annulus.
  const CollisionShape evenodd =
      collision_shape(fx::planar({fx::rectangle(-2, -2, 2, 2), fx::rectangle(-1, -1, 1, 1)},
                                 geometry::FillRule::evenodd),
                      1e-6);
  EXPECT_NEAR(area(evenodd), 16.0 - 4.0, 1e-9);
  EXPECT_FALSE(covers(evenodd, Vec2(0, 0)));
}

TEST(CollisionShapes, UnfilledOutlinesCollideAsTheirStrips) {
  // A square outline with no fill: a strip around it, its inside free.
  const CollisionShape outline = collision_shape(
      fx::planar({fx::rectangle(-2, -2, 2, 2)}, geometry::FillRule::nonzero, false), 1e-9);
  ASSERT_FALSE(outline.empty());
  EXPECT_FALSE(covers(outline, Vec2(0, 0)));
  EXPECT_TRUE(covers(outline, Vec2(2, 0)));
  // Half-width 0.005 of the diagonal (the proxy's default for curves): about 16 x 2 x 0.028.
  const double half_width = 0.005 * std::sqrt(32.0);
  EXPECT_NEAR(area(outline), 16.0 * 2.0 * half_width, 0.05 * 16.0 * 2.0 * half_width);
}

TEST(CollisionShapes, SliversAreLeftOutAndPointsHaveNoPieces) {
  const CollisionShape thin =
      collision_shape(fx::planar({fx::rectangle(-2, -0.001, 2, 0.001)}), 0.01);
  EXPECT_TRUE(thin.triangles.empty());
  EXPECT_TRUE(collision_shape(geometry::Shape{geometry::PointShape{}, ""}, 0.01).empty());
}

TEST(CollisionShapes, MeshesCollideAsTheHullOfTheirProxy) {
  const geometry::Shape cube{
      geometry::MeshShape{fx::box_mesh(geometry::Vec3(-1, -1, -1), geometry::Vec3(1, 1, 1))}, ""};
  const CollisionShape shape = collision_shape(cube, 0.01);
  EXPECT_EQ(shape.hull_points.size(), 8u);
  EXPECT_NEAR(shape.radius, std::sqrt(3.0), 1e-9);
}

}  // namespace
}  // namespace shapeproc::methods
