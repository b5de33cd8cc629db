// The exemplars shipped in data/ read as data/README.md says.
#include <gtest/gtest.h>

#include "libshapeproc/io/scene_io.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

struct Shipped {
  const char* file;
  const char* options;  // "split", "fill", "layer", "window", "separate", "tile" or ""
  std::size_t elements;
  std::size_t categories;
};

class ShippedData : public ::testing::TestWithParam<Shipped> {};

TEST_P(ShippedData, ElementAndCategoryCounts) {
  const Shipped& s = GetParam();
  ReaderOptions options;
  const std::string o = s.options;
  if (o == "split") options.split_subpaths = true;
  if (o == "fill") options.category_by = CategoryRule::parse("fill");
  if (o == "layer") options.category_by = CategoryRule::parse("layer");
  if (o == "window") options.window = WindowOption::parse("0,100,0,100");
  if (o == "separate") options.nested_separate = true;
  if (o == "tile") options.tile = true;
  const geometry::Scene scene = read_scene(testing::data_path(s.file), options);
  EXPECT_EQ(scene.elements.size(), s.elements);
  EXPECT_EQ(scene.categories.size(), s.categories);
  for (std::size_t i = 0; i < scene.elements.size(); ++i) {
    // Every element lies in the window (the generators keep margins).
    EXPECT_TRUE(scene.window.contains(geometry::bounding_box(scene.placed_shape(i))))
        << s.file << " " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Files, ShippedData,
    ::testing::Values(
        Shipped{"svg/dots-random.svg", "", 30, 1}, Shipped{"svg/dashes-rows.svg", "", 29, 1},
        Shipped{"svg/crescents-grid.svg", "", 25, 1}, Shipped{"svg/two-kinds.svg", "fill", 34, 2},
        Shipped{"svg/two-kinds.svg", "layer", 34, 2}, Shipped{"svg/rings.svg", "split", 19, 1},
        Shipped{"svg/rings.svg", "", 14, 1},  // as seen: five dots sit in rings' holes
        Shipped{"svg/rings.svg", "separate", 19, 1},
        Shipped{"third-party/hero-patterns/bubbles.svg", "tile", 17, 1},
        Shipped{"third-party/hero-patterns/tic-tac-toe.svg", "", 4, 1},
        Shipped{"third-party/hero-patterns/bubbles.svg", "split", 17, 1},
        Shipped{"third-party/hero-patterns/tic-tac-toe.svg", "split", 4, 1},
        Shipped{"points/clusters.csv", "window", 39, 2}, Shipped{"mesh/pebbles.obj", "", 12, 1}));

TEST(ShippedData, BubblesAreCirclesOfTheRadiiDrawn) {
  ReaderOptions options;
  options.split_subpaths = true;
  const geometry::Scene scene =
      read_scene(testing::data_path("third-party/hero-patterns/bubbles.svg"), options);
  // Hero Patterns' bubbles use radii 2, 3, 4, 5 and 7: bounding boxes are 2r squares.
  std::multiset<int> radii;
  for (const auto& shape : scene.shapes) {
    const geometry::Vec3 sizes = geometry::bounding_box(shape).sizes();
    EXPECT_NEAR(sizes.x(), sizes.y(), 1e-9);
    radii.insert(static_cast<int>(std::lround(sizes.x() / 2 * 1000)));
  }
  for (int r : radii)
    EXPECT_TRUE(r == 2000 || r == 3000 || r == 4000 || r == 5000 || r == 7000) << r;
}

}  // namespace
}  // namespace shapeproc::io
