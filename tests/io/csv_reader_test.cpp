#include "libshapeproc/io/csv_reader.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::io {
namespace {

ReaderOptions window(const std::string& text) {
  ReaderOptions options;
  options.window = WindowOption::parse(text);
  return options;
}

TEST(CsvPoints, ReadsPointsAndCategoriesInAnyColumnOrder) {
  const geometry::Scene scene = parse_csv_points(
      "category,y,x,id\nred,1,2,a\nblue,3,4,b\r\nred,5,6,c\n\n", "p.csv", window("0,10,0,10"));
  EXPECT_EQ(scene.dimension, 2);
  ASSERT_EQ(scene.elements.size(), 3u);
  EXPECT_EQ(scene.elements[1].position, geometry::Vec3(4, 3, 0));
  ASSERT_EQ(scene.categories.size(), 2u);
  EXPECT_EQ(scene.categories[scene.elements[2].category].name, "red");
  EXPECT_EQ(geometry::dimension(scene.shapes.at(0)), 0);
  EXPECT_DOUBLE_EQ(scene.window_measure(), 100.0);
}

TEST(CsvPoints, ThreeDimensional) {
  const geometry::Scene scene = parse_csv_points("x,y,z\n1,2,3\n", "p.csv", window("0,4,0,4,0,4"));
  EXPECT_EQ(scene.dimension, 3);
  EXPECT_EQ(scene.categories.at(0).name, "default");
  EXPECT_DOUBLE_EQ(scene.window_measure(), 64.0);
}

TEST(CsvPoints, ARadiusColumnMakesDiscsOneShapePerRadius) {
  const geometry::Scene scene = parse_csv_points("x,y,category,radius\n2,2,a,1\n6,6,b,2\n8,2,a,1\n",
                                                 "d.csv", window("0,10,0,10"));
  ASSERT_EQ(scene.elements.size(), 3u);
  ASSERT_EQ(scene.shapes.size(), 2u);
  EXPECT_EQ(scene.elements[0].shape, scene.elements[2].shape);
  EXPECT_NE(scene.elements[0].shape, scene.elements[1].shape);
  const geometry::Box3 box = geometry::bounding_box(scene.shapes[scene.elements[1].shape]);
  EXPECT_NEAR(box.sizes().x(), 4.0, 1e-9);
  EXPECT_NEAR(box.sizes().y(), 4.0, 1e-9);
  EXPECT_NEAR(box.center().x(), 0.0, 1e-9);
  EXPECT_EQ(geometry::dimension(scene.shapes[0]), 2);
}

struct BadCsv {
  const char* name;
  const char* text;
  const char* window;
  const char* message;
  int line;
};

class CsvBadInput : public ::testing::TestWithParam<BadCsv> {};

TEST_P(CsvBadInput, ThrowsWithLine) {
  const BadCsv& bad = GetParam();
  ReaderOptions options;
  if (*bad.window) options.window = WindowOption::parse(bad.window);
  try {
    parse_csv_points(bad.text, "pts.csv", options);
    FAIL() << bad.name;
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.line(), bad.line) << e.what();
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("pts.csv", 0), 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CsvBadInput,
    ::testing::Values(BadCsv{"empty", "", "0,1,0,1", "empty", 0},
                      BadCsv{"no_window", "x,y\n1,1\n", "", "needs window", 0},
                      BadCsv{"wrong_dimension", "x,y,z\n1,1,1\n", "0,2,0,2", "3D", 0},
                      BadCsv{"no_x", "a,y\n1,1\n", "0,2,0,2", "x and y", 1},
                      BadCsv{"bad_number", "x,y\n1,1\n1,abc\n", "0,2,0,2", "got 'abc'", 3},
                      BadCsv{"nan", "x,y\nnan,1\n", "0,2,0,2", "finite", 2},
                      BadCsv{"short_row", "x,y\n1\n", "0,2,0,2", "expected 2 fields", 2},
                      BadCsv{"outside", "x,y\n1,1\n5,1\n", "0,2,0,2", "outside", 3},
                      BadCsv{"header_only", "x,y\n", "0,2,0,2", "no points", 0},
                      BadCsv{"duplicate_column", "x,x,y\n1,1,1\n", "0,2,0,2", "twice", 1},
                      BadCsv{"zero_radius", "x,y,radius\n1,1,0\n", "0,2,0,2", "positive", 2},
                      BadCsv{"bad_radius", "x,y,radius\n1,1,r\n", "0,2,0,2", "got 'r'", 2},
                      BadCsv{"huge_radius", "x,y,radius\n1,1,1e300\n", "0,2,0,2",
                             "larger than 10 times", 2},
                      BadCsv{"radius_3d", "x,y,z,radius\n1,1,1,1\n", "0,2,0,2,0,2", "2D", 1}),
    [](const ::testing::TestParamInfo<BadCsv>& param_info) {
      return std::string(param_info.param.name);
    });

}  // namespace
}  // namespace shapeproc::io
