// Measurements on the shipped Hero Patterns bubbles tile: circles, so every distance is known.
#include <cmath>

#include <gtest/gtest.h>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/io/scene_io.hpp"
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

}  // namespace
}  // namespace shapeproc::geometry
