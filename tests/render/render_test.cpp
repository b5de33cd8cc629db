#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/png_reader.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/render/interaction_plot.hpp"
#include "libshapeproc/render/png_text.hpp"
#include "libshapeproc/render/raster.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::render {
namespace {

// A 100 x 50 window with a black 20 x 20 square whose top-left corner is at (10, 10).
geometry::Scene square_scene(const testing::TempDir& dir) {
  const auto file = dir.write(
      "square.svg",
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50" viewBox="0 0 100 50">
  <rect x="10" y="10" width="20" height="20" fill="black"/></svg>)");
  return io::read_scene(file, {});
}

TEST(Rasterize, FilledShapesCoverTheirArea) {
  const testing::TempDir dir;
  const geometry::Scene scene = square_scene(dir);
  const geometry::Raster mask = rasterize_filled(scene, scene.window, 200, 100);
  ASSERT_EQ(mask.width, 200);
  ASSERT_EQ(mask.height, 100);
  double covered = 0.0;
  for (float v : mask.values) covered += v;
  // 400 of 5000 units², at 4 pixels per unit².
  EXPECT_NEAR(covered, 400.0 * 4, 1.0);
  EXPECT_FLOAT_EQ(mask.sample(scene.window, geometry::Vec2(20, 20)), 1.0f);
  EXPECT_FLOAT_EQ(mask.sample(scene.window, geometry::Vec2(50, 20)), 0.0f);
  EXPECT_FLOAT_EQ(mask.sample(scene.window, geometry::Vec2(-1, 20)), 0.0f);
}

TEST(WritePng, DrawsAtTheAskedScaleAndCarriesItsText) {
  const testing::TempDir dir;
  const geometry::Scene scene = square_scene(dir);
  RenderOptions options;
  options.scale = 3.0;  // pixels per unit
  options.draw_window = false;
  options.text = {{"Comment", "seed 7"}, {"Source", "shapeproc sample m.json --seed 7"}};
  write_png(scene, dir.file("out.png"), options);
  const geometry::Raster picture = io::read_grayscale_png(dir.file("out.png"));
  EXPECT_EQ(picture.width, 300);
  EXPECT_EQ(picture.height, 150);
  EXPECT_LT(picture.sample(scene.window, geometry::Vec2(20, 20)), 0.1f);  // the black square
  EXPECT_GT(picture.sample(scene.window, geometry::Vec2(60, 20)), 0.9f);  // white paper
  EXPECT_EQ(read_png_text(testing::read_file(dir.file("out.png"))), options.text);
  // Without text, no chunk.
  write_png(scene, dir.file("plain.png"), {});
  EXPECT_TRUE(read_png_text(testing::read_file(dir.file("plain.png"))).empty());
}

TEST(PngText, RejectsBadKeywordsAndBytesThatAreNotAPng) {
  EXPECT_THROW(add_png_text("not a png", {{"Comment", "x"}}), core::ArgumentError);
  const testing::TempDir dir;
  const geometry::Scene scene = square_scene(dir);
  write_png(scene, dir.file("p.png"), {});
  const std::string png = testing::read_file(dir.file("p.png"));
  EXPECT_THROW(add_png_text(png, {{"", "x"}}), core::ArgumentError);
  EXPECT_THROW(add_png_text(png, {{std::string(80, 'k'), "x"}}), core::ArgumentError);
}

// Two axes of two bands each: every axis is drawn on both of its opposite directions, as a black
// hard-core sector and one sector per band whose title names the axis, the band, its γ and its
// thresholds.
TEST(InteractionPlot, DrawsOneCurvePerAxisOfEveryPair) {
  model::ShapeProcessModel m;
  m.dimension = 2;
  m.categories = {{"dots", 0.01}};
  m.measurement.directions = 4;
  model::PairInteraction pair;
  model::AxisParameters axis;
  axis.direction = geometry::Vec3(1, 0, 0);
  axis.thresholds = {1.0, 2.0, 3.0};
  axis.gammas = {0.5, 2.0};
  model::AxisParameters other = axis;
  other.direction = geometry::Vec3(0, 1, 0);
  other.gammas = {3.0, 1.0};
  pair.axes = {axis, other};
  m.interactions = {pair};
  const std::string svg = interaction_plot_svg(m);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("dots - dots"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(testing::count_of(svg, "<title>axis "), 8u);  // 2 axes x 2 directions x 2 bands
  EXPECT_EQ(testing::count_of(svg, "<title>axis 0 band 1: gamma 0.5 on [1, 2)</title>"), 2u);
  EXPECT_EQ(testing::count_of(svg, "<title>axis 0 band 2: gamma 2 on [2, 3)</title>"), 2u);
  EXPECT_EQ(testing::count_of(svg, "<title>axis 1 band 1: gamma 3 on [1, 2)</title>"), 2u);
  EXPECT_EQ(testing::count_of(svg, "<title>axis 1 band 2: gamma 1 on [2, 3)</title>"), 2u);
  // Hard-core sectors: 4, and the legend's swatch.
  EXPECT_EQ(testing::count_of(svg, "fill=\"black\""), 5u);
  // γ = 1 is drawn white, and inhibition and attraction in other colours.
  EXPECT_NE(svg.find("fill=\"#ffffff\" stroke=\"#555\" stroke-width=\"0.3\"><title>axis 1 band 2"),
            std::string::npos);

  // A category name from an input file (`class`, `attr:NAME`) is text, never markup: a name
  // holding a script reaches the plot a user opens in a browser escaped.
  m.categories[0].name = "<script>alert(\"1\")</script> & co";
  const std::string hostile = interaction_plot_svg(m);
  EXPECT_EQ(hostile.find("<script"), std::string::npos);
  EXPECT_NE(hostile.find("&lt;script&gt;alert(&quot;1&quot;)&lt;/script&gt; &amp; co"),
            std::string::npos);
}

}  // namespace
}  // namespace shapeproc::render
