// The scene writers: a CSV's exact rows and an SVG's provenance.
#include "libshapeproc/io/scene_writers.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "libshapeproc/io/points_scene.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

TEST(SceneWriters, CsvRowsExactlyAndQuotedNames) {
  geometry::Scene scene;
  scene.dimension = 2;
  scene.categories = {{"plain"}, {"with, comma"}};
  scene.shapes.resize(2);
  scene.elements = {{0, 0, geometry::Vec3(1.5, 2, 0)}, {1, 1, geometry::Vec3(10, 0.25, 0)}};
  std::ostringstream out;
  write_csv(scene, out);
  EXPECT_EQ(out.str(), "x,y,category,shape\n1.5,2,plain,0\n10,0.25,\"with, comma\",1\n");
}

TEST(SceneWriters, SvgCarriesItsProvenanceAndReadsBack) {
  const geometry::Scene scene = read_scene(testing::data_path("svg/dots-random.svg"), {});
  std::ostringstream out;
  write_svg(scene, out, Provenance{R"({"tool":"test"})"});
  const std::string svg = out.str();
  EXPECT_NE(svg.find("<metadata id=\"shapeproc\">"), std::string::npos);
  EXPECT_NE(svg.find("&quot;tool&quot;:&quot;test&quot;"), std::string::npos);
  const testing::TempDir dir;
  const auto file = dir.write("again.svg", svg);
  EXPECT_EQ(read_scene(file, {}).elements.size(), scene.elements.size());
}

// Points written as SVG dots read back as points, at their positions, in their categories: an
// output of a CSV point exemplar measures as the exemplar does (shape distance = centre distance).
TEST(SceneWriters, SvgPointsReadBackAsPoints) {
  PointsInput input;
  input.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(100, 50, 0));
  input.positions = {geometry::Vec3(10, 10, 0), geometry::Vec3(12.5, 40, 0)};
  input.categories = {0, 1};
  input.category_names = {"on", "off"};
  const geometry::Scene points = points_scene(input);
  std::ostringstream out;
  write_svg(points, out, {});
  const testing::TempDir dir;
  const geometry::Scene back = read_scene(dir.write("points.svg", out.str()), {});
  ASSERT_EQ(back.elements.size(), 2u);
  ASSERT_EQ(back.shapes.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<geometry::PointShape>(back.shapes[0].geometry));
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(back.elements[i].position.x(), points.elements[i].position.x(), 1e-9);
    EXPECT_NEAR(back.elements[i].position.y(), points.elements[i].position.y(), 1e-9);
    EXPECT_EQ(back.categories[static_cast<std::size_t>(back.elements[i].category)].name,
              input.category_names[i]);
  }
}

}  // namespace
}  // namespace shapeproc::io
