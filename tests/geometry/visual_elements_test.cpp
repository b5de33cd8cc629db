// Elements as seen, called directly on a scene (the SVG reader's tests draw files): pieces whose
// ink meets join, pieces apart stay apart, and a tile's border cut is mended.
#include "libshapeproc/geometry/visual_elements.hpp"

#include <gtest/gtest.h>

namespace shapeproc::geometry {
namespace {

Path2 square(double x, double y, double side) {
  Path2 path;
  const Vec2 a(x, y), b(x + side, y), c(x + side, y + side), d(x, y + side);
  path.segments = {Segment2::line(a, b), Segment2::line(b, c), Segment2::line(c, d),
                   Segment2::line(d, a)};
  path.closed = true;
  return path;
}

// One element holding the given subpaths as one filled drawable.
Scene scene_of(const std::vector<Path2>& paths, double side = 100) {
  Drawable2 drawable;
  drawable.paths = paths;
  drawable.style["fill"] = "#000000";
  Scene scene;
  scene.dimension = 2;
  scene.window = Box3(Vec3(0, 0, 0), Vec3(side, side, 0));
  scene.categories = {{"ink"}};
  Shape shape;
  shape.geometry = PlanarShape{{drawable}};
  scene.shapes = {shape};
  scene.elements = {{0, 0, Vec3::Zero()}};
  return scene;
}

TEST(VisualElementsDirect, SeparatePiecesTouchingPiecesAndATileCut) {
  // Three squares apart, two of them sharing an edge: two elements from three subpaths.
  const VisualElements seen =
      visual_elements(scene_of({square(10, 10, 5), square(15, 10, 5), square(50, 50, 5)}), {});
  EXPECT_EQ(seen.subpaths, 3u);
  EXPECT_EQ(seen.scene.elements.size(), 2u);
  // As a tile, a square cut by the left and right borders is one element; without, two.
  const Scene cut = scene_of({square(0, 40, 5), square(95, 40, 5)});
  VisualOptions tile;
  tile.tile = true;
  EXPECT_EQ(visual_elements(cut, tile).scene.elements.size(), 1u);
  EXPECT_EQ(visual_elements(cut, {}).scene.elements.size(), 2u);
  // Kept elements: the given element's subpaths start joined.
  VisualOptions keep;
  keep.keep_elements = true;
  EXPECT_EQ(
      visual_elements(scene_of({square(10, 10, 5), square(50, 50, 5)}), keep).scene.elements.size(),
      1u);
}

}  // namespace
}  // namespace shapeproc::geometry
