#include "libshapeproc/geometry/path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace shapeproc::geometry {
namespace {

Path2 square(double x, double y, double side, bool counter_clockwise = true) {
  std::vector<Vec2> corners = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  if (!counter_clockwise) std::reverse(corners.begin(), corners.end());
  Path2 path;
  for (int i = 0; i < 4; ++i)
    path.segments.push_back(Segment2::line(corners[i], corners[(i + 1) % 4]));
  path.closed = true;
  return path;
}

TEST(Segment, CubicBoundingBoxUsesExtremaNotControlPoints) {
  // The curve peaks at t = 1/2 with y = 3/4 while its control points reach y = 1.
  const Segment2 arch = Segment2::bezier({0, 0}, {0, 1}, {1, 1}, {1, 0});
  const Box2 box = bounding_box(arch);
  EXPECT_DOUBLE_EQ(box.min().y(), 0.0);
  EXPECT_NEAR(box.max().y(), 0.75, 1e-15);
  EXPECT_DOUBLE_EQ(box.max().x(), 1.0);
}

TEST(Segment, BoundingBoxContainsDenseSamples) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> coordinate(-10, 10);
  for (int trial = 0; trial < 200; ++trial) {
    const Segment2 s =
        Segment2::bezier({coordinate(rng), coordinate(rng)}, {coordinate(rng), coordinate(rng)},
                         {coordinate(rng), coordinate(rng)}, {coordinate(rng), coordinate(rng)});
    const Box2 box = bounding_box(s);
    Box2 sampled;
    for (int i = 0; i <= 2000; ++i) sampled.extend(s.point_at(i / 2000.0));
    // Exact extrema: the sampled box is inside and within sampling error of it.
    EXPECT_TRUE(box.contains(sampled.min()) || (sampled.min() - box.min()).norm() < 1e-12);
    EXPECT_NEAR((box.min() - sampled.min()).norm(), 0.0, 1e-4);
    EXPECT_NEAR((box.max() - sampled.max()).norm(), 0.0, 1e-4);
  }
}

TEST(Flatten, StaysWithinTolerance) {
  Path2 path;
  path.segments.push_back(Segment2::bezier({0, 0}, {30, 80}, {70, -80}, {100, 0}));
  for (const double tolerance : {1.0, 0.1, 0.01}) {
    const std::vector<Vec2> polyline = flatten(path, tolerance);
    double worst = 0.0;
    for (int i = 0; i <= 4000; ++i) {
      const Vec2 p = path.segments[0].point_at(i / 4000.0);
      double nearest = INFINITY;
      for (std::size_t k = 0; k + 1 < polyline.size(); ++k) {
        const Vec2 a = polyline[k], b = polyline[k + 1];
        const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        nearest = std::min(nearest, (a + t * (b - a) - p).norm());
      }
      worst = std::max(worst, nearest);
    }
    EXPECT_LE(worst, tolerance) << tolerance;
  }
}

TEST(Polygon, AreaAndWinding) {
  const std::vector<Vec2> ccw = flatten(square(0, 0, 2), 0.1);
  EXPECT_EQ(ccw.size(), 4u);  // a closed path does not repeat its first point
  EXPECT_DOUBLE_EQ(signed_area(ccw), 4.0);
  EXPECT_EQ(winding_number(ccw, {1, 1}), 1);
  EXPECT_EQ(winding_number(ccw, {3, 1}), 0);
  const std::vector<Vec2> cw = flatten(square(0, 0, 2, false), 0.1);
  EXPECT_DOUBLE_EQ(signed_area(cw), -4.0);
  EXPECT_EQ(winding_number(cw, {1, 1}), -1);
}

TEST(Polylines, OverlapIgnoresIsolatedTouchingPoints) {
  const auto a = flatten(square(0, 0, 1), 0.1);
  EXPECT_TRUE(polylines_overlap(a, true, flatten(square(0.5, 0.5, 1), 0.1), true));  // crossing
  EXPECT_FALSE(polylines_overlap(a, true, flatten(square(1, 1, 1), 0.1), true));     // corner only
  EXPECT_TRUE(polylines_overlap(a, true, flatten(square(1, 0, 1), 0.1), true));      // shared edge
  EXPECT_FALSE(polylines_overlap(a, true, flatten(square(3, 0, 1), 0.1), true));     // apart
  EXPECT_FALSE(polylines_overlap(a, true, flatten(square(0.25, 0.25, 0.5), 0.1), true));  // nested
}

}  // namespace
}  // namespace shapeproc::geometry
