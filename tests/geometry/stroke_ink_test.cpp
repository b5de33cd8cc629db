// A stroke's ink: a line of width 2 and length 10 with flat caps paints a 10 × 2 rectangle.
#include "libshapeproc/geometry/stroke_ink.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/geometry/path.hpp"

namespace shapeproc::geometry {
namespace {

Drawable2 line(const std::string& width, const std::string& cap) {
  Path2 path;
  path.segments = {Segment2::line(Vec2(0, 0), Vec2(10, 0))};
  Drawable2 d;
  d.paths = {path};
  d.style["stroke"] = "#000000";
  d.style["stroke-width"] = width;
  d.style["fill"] = "none";
  if (!cap.empty()) d.style["stroke-linecap"] = cap;
  return d;
}

double ink_area(const Drawable2& d) {
  double area = 0.0;
  for (const Path2& p : d.paths) area += std::abs(signed_area(flatten(p, 1e-3)));
  return area;
}

TEST(StrokeInk, ALineOfWidthTwoWithFlatAndSquareCaps) {
  EXPECT_TRUE(stroked(line("2", "")));
  const auto flat = stroke_ink(line("2", "butt"), 1e-3);
  ASSERT_TRUE(flat.has_value());
  EXPECT_NEAR(ink_area(*flat), 20.0, 1e-6);
  const auto square = stroke_ink(line("2", "square"), 1e-3);
  ASSERT_TRUE(square.has_value());
  EXPECT_NEAR(ink_area(*square), 24.0, 1e-6);  // half a width beyond each end
  // No stroke colour or no width: nothing painted.
  Drawable2 unstroked = line("2", "");
  unstroked.style["stroke"] = "none";
  EXPECT_FALSE(stroked(unstroked));
  EXPECT_FALSE(stroke_ink(unstroked, 1e-3).has_value());
  EXPECT_FALSE(stroke_ink(line("0", ""), 1e-3).has_value());
}

}  // namespace
}  // namespace shapeproc::geometry
