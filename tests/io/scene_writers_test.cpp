// The scene writers: a CSV's exact rows and an SVG's provenance.
#include "libshapeproc/io/scene_writers.hpp"

#include <gtest/gtest.h>

#include <sstream>

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

}  // namespace
}  // namespace shapeproc::io
