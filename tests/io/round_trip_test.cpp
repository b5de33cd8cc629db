// Reading what was written gives the same elements, for every writer.
#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

using geometry::Scene;

void expect_same_elements(const Scene& a, const Scene& b, double tolerance) {
  ASSERT_EQ(a.elements.size(), b.elements.size());
  ASSERT_EQ(a.dimension, b.dimension);
  EXPECT_LE((a.window.min() - b.window.min()).norm(), tolerance);
  EXPECT_LE((a.window.max() - b.window.max()).norm(), tolerance);
  for (std::size_t i = 0; i < a.elements.size(); ++i) {
    EXPECT_LE((a.elements[i].position - b.elements[i].position).norm(), tolerance) << i;
    EXPECT_EQ(a.categories[a.elements[i].category].name, b.categories[b.elements[i].category].name)
        << i;
    const auto& sa = a.shapes[a.elements[i].shape];
    const auto& sb = b.shapes[b.elements[i].shape];
    EXPECT_EQ(geometry::primitive_count(sa), geometry::primitive_count(sb)) << i;
    const auto box_a = geometry::bounding_box(sa), box_b = geometry::bounding_box(sb);
    EXPECT_LE((box_a.min() - box_b.min()).norm(), tolerance) << i;
    EXPECT_LE((box_a.max() - box_b.max()).norm(), tolerance) << i;
  }
}

TEST(RoundTrip, SvgKeepsGeometryStylesAndCategories) {
  const testing::TempDir dir;
  ReaderOptions options;
  options.category_by = CategoryRule::parse("fill");
  const Scene original = read_scene(testing::data_path("svg/two-kinds.svg"), options);
  write_scene(original, dir.file("out.svg"), Provenance{R"({"test":true})"});
  ReaderOptions back;
  back.category_by = CategoryRule::parse("attr:data-category");
  const Scene reread = read_scene(dir.file("out.svg"), back);
  expect_same_elements(original, reread, 1e-9);
  // Styles and fill rules survive.
  const auto& p0 = std::get<geometry::PlanarShape>(original.shapes[0].geometry).parts[0];
  const auto& q0 = std::get<geometry::PlanarShape>(reread.shapes[0].geometry).parts[0];
  EXPECT_EQ(p0.style, q0.style);
  EXPECT_EQ(p0.fill_rule, q0.fill_rule);
  EXPECT_NE(testing::read_file(dir.file("out.svg")).find(R"(<metadata id="shapeproc">)"),
            std::string::npos);
}

TEST(RoundTrip, SvgMultiPartElementsAndHoles) {
  const testing::TempDir dir;
  ReaderOptions options;
  options.split_subpaths = true;
  const Scene original = read_scene(testing::data_path("svg/rings.svg"), options);
  write_scene(original, dir.file("rings.svg"), {});
  const Scene reread = read_scene(dir.file("rings.svg"), {});
  expect_same_elements(original, reread, 1e-9);
  const Scene crescents = read_scene(testing::data_path("svg/crescents-grid.svg"), {});
  write_scene(crescents, dir.file("c.svg"), {});
  expect_same_elements(crescents, read_scene(dir.file("c.svg"), {}), 1e-9);
}

TEST(RoundTrip, ObjAndPly) {
  const testing::TempDir dir;
  const Scene original = read_scene(testing::data_path("mesh/pebbles.obj"), {});
  ReaderOptions window;
  window.window = WindowOption{3, original.window};
  for (const char* name : {"out.obj", "out.ply"}) {
    write_scene(original, dir.file(name), Provenance{"{}"});
    expect_same_elements(original, read_scene(dir.file(name), window), 1e-5);
  }
  ReaderOptions groups = window;
  groups.mesh_split = MeshSplit::groups;
  expect_same_elements(original, read_scene(dir.file("out.obj"), groups), 1e-5);
}

TEST(RoundTrip, CsvPlacements) {
  const testing::TempDir dir;
  ReaderOptions options;
  options.window = WindowOption::parse("0,100,0,100");
  const Scene points = read_scene(testing::data_path("points/clusters.csv"), options);
  write_scene(points, dir.file("p.csv"), Provenance{R"({"seed":1})"});
  expect_same_elements(points, read_scene(dir.file("p.csv"), options), 0.0);
  EXPECT_EQ(testing::read_file(dir.file("p.csv.json")), "{\"seed\":1}\n");
  // An SVG scene as placements: reference positions, categories and shape indices.
  const Scene svg = read_scene(testing::data_path("svg/dots-random.svg"), {});
  write_scene(svg, dir.file("dots.csv"), {});
  ReaderOptions svg_window;
  svg_window.window = WindowOption{2, svg.window};
  const Scene placed = read_scene(dir.file("dots.csv"), svg_window);
  ASSERT_EQ(placed.elements.size(), svg.elements.size());
  for (std::size_t i = 0; i < svg.elements.size(); ++i) {
    EXPECT_EQ(placed.elements[i].position, svg.elements[i].position);
  }
  EXPECT_EQ(testing::read_file(dir.file("dots.csv")).substr(0, 19), "x,y,category,shape\n");
}

TEST(Writers, RefuseFormatsThatCannotHoldTheScene) {
  const testing::TempDir dir;
  const Scene svg = read_scene(testing::data_path("svg/dots-random.svg"), {});
  EXPECT_THROW(write_scene(svg, dir.file("x.obj"), {}), core::UsageError);
  EXPECT_THROW(write_scene(svg, dir.file("x.png"), {}), core::UsageError);
  const Scene mesh = read_scene(testing::data_path("mesh/pebbles.obj"), {});
  EXPECT_THROW(write_scene(mesh, dir.file("x.svg"), {}), core::UsageError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.obj")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.svg")));
}

}  // namespace
}  // namespace shapeproc::io
