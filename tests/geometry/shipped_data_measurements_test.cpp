// Measurements on the shipped Hero Patterns bubbles tile: circles, so every distance is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/svg_reader.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::geometry {
namespace {

Scene bubbles() {
  io::ReaderOptions options;
  options.split_subpaths = true;
  return io::read_scene(testing::data_path("third-party/hero-patterns/bubbles.svg"), options);
}

TEST(ShippedDataMeasurements, BubbleDistancesAreCentreDistancesMinusRadii) {
  const Scene scene = bubbles();
  ASSERT_EQ(scene.elements.size(), 17u);
  const PairMeasurer measurer(scene, MeasurementOptions{});
  const auto pairs = measurer.all_pairs(scene.elements);
  EXPECT_EQ(pairs.size(), 17u * 16u / 2u);
  for (const PairRecord& p : pairs) {
    const Element& a = scene.elements[p.i];
    const Element& b = scene.elements[p.j];
    const double ra = bounding_box(scene.shapes[a.shape]).sizes().x() / 2;
    const double rb = bounding_box(scene.shapes[b.shape]).sizes().x() / 2;
    const double exact = (b.position - a.position).norm() - ra - rb;
    // Proxies are inscribed polygons within 1% of the diagonal (2√2 r) of the circles (the
    // drawn Béziers are themselves within 0.03% of circles).
    const double tolerance = 0.01 * 2 * std::sqrt(2.0) * (ra + rb) + 0.001 * (ra + rb);
    EXPECT_GE(p.measurement.distance, exact - 0.001 * (ra + rb)) << p.i << " " << p.j;
    EXPECT_LE(p.measurement.distance, exact + tolerance) << p.i << " " << p.j;
    // Discs of uniform mass attract along the line of centres.
    const Vec3 centres = (b.position - a.position).normalized();
    EXPECT_GT(p.measurement.direction.dot(centres), std::cos(0.5 * 3.14159265358979323846 / 180));
  }
}

TEST(ShippedDataMeasurements, PeriodicTileGapMatchesTheTiledExemplar) {
  // The tile repeats: with --periodic the smallest gap is the one measured between bubbles of
  // neighbouring tiles in the 3x3 composite (9.279 in the data manifest); without it, no gap is
  // smaller.
  const Scene scene = bubbles();
  MeasurementOptions options;
  options.proxy.tolerance = 0.001;
  double open_min = INFINITY, periodic_min = INFINITY;
  for (const PairRecord& p : PairMeasurer(scene, options).all_pairs(scene.elements)) {
    open_min = std::min(open_min, p.measurement.distance);
  }
  options.periodic = true;
  for (const PairRecord& p : PairMeasurer(scene, options).all_pairs(scene.elements)) {
    periodic_min = std::min(periodic_min, p.measurement.distance);
  }
  EXPECT_NEAR(periodic_min, 9.279, 0.01);
  EXPECT_GE(open_min, periodic_min);
}

// Copies of one drawing placed anywhere get one proxy: a circle drawn as two half arcs whose end
// points are a diameter apart only up to rounding, and Douglas–Peucker's ties between a
// circle's equally far samples, must not depend on where the copy lies.
TEST(ShippedDataMeasurements, CopiesOfOneDrawingShareTheirProxy) {
  io::ReaderOptions split;
  split.split_subpaths = true;
  const Scene rings = io::read_scene(testing::data_path("svg/rings.svg"), split);
  const PairMeasurer measurer(rings, MeasurementOptions{});
  // 19 elements: rings of radius 9 and 12 (outline and hole) and dots of radius 2.5.
  std::vector<int> representatives;
  for (int s = 0; s < static_cast<int>(rings.shapes.size()); ++s) {
    const bool known = std::any_of(representatives.begin(), representatives.end(),
                                   [&](int r) { return measurer.same_proxy(r, s); });
    if (!known) representatives.push_back(s);
  }
  EXPECT_EQ(representatives.size(), 3u);
  // Same proxy, same measurements; different drawings differ.
  const Vec3 offset(31.0, 7.5, 0.0);
  for (int s = 0; s < static_cast<int>(rings.shapes.size()); ++s) {
    for (int r : representatives) {
      if (!measurer.same_proxy(r, s)) continue;
      EXPECT_NEAR(measurer.distance(s, 0, offset), measurer.distance(r, 0, offset), 1e-9);
      EXPECT_NEAR(measurer.direction(s, 0, offset).x(), measurer.direction(r, 0, offset).x(), 1e-9);
    }
  }
  EXPECT_FALSE(measurer.same_proxy(representatives[0], representatives[1]));

  // The same circle as <circle> and as arcs from a start point, at positions whose sums round.
  const Scene circles = io::parse_svg(
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 300 300'>"
      "<path d='M116.12 30.294a5.4 5.4 0 1 0 0 10.8a5.4 5.4 0 1 0 0 -10.8z'/>"
      "<path d='M171.134 89.246a5.4 5.4 0 1 0 0 10.8a5.4 5.4 0 1 0 0 -10.8z'/>"
      "<path d='M82.719 153.452a5.4 5.4 0 1 0 0 10.8a5.4 5.4 0 1 0 0 -10.8z'/>"
      "<circle cx='20.3' cy='40.7' r='7.25'/><circle cx='251.9' cy='199.03' r='7.25'/>"
      "<circle cx='120.01' cy='260.77' r='7.3'/></svg>",
      "circles.svg", {});
  const PairMeasurer circle_measurer(circles, MeasurementOptions{});
  EXPECT_TRUE(circle_measurer.same_proxy(0, 1));
  EXPECT_TRUE(circle_measurer.same_proxy(0, 2));
  EXPECT_TRUE(circle_measurer.same_proxy(3, 4));
  EXPECT_FALSE(circle_measurer.same_proxy(3, 5));
  EXPECT_FALSE(circle_measurer.same_proxy(0, 3));
}

}  // namespace
}  // namespace shapeproc::geometry
