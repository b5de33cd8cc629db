#include "libshapeproc/methods/ijiri2008/seed_and_grow.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/methods/ijiri2008/delaunay_connectivity.hpp"
#include "libshapeproc/methods/ijiri2008/ring_matching.hpp"
#include "tests/methods/method_scenes.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::methods {
namespace {

using geometry::Boundary;
using geometry::Domain;

std::vector<Vec3> positions_of(const geometry::Scene& scene) {
  std::vector<Vec3> out;
  for (const auto& e : scene.elements) out.push_back(e.position);
  return out;
}

TEST(DelaunayConnectivity, AHexagonalLatticeOnATorusHasSixNeighboursEach) {
  const geometry::Scene lattice = testing::hexagonal_lattice(6, 6, 10.0, 3.0, 3.0);
  const Domain tile(lattice.window, 2, Boundary::torus);
  const Connectivity c = delaunay_connectivity(positions_of(lattice), tile);
  ASSERT_EQ(c.rings.size(), 36u);
  for (const Ring& ring : c.rings) {
    EXPECT_TRUE(ring.closed);
    ASSERT_EQ(ring.neighbour.size(), 6u);
    for (std::size_t k = 0; k < 6; ++k) {
      EXPECT_NEAR(ring.offset[k].norm(), 10.0, 1e-9);
      // Counter-clockwise, 60 degrees apart.
      const Vec3 &a = ring.offset[k], &b = ring.offset[(k + 1) % 6];
      EXPECT_NEAR(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)), M_PI / 3, 1e-9);
    }
  }
  EXPECT_EQ(c.edges.size(), 36u * 3u);
  EXPECT_NEAR(c.mean_edge, 10.0, 1e-9);
}

TEST(DelaunayConnectivity, OpenExemplarsLoseTheirBorderAndSkewedTriangles) {
  const geometry::Scene lattice = testing::hexagonal_lattice(6, 6, 10.0, 3.0, 3.0);
  const Domain open(lattice.window, 2, Boundary::open);
  const Connectivity c = delaunay_connectivity(positions_of(lattice), open);
  int closed = 0;
  for (std::size_t e = 0; e < c.rings.size(); ++e) {
    // Inner elements have all six lattice neighbours.
    int around = 0;
    for (const auto& o : lattice.elements)
      around += std::abs((o.position - lattice.elements[e].position).norm() - 10.0) < 1e-6 ? 1 : 0;
    // Inner elements close; the row ends with 5 close across the notch by a triangle of exactly
    // 2π/3 (kept or not as rounding has it); the rest are open.
    if (around == 6) {
      EXPECT_TRUE(c.rings[e].closed) << e;
    }
    if (around < 5) {
      EXPECT_FALSE(c.rings[e].closed) << e;
    }
    closed += c.rings[e].closed ? 1 : 0;
    // No skewed triangle survives: no edge is longer than the lattice's diagonals.
    for (const Vec3& o : c.rings[e].offset) EXPECT_LT(o.norm(), 10.0 * std::sqrt(3.0) + 1e-9);
  }
  EXPECT_GE(closed, 16);
  EXPECT_LE(closed, 20);
}

TEST(DelaunayConnectivity, AFlipTurnsAnEdgeIntoTheOtherDiagonal) {
  // A rhombus: Delaunay joins the short diagonal 1-3; the flip asks for 0-2.
  const std::vector<Vec3> points{{0, 0, 0}, {10, -4, 0}, {20, 0, 0}, {10, 4, 0}};
  const Domain open(geometry::Box3(Vec3(0, -5, 0), Vec3(20, 5, 0)), 2, Boundary::open);
  const Connectivity before = delaunay_connectivity(points, open);
  EXPECT_EQ(before.edges,
            (std::vector<std::pair<int, int>>{{0, 1}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
  const Connectivity after = delaunay_connectivity(points, open, {{3, 1}});
  EXPECT_EQ(after.edges,
            (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {2, 3}}));
  EXPECT_THROW(delaunay_connectivity(points, open, {{0, 2}}), core::ArgumentError);  // not an edge
  EXPECT_THROW(delaunay_connectivity(points, open, {{0, 1}}), core::ArgumentError);  // border
  EXPECT_THROW(delaunay_connectivity(points, open, {{0, 9}}), core::ArgumentError);
}

TEST(RingMatching, PartialRingsStartAfterTheirWidestGap) {
  // Neighbours at 10, 80 and 200 degrees: the widest gap is from 200 round to 10.
  std::vector<TargetNeighbour> target;
  for (const double degrees : {80.0, 200.0, 10.0}) {
    const double r = degrees * M_PI / 180;
    target.push_back({Vec3(std::cos(r), std::sin(r), 0), -1, -1});
  }
  EXPECT_EQ(partial_ring_order(target), (std::vector<int>{2, 0, 1}));
}

TEST(RingMatching, CyclicMatchingsOnAHandCase) {
  // A reference ring of four neighbours at east, north, west, south (symbols 1, 2, 3, 4); the
  // seed has two neighbours, north then west, of symbols 2 and 3.
  ReferenceRing ref{
      7, 1, {{10, 0, 0}, {0, 10, 0}, {-10, 0, 0}, {0, -10, 0}}, {1, 2, 3, 4}, {1, 2, 3, 4}};
  const std::vector<TargetNeighbour> target{{{0, 10, 0}, 2, 5}, {{-10, 0, 0}, 3, 6}};
  const MatchWeights w{1.0, 1.0, 100.0, 10.0};
  // f_1 pairs them with north and west exactly: error 0.
  EXPECT_DOUBLE_EQ(matching_error(target, ref, 1, 0.0, w), 0.0);
  // f_0 pairs north with east (distance √200 / 10) and west with north (same), symbols both wrong.
  EXPECT_DOUBLE_EQ(matching_error(target, ref, 0, 0.0, w), 2 * std::sqrt(2.0) + 2.0);
  // f_2: north with west, west with south: distances √2 each, symbols both wrong.
  EXPECT_DOUBLE_EQ(matching_error(target, ref, 2, 0.0, w), 2 * std::sqrt(2.0) + 2.0);
  // f_3: north with south (2), west with east (2), symbols both wrong.
  EXPECT_DOUBLE_EQ(matching_error(target, ref, 3, 0.0, w), 6.0);
  // A neighbour copying the reference itself costs w3.
  std::vector<TargetNeighbour> self = target;
  self[0].sub_id = 7;
  EXPECT_DOUBLE_EQ(matching_error(self, ref, 1, 0.0, w), 100.0);
  core::Random random(1);
  const RingMatch m = best_match(target, {ref}, {0}, RotationMode::none, 0.0, w, random);
  EXPECT_EQ(m.shift, 1);
  EXPECT_DOUBLE_EQ(m.error, 0.0);
  // Turned by 30 degrees, the best rotation finds the turn back and the error vanishes again.
  std::vector<TargetNeighbour> turned = target;
  for (auto& t : turned) t.offset = Eigen::AngleAxisd(M_PI / 6, Vec3::UnitZ()) * t.offset;
  const RingMatch r = best_match(turned, {ref}, {0}, RotationMode::best, 0.0, w, random);
  EXPECT_EQ(r.shift, 1);
  EXPECT_NEAR(r.angle, M_PI / 6, 1e-12);
  EXPECT_NEAR(r.error, 0.0, 1e-12);
  EXPECT_GT(best_match(turned, {ref}, {0}, RotationMode::none, 0.0, w, random).error, 0.5);
  // A reference smaller than the partial ring is skipped.
  const std::vector<TargetNeighbour> five(5, target[0]);
  EXPECT_EQ(best_match(five, {ref}, {0}, RotationMode::none, 0.0, w, random).reference, -1);
}

TEST(SeedAndGrow, AHexagonalLatticeGrowsIntoTheLattice) {
  const geometry::Scene exemplar = testing::hexagonal_lattice(6, 6, 10.0, 3.0, 3.0);
  for (const Boundary boundary : {Boundary::torus, Boundary::open}) {
    const Domain domain(geometry::Box3(Vec3(0, 0, 0), Vec3(120, 6 * 10 * std::sqrt(3.0), 0)), 2,
                        boundary);
    const SeedAndGrow method(exemplar, Boundary::torus, domain, {});
    const auto result = testing::run(method, 3);
    const auto nearest = testing::nearest_distances(result.scene, domain);
    for (const double d : nearest) EXPECT_NEAR(d, 10.0, 0.5);
    const double expected = domain.measure() * 36 / exemplar.window_measure();
    if (boundary == Boundary::torus) {
      EXPECT_NEAR(static_cast<double>(result.scene.elements.size()), expected, 0.02 * expected);
    } else {
      // Open: growth stops at the box, whose border cuts rows.
      EXPECT_GT(static_cast<double>(result.scene.elements.size()), 0.85 * expected);
      EXPECT_LE(static_cast<double>(result.scene.elements.size()), expected + 12);
    }
  }
}

TEST(SeedAndGrow, SameSeedSameOutputAndRotationModes) {
  const geometry::Scene exemplar = io::read_scene(testing::data_path("svg/dots-random.svg"), {});
  const Domain domain(geometry::Box3(Vec3(0, 0, 0), Vec3(300, 300, 0)), 2, Boundary::open);
  for (const RotationMode mode :
       {RotationMode::none, RotationMode::best, RotationMode::flow_field}) {
    SeedGrowthOptions options;
    options.rotation = mode;
    if (mode == RotationMode::flow_field) options.field = OrientationField::constant(30);
    const SeedAndGrow method(exemplar, Boundary::open, domain, options);
    const auto a = testing::run(method, 5), b = testing::run(method, 5);
    ASSERT_EQ(a.scene.elements.size(), b.scene.elements.size());
    for (std::size_t e = 0; e < a.scene.elements.size(); ++e)
      EXPECT_EQ(a.scene.elements[e].position, b.scene.elements[e].position);
    EXPECT_GT(a.scene.elements.size(), 20u);
    for (const auto& e : a.scene.elements) EXPECT_TRUE(domain.contains(e.position));
  }
}

TEST(SeedAndGrow, ATileOfTwoElementsIsRepeatedAndGrows) {
  // The hexagonal lattice of spacing 10 as a tile of two elements (10 x 10√3, the second element
  // in the middle): its 2 x 2 repeat has closed rings, and a torus of 12 x 6 tiles fills with the
  // lattice's 144 elements at its spacing.
  const double h = 10.0 * std::sqrt(3.0);
  geometry::Scene tile = testing::hexagonal_lattice(2, 2, 10.0, 3.0, 3.0);
  tile.window = geometry::Box3(Vec3(0, 0, 0), Vec3(10, h, 0));
  tile.elements = {{0, 0, Vec3(2.5, 0.25 * h, 0)}, {0, 0, Vec3(7.5, 0.75 * h, 0)}};
  const Domain domain(geometry::Box3(Vec3(0, 0, 0), Vec3(120, 6 * h, 0)), 2, Boundary::torus);
  const SeedAndGrow method(tile, Boundary::torus, domain, {});
  const auto result = testing::run(method, 2);
  EXPECT_NEAR(static_cast<double>(result.scene.elements.size()), 144.0, 0.02 * 144.0);
  for (const double d : testing::nearest_distances(result.scene, domain)) EXPECT_NEAR(d, 10.0, 0.5);
}

TEST(SeedAndGrow, RefusesWhatItCannotGrow) {
  geometry::Scene two = testing::hexagonal_lattice(2, 2, 10.0, 3.0, 3.0);
  two.elements.resize(2);
  const Domain domain(geometry::Box3(Vec3(0, 0, 0), Vec3(100, 100, 0)), 2, Boundary::open);
  EXPECT_THROW(SeedAndGrow(two, Boundary::open, domain, {}), core::ArgumentError);
  // Three in a row: every triangle is skewed or missing, no ring closes.
  geometry::Scene row = two;
  row.elements = {{0, 0, Vec3(1, 1, 0)}, {0, 0, Vec3(5, 1.1, 0)}, {0, 0, Vec3(9, 1, 0)}};
  EXPECT_THROW(SeedAndGrow(row, Boundary::open, domain, {}), core::ArgumentError);
  SeedGrowthOptions outside;
  outside.seeds = {Vec3(500, 0, 0)};
  EXPECT_THROW(
      SeedAndGrow(testing::hexagonal_lattice(6, 6, 10, 3, 3), Boundary::torus, domain, outside),
      core::ArgumentError);
}

TEST(SeedAndGrow, ExactOverlapsKeepLongShapesApart) {
  // Ijiri's growth has no overlap test: scattered bars grow onto each other. With the shapes
  // tested, none overlaps and the domain is still grown over.
  const geometry::Scene exemplar = testing::bar_scatter(60, 4);
  const Domain domain = Domain::from_sizes({400, 400}, Boundary::torus);
  SeedGrowthOptions options;
  const SeedAndGrow plain(exemplar, Boundary::torus, domain, options);
  options.exact_overlap = true;
  const SeedAndGrow shapes(exemplar, Boundary::torus, domain, options);
  const auto a = testing::run(plain, 1), b = testing::run(shapes, 1);
  EXPECT_GT(testing::overlapping_bars(a.scene, domain), 0);
  EXPECT_EQ(testing::overlapping_bars(b.scene, domain), 0);
  EXPECT_GT(b.scene.elements.size(), 150u);  // 240 at the exemplar's density
}

TEST(SeedAndGrow, CircleOverlapsKeepBoundingCirclesApart) {
  // With circles, no two elements come closer than their radii (half each exemplar element's
  // nearest ring distance) allow; without, dots-random grows some that do.
  const geometry::Scene exemplar = io::read_scene(testing::data_path("svg/dots-random.svg"), {});
  const Domain domain = Domain::from_sizes({400, 400}, Boundary::torus);
  const auto too_close = [&](const SeedAndGrow& method, const geometry::Scene& scene) {
    // Output elements keep their exemplar shape; a shape may be shared by several exemplar
    // elements, so take the smallest circle of its shape.
    std::vector<double> radius(exemplar.shapes.size(), 1e300);
    for (std::size_t e = 0; e < exemplar.elements.size(); ++e) {
      double& r = radius[static_cast<std::size_t>(exemplar.elements[e].shape)];
      r = std::min(r, method.exemplar().circle_radius[e]);
    }
    int pairs = 0;
    for (std::size_t i = 0; i < scene.elements.size(); ++i)
      for (std::size_t j = i + 1; j < scene.elements.size(); ++j) {
        const double d =
            domain.minimum_image(scene.elements[j].position - scene.elements[i].position).norm();
        pairs += d < radius[static_cast<std::size_t>(scene.elements[i].shape)] +
                         radius[static_cast<std::size_t>(scene.elements[j].shape)] - 1e-6;
      }
    return pairs;
  };
  SeedGrowthOptions options;
  const SeedAndGrow plain(exemplar, Boundary::open, domain, options);
  options.circle_overlap = true;
  const SeedAndGrow circles(exemplar, Boundary::open, domain, options);
  const auto a = testing::run(plain, 1), b = testing::run(circles, 1);
  EXPECT_GT(too_close(plain, a.scene), 0);
  EXPECT_EQ(too_close(circles, b.scene), 0);
  EXPECT_GT(b.scene.elements.size(), 60u);  // 120 at the exemplar's density
}

}  // namespace
}  // namespace shapeproc::methods
