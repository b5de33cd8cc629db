#include "libshapeproc/geometry/arc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>

namespace shapeproc::geometry {
namespace {

// Largest |distance to centre - radius| over dense samples of every segment.
double radial_error(const Path2& path, const Vec2& centre, double radius) {
  double worst = 0.0;
  for (const Segment2& s : path.segments) {
    for (int i = 0; i <= 64; ++i) {
      worst = std::max(worst, std::abs((s.point_at(i / 64.0) - centre).norm() - radius));
    }
  }
  return worst;
}

TEST(EllipticalArc, SemicircleEndsExactlyAndStaysOnTheCircle) {
  Path2 path;
  append_elliptical_arc(path, Vec2(0, 0), 1, 1, 0, false, true, Vec2(2, 0));
  ASSERT_EQ(path.segments.size(), 2u);  // pieces of at most 90 degrees
  EXPECT_EQ(path.segments.front().start, Vec2(0, 0));
  EXPECT_EQ(path.segments.back().end, Vec2(2, 0));
  // A 90-degree cubic arc deviates from the circle by at most 2.7e-4 of the radius.
  EXPECT_LT(radial_error(path, Vec2(1, 0), 1.0), 3e-4);
  // sweep-flag 1 turns towards increasing angle: in SVG's y-down frame through (1, -1).
  EXPECT_NEAR(path.segments.front().end.x(), 1.0, 1e-12);
  EXPECT_NEAR(path.segments.front().end.y(), -1.0, 1e-12);
}

TEST(EllipticalArc, FlagsChooseTheFourArcs) {
  // From (0,0) to (1,1) with radius 1: centres (1,0) and (0,1); large/sweep choose the arc.
  for (const bool large : {false, true}) {
    for (const bool sweep : {false, true}) {
      Path2 path;
      append_elliptical_arc(path, Vec2(0, 0), 1, 1, 0, large, sweep, Vec2(1, 1));
      EXPECT_EQ(path.segments.size(), large ? 3u : 1u) << large << sweep;
      const Vec2 centre = (large == sweep) ? Vec2(1, 0) : Vec2(0, 1);
      EXPECT_LT(radial_error(path, centre, 1.0), 3e-4) << large << sweep;
      EXPECT_EQ(path.segments.back().end, Vec2(1, 1));
    }
  }
}

TEST(EllipticalArc, OutOfRangeParameters) {
  Path2 same;
  append_elliptical_arc(same, Vec2(3, 4), 5, 5, 0, false, false, Vec2(3, 4));
  EXPECT_TRUE(same.segments.empty());

  Path2 flat;
  append_elliptical_arc(flat, Vec2(0, 0), 0, 5, 0, false, false, Vec2(3, 4));
  ASSERT_EQ(flat.segments.size(), 1u);
  EXPECT_FALSE(flat.segments[0].cubic);

  // Radii too small are scaled up until the arc reaches: a semicircle of radius 1.
  Path2 scaled;
  append_elliptical_arc(scaled, Vec2(0, 0), -0.25, 0.25, 0, false, true, Vec2(2, 0));
  EXPECT_LT(radial_error(scaled, Vec2(1, 0), 1.0), 3e-4);

  // Radii or a rotation that are not finite give no ellipse: a line, as for zero radii (a NaN
  // radius had reached an int conversion, undefined behaviour).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& [rx, ry, rotation] :
       {std::tuple{nan, 5.0, 0.0}, std::tuple{5.0, inf, 0.0}, std::tuple{5.0, 5.0, nan}}) {
    Path2 line;
    append_elliptical_arc(line, Vec2(0, 0), rx, ry, rotation, false, false, Vec2(3, 4));
    ASSERT_EQ(line.segments.size(), 1u);
    EXPECT_FALSE(line.segments[0].cubic);
  }
}

TEST(EllipticalArc, RotatedEllipse) {
  // Ellipse rx = 2, ry = 1 rotated by 90 degrees: x^2 + (y/2)^2 = 1 around the origin.
  Path2 path;
  append_elliptical_arc(path, Vec2(0, -2), 2, 1, 90, false, true, Vec2(0, 2));
  for (const Segment2& s : path.segments) {
    for (int i = 0; i <= 32; ++i) {
      const Vec2 p = s.point_at(i / 32.0);
      EXPECT_NEAR(std::hypot(p.x(), p.y() / 2), 1.0, 1e-3);
    }
  }
  EXPECT_NEAR(path.segments.front().end.x(), 1.0, 1e-12);  // passes through (1, 0)
}

TEST(EllipsePath, ClosedWithExactBoundingBox) {
  const Path2 path = ellipse_path(Vec2(10, 20), 3, 2);
  EXPECT_TRUE(path.closed);
  ASSERT_EQ(path.segments.size(), 4u);
  EXPECT_EQ(path.segments.back().end, path.segments.front().start);
  const Box2 box = bounding_box(path);
  EXPECT_NEAR(box.min().x(), 7, 1e-12);
  EXPECT_NEAR(box.max().x(), 13, 1e-12);
  EXPECT_NEAR(box.min().y(), 18, 1e-12);
  EXPECT_NEAR(box.max().y(), 22, 1e-12);
}

}  // namespace
}  // namespace shapeproc::geometry
