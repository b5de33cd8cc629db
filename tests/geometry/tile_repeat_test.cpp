// A seamless tile repeated for fitting: every element's periodic images become elements that the
// nearest-image pair counting sees.
#include "libshapeproc/geometry/tile_repeat.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "libshapeproc/geometry/arc.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"

namespace shapeproc::geometry {
namespace {

Scene one_dot_tile() {
  Scene tile;
  tile.window = Box3(Vec3(0, 0, 0), Vec3(10, 6, 0));
  tile.categories.push_back({"dots"});
  Drawable2 dot;
  dot.paths.push_back(ellipse_path(Vec2(2, 3), 1, 1));
  add_element(tile, Shape{PlanarShape{{dot}}, "dot"}, 0);
  return tile;
}

TEST(TileRepeat, CopiesEveryElementByWholeWindows) {
  const Scene tile = one_dot_tile();
  const Scene repeated = repeat_tile(tile, 3);
  ASSERT_EQ(repeated.elements.size(), 9u);
  EXPECT_EQ(repeated.window.min(), tile.window.min());
  EXPECT_EQ(repeated.window.max(), Vec3(30, 18, 0));
  EXPECT_EQ(repeated.shapes.size(), 1u);
  EXPECT_EQ(repeated.elements[4].position, Vec3(12, 9, 0));  // the middle copy
  EXPECT_EQ(repeat_tile(tile, 1).elements.size(), 1u);
  EXPECT_EQ(tile_repeats(1), 4);
  EXPECT_EQ(tile_repeats(4), 3);
  EXPECT_EQ(tile_repeats(8), 1);
}

TEST(TileRepeat, TileOverContinuesTheDrawingOverARegion) {
  // The dot at (2, 3) of a 10 x 6 tile, over [-5, 25] x [0, 12]: x in {2, 12, 22}, y in {3, 9}.
  const Scene tile = one_dot_tile();
  const std::vector<Element> over = tile_over(tile, Box3(Vec3(-5, 0, 0), Vec3(25, 12, 0)));
  ASSERT_EQ(over.size(), 6u);
  std::vector<Vec3> expected;
  for (double y : {3.0, 9.0})
    for (double x : {2.0, 12.0, 22.0}) expected.emplace_back(x, y, 0);
  for (const Vec3& p : expected) {
    EXPECT_EQ(
        std::count_if(over.begin(), over.end(), [&](const Element& e) { return e.position == p; }),
        1)
        << p.transpose();
  }
  EXPECT_TRUE(tile_over(tile, Box3(Vec3(3, 4, 0), Vec3(11, 8, 0))).empty());
  EXPECT_TRUE(tile_over(Scene{}, Box3(Vec3(0, 0, 0), Vec3(9, 9, 0))).empty());
}

// A torus holds pairs up to `range` apart once when its smallest side is at least twice the
// range plus the largest extent on either side: the dot of radius 1 (extent √2, its bounding
// box's half diagonal) on the 10 x 6 tile needs 2 (4 + 2√2) = 13.7, three repeats of 6.
TEST(TileRepeat, RepeatsToHoldARangeOnTheTorus) {
  const Scene tile = one_dot_tile();
  EXPECT_EQ(repeats_to_hold(tile, 4.0, 1), 3);
  EXPECT_EQ(repeats_to_hold(tile, 4.0, 4), 4);
  EXPECT_EQ(repeats_to_hold(tile, 0.0, 1), 1);
  EXPECT_EQ(repeats_to_hold(tile, 0.2, 1), 2);  // 2 (0.2 + 2.83) = 6.06 > 6
}

TEST(TileRepeat, AOneElementTileHasNeighbours) {
  // On its own torus the dot has no pair; repeated 3 x 3, each copy has its images one period
  // away on either side as neighbours: 2 along x (at 10 - 2 = 8 between outlines), 2 along y (4).
  MeasurementOptions options;
  options.periodic = true;
  const Scene tile = one_dot_tile();
  EXPECT_TRUE(PairMeasurer(tile, options).all_pairs(tile.elements, 9.0).empty());
  const Scene repeated = repeat_tile(tile, 3);
  const PairMeasurer measurer(repeated, options);
  const auto pairs = measurer.all_pairs(repeated.elements, 9.0);
  std::vector<int> neighbours(repeated.elements.size(), 0);
  for (const PairRecord& p : pairs) {
    ++neighbours[static_cast<std::size_t>(p.i)];
    ++neighbours[static_cast<std::size_t>(p.j)];
    EXPECT_TRUE(std::abs(p.measurement.distance - 8.0) < 0.01 ||
                std::abs(p.measurement.distance - 4.0) < 0.01)
        << p.measurement.distance;
  }
  for (int n : neighbours) EXPECT_EQ(n, 4);
}

}  // namespace
}  // namespace shapeproc::geometry
