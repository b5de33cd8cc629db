// The multipole expansions of 2D gravitation (region_gravitation.hpp) against the edge-pair
// boundary integral on polygons whose edges are cut into 64 collinear pieces (its quadrature error
// shrinks with the square of the edges' length: below 2e-5 there, against a 2D cubature of the
// kernel over the polygons' triangles; up to 2e-3 on the uncut polygons of the last test).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/region_gravitation.hpp"

namespace shapeproc::geometry {
namespace {

// A star-shaped polygon (counter-clockwise) with `corners` corners at radii in [0.6, 1] * radius,
// each edge cut into `pieces` collinear edges.
MassBoundary2 star(std::mt19937& rng, int corners, double radius, int pieces) {
  std::uniform_real_distribution<double> r(0.6 * radius, radius);
  std::vector<Vec2> points;
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * core::kPi * i / corners;
    const double length = r(rng);
    points.emplace_back(length * std::cos(angle), length * std::sin(angle));
  }
  MassBoundary2 mass;
  for (int i = 0; i < corners; ++i) {
    const Vec2 a = points[i], b = points[(i + 1) % corners];
    const Vec2 edge = b - a;
    const Vec2 outward = Vec2(edge.y(), -edge.x()).normalized();
    for (int k = 0; k < pieces; ++k)
      mass.add_edge(a + edge * (double(k) / pieces), a + edge * (double(k + 1) / pieces), outward);
  }
  mass.finish();
  return mass;
}

double relative(const Vec2& value, const Vec2& reference) {
  return (value - reference).norm() / reference.norm();
}

TEST(GravitationExpansion, MomentsOfASquareAreExact) {
  MassBoundary2 square;  // [-1, 3] x [-1, 1]: area 8, centroid (1, 0)
  const Vec2 c[4] = {{-1, -1}, {3, -1}, {3, 1}, {-1, 1}};
  const Vec2 n[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (int i = 0; i < 4; ++i) square.add_edge(c[i], c[(i + 1) % 4], n[i]);
  square.finish();
  const auto& m = square.complex_moments;
  EXPECT_NEAR(m[moment_index(0, 0)].real(), 8.0, 1e-12);
  EXPECT_NEAR(std::abs(m[moment_index(1, 0)]), 0.0, 1e-12);  // about the centroid
  // ∫ |z|^2 over a 4 x 2 rectangle = 8 (4^2 + 2^2) / 12; ∫ z^2 = 8 (4^2 − 2^2) / 12.
  EXPECT_NEAR(m[moment_index(1, 1)].real(), 8.0 * 20 / 12, 1e-12);
  EXPECT_NEAR(m[moment_index(2, 0)].real(), 8.0 * 12 / 12, 1e-12);
  EXPECT_NEAR(m[moment_index(2, 0)].imag(), 0.0, 1e-12);
  // ∫ x^4 over [-2, 2] x [-1, 1] = 2 * 2 * 2^5 / 5; Re z^4 = x^4 − 6 x^2 y^2 + y^4.
  const double x4 = 2 * 2 * 32.0 / 5, y4 = 4 * 2.0 / 5, x2y2 = (2 * 8.0 / 3) * (2.0 / 3);
  EXPECT_NEAR(m[moment_index(4, 0)].real(), x4 - 6 * x2y2 + y4, 1e-10);
}

TEST(GravitationExpansion, PairExpansionMatchesTheBoundaryIntegral) {  // NOLINT
  std::mt19937 rng(3);
  // From 2.1 on: about twice the radii and nearer, the expansion would need more than
  // kMomentOrder terms and the edges answer instead (the last test).
  std::uniform_real_distribution<double> angle(0, 2 * core::kPi), spread(2.1, 5.0);
  for (int trial = 0; trial < 20; ++trial) {
    const int ca = 5 + trial % 7, cb = 4 + trial % 5;
    std::mt19937 copy = rng;
    const MassBoundary2 a = star(rng, ca, 1.0, 1), b = star(rng, cb, 1.5, 1);
    const MassBoundary2 fine_a = star(copy, ca, 1.0, 64), fine_b = star(copy, cb, 1.5, 64);
    const PairExpansion pair = pair_expansion(a, b);
    // Centroid distance from 2 to 5 times the sum of the radii.
    const double phi = angle(rng);
    const Vec2 offset = a.centroid - b.centroid +
                        spread(rng) * (a.radius + b.radius) * Vec2(std::cos(phi), std::sin(phi));
    const Vec2 reference = gravitation_force_edges(fine_a, fine_b, offset);
    EXPECT_LT(relative(gravitation_force(a, b, offset, &pair), reference), 3e-5) << trial;
    // Antisymmetric up to rounding.
    const PairExpansion back = pair_expansion(b, a);
    EXPECT_LT(relative(gravitation_force(b, a, -offset, &back), -reference), 3e-5) << trial;
  }
}

TEST(GravitationExpansion, PotentialExpansionAlongEdgesOfLargePolygons) {  // NOLINT
  // Many edges and near neighbours: edges of A far from B use B's expansion, the others the
  // edge pairs; the total stays within the edge-pair method's own quadrature error.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> angle(0, 2 * core::kPi), gap(0.1, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    std::mt19937 copy = rng;
    const MassBoundary2 a = star(rng, 40, 1.0, 4), b = star(rng, 40, 1.0, 4);
    const MassBoundary2 fine_a = star(copy, 40, 1.0, 16), fine_b = star(copy, 40, 1.0, 16);
    const double phi = angle(rng);
    const Vec2 offset = (2.0 + gap(rng)) * Vec2(std::cos(phi), std::sin(phi));
    const Vec2 reference = gravitation_force_edges(fine_a, fine_b, offset);
    EXPECT_LT(relative(gravitation_force(a, b, offset), reference), 2e-3) << trial;
    EXPECT_LT(relative(gravitation_force_edges(a, b, offset), reference), 2e-3) << trial;
  }
}

TEST(GravitationExpansion, ClusterPotentialMatchesItsEdgesFarAway) {  // NOLINT
  // A cluster of 16 edges of a star's boundary, seen from 4 to 20 radii: the expansion against
  // the edges' own integrals (closed form along each edge, exact up to rounding).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(0, 2 * core::kPi), distance(4.0, 20.0);
  for (int trial = 0; trial < 20; ++trial) {
    const MassBoundary2 star_edges = star(rng, 16, 1.0, 4);
    EdgeCluster cluster;
    Box2 box;
    for (int j = 0; j < 16; ++j) box.extend(star_edges.start[j]).extend(star_edges.end[j]);
    cluster.centre = box.center();
    double total_length = 0.0;
    for (int j = 0; j < 16; ++j) {
      cluster.add_edge(star_edges.start[j], star_edges.end[j], star_edges.normal[j]);
      total_length += star_edges.length[j];
    }
    const double phi = angle(rng), ratio = distance(rng);
    const Vec2 x = cluster.centre + ratio * cluster.radius * Vec2(std::cos(phi), std::sin(phi));
    double exact = 0.0;  // Σ_j ∫ n_j·(y − x)/|y − x| ds by 2000 midpoints per edge
    for (int j = 0; j < 16; ++j) {
      const Vec2 a = star_edges.start[j], b = star_edges.end[j];
      for (int k = 0; k < 2000; ++k) {
        const Vec2 y = a + (k + 0.5) / 2000 * (b - a);
        exact += star_edges.normal[j].dot(y - x) / (y - x).norm() * star_edges.length[j] / 2000;
      }
    }
    // The truncation is of the fourth order in radius / distance.
    EXPECT_LT(std::abs(cluster.potential(x) - exact), 2.0 * total_length * std::pow(ratio, -4))
        << trial;
  }
}

TEST(GravitationExpansion, ClustersKeepTheForceOfTouchingDetailedShapes) {  // NOLINT
  // Two 640-edge stars nearly touching: most of each boundary is far from most of the other's
  // clusters. The force with the clusters' expansions against the edge pairs alone.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * core::kPi), gap(0.02, 0.3);
  double worst = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    const MassBoundary2 a = star(rng, 40, 1.0, 16), b = star(rng, 40, 1.0, 16);
    const double phi = angle(rng);
    const Vec2 offset = (2.0 + gap(rng)) * Vec2(std::cos(phi), std::sin(phi));
    const Vec2 reference = gravitation_force_edges(a, b, offset);
    worst = std::max(worst, relative(gravitation_force(a, b, offset), reference));
  }
  EXPECT_LT(worst, 2e-4);
}

}  // namespace
}  // namespace shapeproc::geometry
