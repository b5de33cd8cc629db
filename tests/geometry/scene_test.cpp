#include "libshapeproc/geometry/scene.hpp"

#include <gtest/gtest.h>

namespace shapeproc::geometry {
namespace {

Shape square_shape(double x, double y, double side) {
  Path2 path;
  const Vec2 c[4] = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  for (int i = 0; i < 4; ++i) path.segments.push_back(Segment2::line(c[i], c[(i + 1) % 4]));
  path.closed = true;
  Drawable2 drawable;
  drawable.paths.push_back(path);
  return Shape{PlanarShape{{drawable}}, "square"};
}

TEST(Scene, ElementsStoreCentredShapesAndBoundingBoxCentres) {
  Scene scene;
  scene.window = Box3(Vec3(0, 0, 0), Vec3(10, 20, 0));
  const int category = scene.category_index("squares");
  EXPECT_EQ(scene.category_index("squares"), category);
  add_element(scene, square_shape(2, 4, 2), category);
  ASSERT_EQ(scene.elements.size(), 1u);
  EXPECT_EQ(scene.elements[0].position, Vec3(3, 5, 0));
  const Box3 local = bounding_box(scene.shapes[0]);
  EXPECT_EQ(local.center(), Vec3::Zero());
  const Box3 placed = bounding_box(scene.placed_shape(0));
  EXPECT_EQ(placed.min(), Vec3(2, 4, 0));
  EXPECT_EQ(placed.max(), Vec3(4, 6, 0));
  EXPECT_DOUBLE_EQ(scene.window_measure(), 200.0);
  EXPECT_EQ(primitive_count(scene.shapes[0]), 4u);
  EXPECT_EQ(category_counts(scene), std::vector<std::size_t>{1});
}

TEST(Scene, VolumeIn3D) {
  Scene scene;
  scene.dimension = 3;
  scene.window = Box3(Vec3(0, 0, 0), Vec3(2, 3, 4));
  EXPECT_DOUBLE_EQ(scene.window_measure(), 24.0);
}

}  // namespace
}  // namespace shapeproc::geometry
