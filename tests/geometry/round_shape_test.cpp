// Round shapes (geometry/round_shape.hpp): which shapes are, and the direction between two of
// them that are apart, the line of their centres, against the integrated gravitation.
#include "libshapeproc/geometry/round_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/region_gravitation.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "tests/geometry/measurement_fixtures.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::geometry {
namespace {

using fixtures::disc;
using fixtures::planar;
using fixtures::polygon;
using fixtures::ring;

Shape regular_polygon(int corners, double radius) {
  std::vector<Vec2> points;
  for (int k = 0; k < corners; ++k) {
    const double angle = 2 * core::kPi * k / corners;
    points.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  return planar({polygon(points)});
}

TEST(RoundShape, DiscsRingsAndPointsAreRoundAndOtherShapesAreNot) {
  ASSERT_TRUE(round_radius(disc(3)).has_value());
  EXPECT_NEAR(*round_radius(disc(3)), 3.0, 3.0 * 2 * kRoundTolerance);
  EXPECT_GE(*round_radius(disc(3)), 3.0);
  ASSERT_TRUE(round_radius(ring(5, 3)).has_value());
  EXPECT_NEAR(*round_radius(ring(5, 3)), 5.0, 5.0 * 2 * kRoundTolerance);
  EXPECT_EQ(round_radius(Shape{PointShape{}, ""}), 0.0);
  // A 16-gon is round to the measurements (its corners 22.5° apart); a 12-gon and a square are
  // polygons, though their corners lie on a circle too.
  EXPECT_TRUE(round_radius(regular_polygon(16, 2)).has_value());
  EXPECT_FALSE(round_radius(regular_polygon(12, 2)).has_value());
  EXPECT_FALSE(round_radius(regular_polygon(4, 2)).has_value());
  EXPECT_FALSE(round_radius(planar({ellipse_path(Vec2::Zero(), 3, 2)})).has_value());
  EXPECT_FALSE(round_radius(planar({ellipse_path(Vec2(1, 0), 3, 3)})).has_value());  // off centre
  Shape ring_and_dot = ring(5, 3);
  std::get<PlanarShape>(ring_and_dot.geometry)
      .parts.front()
      .paths.push_back(ellipse_path(Vec2(1, 0), 0.5, 0.5));
  EXPECT_FALSE(round_radius(ring_and_dot).has_value());  // a dot off the ring's centre
  EXPECT_FALSE(round_radius(planar({polygon({{-3, 0}, {0, 3}, {3, 0}}, false)}, FillRule::nonzero,
                                   false))
                   .has_value());  // an open curve
  EXPECT_FALSE(round_radius(Shape{MeshShape{}, ""}).has_value());
}

// Apart, the direction between round shapes is the line of centres bit for bit; the integrated
// force between their polygonal proxies agrees within their error.
TEST(RoundShape, ApartTheyPullAlongTheLineOfCentres) {
  Scene scene;
  scene.dimension = 2;
  scene.window = Box3(Vec3(-100, -100, 0), Vec3(100, 100, 0));
  scene.shapes = {disc(2), ring(5, 3), disc(0.5)};
  const PairMeasurer measurer(scene, MeasurementOptions{});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    const int a = static_cast<int>(rng() % 3), b = static_cast<int>(rng() % 3);
    const double outer[] = {2, 5, 0.5};
    const double angle = 2 * core::kPi * unit(rng);
    const double apart = (outer[a] + outer[b]) * (1.01 + 2 * unit(rng));
    const Vec3 offset(apart * std::cos(angle), apart * std::sin(angle), 0);
    const Vec3 direction = measurer.direction(a, b, offset);
    EXPECT_EQ(direction, Vec3(offset.normalized()));
    EXPECT_EQ(measurer.direction(b, a, -offset), Vec3(-direction));
    const Vec2 force = gravitation_force(measurer.proxies2()[a].mass, measurer.proxies2()[b].mass,
                                         offset.head<2>(), nullptr);
    worst = std::max(worst,
                     std::acos(std::clamp(force.normalized().dot(direction.head<2>()), -1.0, 1.0)));
  }
  // The proxies' polygons (within 1% of the diagonal) against the circles: at most 2°, nearest
  // where the shapes almost touch.
  EXPECT_LT(worst, 0.035);
}

// An unfilled circle drawn with a wide stroke is round, and its mass is the stroke's strip,
// wider than the outline: a dot inside the strip, beyond the outline's circle, is integrated.
TEST(RoundShape, AStrokesStripWidensTheOuterCircle) {
  Scene scene;
  scene.dimension = 2;
  scene.window = Box3(Vec3(-100, -100, 0), Vec3(100, 100, 0));
  Shape circle = planar({ellipse_path(Vec2::Zero(), 5, 5)}, FillRule::nonzero, false);
  std::get<PlanarShape>(circle.geometry).parts.front().style["stroke-width"] = "4";
  ASSERT_TRUE(round_radius(circle).has_value());
  scene.shapes = {circle, disc(0.5)};
  const PairMeasurer measurer(scene, MeasurementOptions{});
  for (const double r : {5.8, 6.3, 6.8}) {
    const Vec3 offset(r, 0, 0);
    const Vec2 force = gravitation_force(measurer.proxies2()[0].mass, measurer.proxies2()[1].mass,
                                         offset.head<2>(), nullptr);
    const Vec3 direction = measurer.direction(0, 1, offset);
    EXPECT_NEAR(direction.x(), force.normalized().x(), 1e-9) << r;
    EXPECT_NEAR(direction.y(), force.normalized().y(), 1e-9) << r;
  }
}

// The shipped exemplars whose shapes are all discs or rings, those whose shapes are none, and
// two-kinds: its discs are round, its crosses are not.
TEST(RoundShape, ShippedDiscAndRingExemplarsAreRound) {
  io::ReaderOptions split;
  split.split_subpaths = true;
  const auto all_round = [](const Scene& scene) {
    for (const Shape& s : scene.shapes)
      if (!round_radius(s)) return false;
    return true;
  };
  const auto none_round = [](const Scene& scene) {
    for (const Shape& s : scene.shapes)
      if (round_radius(s)) return false;
    return true;
  };
  EXPECT_TRUE(all_round(io::read_scene(testing::data_path("svg/dots-random.svg"), {})));
  const Scene two_kinds = io::read_scene(testing::data_path("svg/two-kinds.svg"), {});
  int round = 0;
  for (const Shape& s : two_kinds.shapes) round += round_radius(s) ? 1 : 0;
  EXPECT_EQ(round, 17);  // its 17 <circle>s
  EXPECT_LT(round, static_cast<int>(two_kinds.shapes.size()));
  EXPECT_TRUE(all_round(io::read_scene(testing::data_path("svg/rings.svg"), split)));
  EXPECT_TRUE(none_round(io::read_scene(testing::data_path("svg/crescents-grid.svg"), {})));
  EXPECT_TRUE(none_round(io::read_scene(testing::data_path("svg/dashes-rows.svg"), {})));
}

}  // namespace
}  // namespace shapeproc::geometry
