#include "libshapeproc/geometry/segment_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "libshapeproc/geometry/triangle_distance.hpp"

namespace shapeproc::geometry {
namespace {

TEST(SegmentDistance, AnalyticCases) {
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 0}, {1, 0}, {0, 2}, {1, 2}), 2.0);  // parallel
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 0}, {2, 2}, {0, 2}, {2, 0}), 0.0);  // crossing
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 0}, {1, 0}, {1, 0}, {1, 5}), 0.0);  // touching
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 0}, {1, 0}, {3, 0}, {4, 0}),
                   2.0);  // collinear apart
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 0}, {3, 0}, {1, 0}, {4, 0}),
                   0.0);  // collinear overlap
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 0}, {0, 0}, {3, 4}, {3, 4}), 5.0);  // two points
  EXPECT_DOUBLE_EQ(segment_segment_distance({1, 1}, {1, 1}, {0, 0}, {2, 0}),
                   1.0);  // point, segment
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 0}, {4, 0}, {2, 1}, {2, 3}), 1.0);  // T apart
}

TEST(SegmentDistance, MatchesDenseSampling) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng)), d(u(rng), u(rng));
    double sampled = INFINITY;
    for (int i = 0; i <= 400; ++i)
      sampled = std::min(sampled, point_segment_distance(a + (b - a) * (i / 400.0), c, d));
    const double exact = segment_segment_distance(a, b, c, d);
    EXPECT_LE(exact, sampled + 1e-12);
    EXPECT_NEAR(exact, sampled, (b - a).norm() / 400 + 1e-12);
    EXPECT_DOUBLE_EQ(exact, segment_segment_distance(c, d, a, b));
  }
}

TEST(TriangleDistance, AnalyticCases) {
  const Vec3 a0(0, 0, 0), a1(1, 0, 0), a2(0, 1, 0);
  EXPECT_NEAR(triangle_triangle_distance(a0, a1, a2, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}), 2.0,
              1e-12);  // parallel
  EXPECT_NEAR(triangle_triangle_distance(a0, a1, a2, {0.2, 0.2, -1}, {0.2, 0.2, 1}, {0.3, 0.2, 1}),
              0.0, 1e-12);  // piercing
  EXPECT_NEAR(triangle_triangle_distance(a0, a1, a2, {2, 0, 0}, {3, 0, 0}, {2, 1, 0}), 1.0,
              1e-12);  // coplanar apart
  // Degenerate triangles: a segment above, a point beside.
  EXPECT_NEAR(triangle_triangle_distance(a0, a1, a2, {0.1, 0.1, 3}, {0.2, 0.1, 3}, {0.2, 0.1, 3}),
              3.0, 1e-12);
  EXPECT_NEAR(point_triangle_distance({-3, 0, 4}, a0, a1, a2), 5.0, 1e-12);
  EXPECT_NEAR(
      triangle_triangle_distance({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {3, 4, 0}, {3, 4, 0}, {3, 4, 0}),
      5.0, 1e-12);
}

}  // namespace
}  // namespace shapeproc::geometry
