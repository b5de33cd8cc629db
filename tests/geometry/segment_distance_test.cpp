#include "libshapeproc/geometry/segment_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

TEST(TriangleDistance, SkewEdgesAreNearestAtTheirCommonPerpendicular) {
  // A's edge along x at z = 0 and B's along y at z = 1: every corner and face is farther.
  EXPECT_NEAR(triangle_triangle_distance({-1, 0, 0}, {1, 0, 0}, {0, -1, -1}, {0, -1, 1}, {0, 1, 1},
                                         {1, 0, 2}),
              1.0, 1e-12);
  // The same pair moved and turned: a corner of B over A's inside instead.
  EXPECT_NEAR(triangle_triangle_distance({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0.5}, {1, 1, 3},
                                         {2, 1, 3}),
              0.5, 1e-12);
}

TEST(TriangleDistance, MatchesDenseSamplingOfOneTriangle) {
  // The distance between two triangles is the least distance from a point of the first to the
  // second: sampled on a barycentric grid of the first (step h), the sampled minimum is at least
  // the exact one and at most h above it. Intersecting pairs (most of the near ones) give 0.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto random_point = [&](const Vec3& centre) {
    return Vec3(centre + Vec3(u(rng), u(rng), u(rng)));
  };
  constexpr int kSteps = 40;
  int intersecting = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 shift = Vec3(u(rng), u(rng), u(rng)) * (trial % 2 ? 1.0 : 3.0);
    const Vec3 a0 = random_point(Vec3::Zero()), a1 = random_point(Vec3::Zero()),
               a2 = random_point(Vec3::Zero());
    const Vec3 b0 = random_point(shift), b1 = random_point(shift), b2 = random_point(shift);
    double sampled = INFINITY;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j) {
        const double s = double(i) / kSteps, t = double(j) / kSteps;
        sampled = std::min(sampled,
                           point_triangle_distance(a0 + s * (a1 - a0) + t * (a2 - a0), b0, b1, b2));
      }
    const double step = std::max({(a1 - a0).norm(), (a2 - a0).norm()}) / kSteps;
    const double exact = triangle_triangle_distance(a0, a1, a2, b0, b1, b2);
    EXPECT_LE(exact, sampled + 1e-12) << trial;
    EXPECT_GE(exact, sampled - step - 1e-12) << trial;
    EXPECT_NEAR(exact, triangle_triangle_distance(b0, b1, b2, a0, a1, a2), 1e-12) << trial;
    intersecting += exact == 0.0;
  }
  EXPECT_GT(intersecting, 10);  // both kinds of pair were tried
  EXPECT_LT(intersecting, 190);
}

}  // namespace
}  // namespace shapeproc::geometry
