#include "libshapeproc/io/svg_reader.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::io {
namespace {

using geometry::Box3;
using geometry::Drawable2;
using geometry::PlanarShape;
using geometry::Scene;
using geometry::Vec2;
using geometry::Vec3;

const char* kOpen =
    R"(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" )"
    R"(xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" viewBox="0 0 100 100">)";

// Groups or lone drawables as elements unless a test asks otherwise: these scenes place shapes
// on top of each other, which visual reading would join.
ReaderOptions groups_rule() {
  ReaderOptions options;
  options.elements = ElementRule::groups;
  return options;
}

Scene read(const std::string& body, const ReaderOptions& options = groups_rule()) {
  return parse_svg(std::string(kOpen) + body + "</svg>", "test.svg", options);
}

const PlanarShape& planar(const Scene& scene, std::size_t element) {
  return std::get<PlanarShape>(scene.shapes.at(scene.elements.at(element).shape).geometry);
}

// Placed path segments of an element's first part, as end points.
std::vector<Vec2> end_points(const Scene& scene, std::size_t element) {
  const auto shape = scene.placed_shape(element);
  std::vector<Vec2> points;
  for (const auto& path : std::get<PlanarShape>(shape.geometry).parts.at(0).paths) {
    points.push_back(path.start_point());
    for (const auto& s : path.segments) points.push_back(s.end);
  }
  return points;
}

Box3 placed_box(const Scene& scene, std::size_t element) {
  return geometry::bounding_box(scene.placed_shape(element));
}

void expect_points_near(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_LT((a[i] - b[i]).norm(), 1e-12) << i;
}

TEST(SvgPath, AbsoluteRelativeAndOrthogonalFormsAgree) {
  const Scene scene = read(R"(<path d="M10 10 L20 10 L20 20 Z"/><path d="m10 10 l10 0 0 10z"/>)"
                           R"(<path d="M10 10H20V20z"/><path d="m10 10h10v10z"/>)");
  ASSERT_EQ(scene.elements.size(), 4u);
  const auto reference = end_points(scene, 0);
  EXPECT_EQ(reference.size(), 4u);  // M, L, L, closing line
  for (std::size_t i = 1; i < 4; ++i) expect_points_near(end_points(scene, i), reference);
  EXPECT_TRUE(planar(scene, 0).parts[0].paths[0].closed);
}

TEST(SvgPath, MinifiedNumbers) {
  const Scene scene = read(R"(<path d="M2-1.79.5.5l1e1-0 .5.5"/>)");
  expect_points_near(end_points(scene, 0), {{2, -1.79}, {0.5, 0.5}, {10.5, 0.5}, {11, 1}});
}

TEST(SvgPath, SmoothCurvesReflectControlPoints) {
  const Scene scene = read(R"(<path d="M0 0C0 1 1 1 1 0S2-1 2 0"/><path d="M0 0Q1 1 2 0T4 0"/>)");
  const auto& cubic = planar(scene, 0).parts[0].paths[0].segments;
  ASSERT_EQ(cubic.size(), 2u);
  const Vec3 offset = scene.elements[0].position;
  EXPECT_LT((cubic[1].control1 + offset.head<2>() - Vec2(1, -1)).norm(), 1e-12);
  const auto& quadratic = planar(scene, 1).parts[0].paths[0].segments;
  ASSERT_EQ(quadratic.size(), 2u);
  const Vec2 o1 = scene.elements[1].position.head<2>();
  // Q(1,1) elevated: C1 = P0 + 2/3 (Q - P0); T reflects Q to (3, -1).
  EXPECT_LT((quadratic[0].control1 + o1 - Vec2(2.0 / 3, 2.0 / 3)).norm(), 1e-12);
  EXPECT_LT((quadratic[1].control1 + o1 - Vec2(2 + 2.0 / 3, -2.0 / 3)).norm(), 1e-12);
}

TEST(SvgPath, ArcsBecomeCubicsWithExactEnds) {
  const Scene scene =
      read(R"(<path d="M0 50A50 50 0 0 1 100 50"/><path d="M10 10a3 3 0 1006 0"/>)");
  const Box3 box = placed_box(scene, 0);
  EXPECT_NEAR(box.min().y(), 0.0, 1e-9);  // the arc passes through (50, 0)
  EXPECT_NEAR(box.max().x(), 100.0, 1e-12);
  EXPECT_EQ(end_points(scene, 0).back(), Vec2(100, 50));
  // Compact flags "1006" are large-arc 1, sweep 0, x 06.
  EXPECT_LT((end_points(scene, 1).back() - Vec2(16, 10)).norm(), 1e-12);
  EXPECT_NEAR(placed_box(scene, 1).max().y(), 13.0, 1e-9);  // sweep 0 bulges towards +y
}

TEST(SvgShapes, BasicShapesBecomePaths) {
  const Scene scene = read(
      R"(<rect x="1" y="2" width="10" height="5"/><rect x="20" y="20" width="10" height="10" rx="2"/>)"
      R"(<circle cx="50" cy="50" r="5"/><ellipse cx="80" cy="20" rx="6" ry="3"/>)"
      R"(<line x1="0" y1="90" x2="10" y2="95"/><polyline points="20,90 30,90 30,95"/>)"
      R"(<polygon points="40 90,50 90,45 99"/>)");
  ASSERT_EQ(scene.elements.size(), 7u);
  EXPECT_EQ(planar(scene, 0).parts[0].paths[0].segments.size(), 4u);
  EXPECT_EQ(placed_box(scene, 0).min(), Vec3(1, 2, 0));
  EXPECT_EQ(scene.elements[0].position, Vec3(6, 4.5, 0));
  EXPECT_EQ(planar(scene, 1).parts[0].paths[0].segments.size(), 8u);
  EXPECT_NEAR(placed_box(scene, 2).min().x(), 45, 1e-12);
  EXPECT_NEAR(placed_box(scene, 3).max().y(), 23, 1e-12);
  EXPECT_FALSE(planar(scene, 4).parts[0].paths[0].closed);
  EXPECT_EQ(planar(scene, 5).parts[0].paths[0].segments.size(), 2u);
  EXPECT_FALSE(planar(scene, 5).parts[0].paths[0].closed);
  EXPECT_EQ(planar(scene, 6).parts[0].paths[0].segments.size(), 3u);
  EXPECT_TRUE(planar(scene, 6).parts[0].paths[0].closed);
}

TEST(SvgStructure, TransformsComposeDownTheTree) {
  const Scene scene = read(R"(<g transform='translate(10,0)'><g transform='scale(2)'>)"
                           R"(<rect width="1" height="1" transform='rotate(90)'/></g></g>)");
  ASSERT_EQ(scene.elements.size(), 1u);
  const Box3 box = placed_box(scene, 0);
  EXPECT_NEAR(box.min().x(), 8, 1e-12);
  EXPECT_NEAR(box.max().x(), 10, 1e-12);
  EXPECT_NEAR(box.max().y(), 2, 1e-12);
}

TEST(SvgStructure, NestedSvgIsAContainerAtItsPosition) {
  const Scene scene = read(
      R"x(<svg x="20" y="30"><rect width="2" height="2"/><rect x="5" width="2" height="2"/></svg>)x");
  ASSERT_EQ(scene.elements.size(), 2u);
  EXPECT_EQ(scene.elements[0].position, Vec3(21, 31, 0));
  EXPECT_EQ(scene.elements[1].position, Vec3(26, 31, 0));
}

TEST(SvgStructure, UseDrawsItsTargetPlaced) {
  const Scene scene =
      read(R"(<defs><rect id="r" width="2" height="2" fill="red"/></defs>)"
           R"(<use href="#r" x="5" y="5"/><use xlink:href="#r" transform='translate(10,0)'/>)");
  ASSERT_EQ(scene.elements.size(), 2u);
  EXPECT_EQ(scene.elements[0].position, Vec3(6, 6, 0));
  EXPECT_EQ(scene.elements[1].position, Vec3(11, 1, 0));
  EXPECT_EQ(planar(scene, 0).parts[0].style.at("fill"), "red");
}

TEST(SvgStructure, InkscapeGroupingRules) {
  const std::string body =
      R"(<g inkscape:groupmode="layer" inkscape:label="L1"><circle r="1" cx="5" cy="5"/>)"
      R"(<g><rect width="1" height="1"/><rect x="3" width="1" height="1"/></g></g>)"
      R"(<rect x="50" width="1" height="1"/><g style="display:none"><rect width="9" height="9"/></g>)";
  const Scene scene = read(body);
  ASSERT_EQ(scene.elements.size(), 3u);  // circle, the group (one element), lone rect
  EXPECT_EQ(planar(scene, 1).parts.size(), 2u);
  ReaderOptions containers = groups_rule();
  containers.groups = GroupMode::container;
  EXPECT_EQ(read(body, containers).elements.size(), 4u);
}

TEST(SvgStructure, SplitSubpathsMakesPiecesOfAPath) {
  const std::string body =
      R"(<path fill-rule="evenodd" d="M0 0h20v20h-20z M5 5h10v10h-10z M8 8h4v4h-4z M40 0h5v5h-5z"/>)";
  EXPECT_EQ(read(body).elements.size(), 1u);
  ReaderOptions split = groups_rule();
  split.split_subpaths = true;
  const Scene scene = read(body, split);
  ASSERT_EQ(scene.elements.size(), 3u);  // square with hole, dot in the hole, far square
  EXPECT_EQ(planar(scene, 0).parts[0].paths.size(), 2u);
  EXPECT_EQ(planar(scene, 0).parts[0].fill_rule, geometry::FillRule::evenodd);
}

TEST(SvgWindow, WindowRectThenViewBoxThenSize) {
  const Scene with_rect = read(
      R"(<rect id="window" x="10" y="10" width="50" height="40"/><circle r="1" cx="20" cy="20"/>)");
  EXPECT_EQ(with_rect.elements.size(), 1u);
  EXPECT_EQ(with_rect.window.min(), Vec3(10, 10, 0));
  EXPECT_EQ(with_rect.window.max(), Vec3(60, 50, 0));
  const Scene view_box = read(R"(<circle r="1" cx="20" cy="20"/>)");
  EXPECT_EQ(view_box.window.max(), Vec3(100, 100, 0));
  const Scene sized = parse_svg(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="30mm" height="20mm"><circle r="1" cx="2" cy="2"/></svg>)",
      "sized.svg", {});
  EXPECT_NEAR(sized.window.max().x(), 30 * 96 / 25.4, 1e-9);
  const Scene mm = parse_svg(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="30mm" height="20mm" viewBox="0 0 30 20"><circle r="1" cx="2" cy="2"/></svg>)",
      "mm.svg", {});
  EXPECT_EQ(mm.units, "mm");
}

TEST(SvgStyle, InheritanceSheetsAndStyleAttributes) {
  const Scene scene = parse_svg(
      R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10" fill="#00f" stroke-width="2">)"
      R"(<style>.warm { fill: orange } #special { stroke: green }</style>)"
      R"(<rect width="1" height="1"/><rect class="warm" width="1" height="1"/>)"
      R"(<rect class="warm" style="fill:red" fill="black" width="1" height="1"/>)"
      R"(<g transform='scale(3)' color="purple"><rect id="special" fill="currentColor" width="1" height="1"/></g>)"
      R"(<g fill-rule="evenodd" opacity=".5"><rect width="1" height="1" opacity=".5"/></g></svg>)",
      "style.svg", {});
  ASSERT_EQ(scene.elements.size(), 5u);
  EXPECT_EQ(planar(scene, 0).parts[0].style.at("fill"), "#00f");
  EXPECT_EQ(planar(scene, 1).parts[0].style.at("fill"), "orange");
  EXPECT_EQ(planar(scene, 2).parts[0].style.at("fill"), "red");
  const auto& special = planar(scene, 3).parts[0].style;
  EXPECT_EQ(special.at("fill"), "purple");
  // The stroke is ink of its own: a part filled green, as wide as the stroke scaled with the
  // geometry (a 3 x 3 square with a stroke of 6: 9 x 9).
  ASSERT_EQ(planar(scene, 3).parts.size(), 2u);
  EXPECT_EQ(special.at("stroke"), "none");
  EXPECT_EQ(planar(scene, 3).parts[1].style.at("fill"), "green");
  EXPECT_NEAR(geometry::bounding_box(scene.shapes.at(scene.elements.at(3).shape)).sizes().x(), 9.0,
              1e-9);
  EXPECT_EQ(planar(scene, 4).parts[0].fill_rule, geometry::FillRule::evenodd);
  EXPECT_EQ(planar(scene, 4).parts[0].style.at("opacity"), "0.25");
}

TEST(SvgCategories, EveryRule) {
  const std::string body =
      R"(<g inkscape:groupmode="layer" inkscape:label="front">)"
      R"(<rect class="a" data-kind="x" fill="red" width="1" height="1"/>)"
      R"(<rect class="b" data-kind="y" fill="#ff0000" stroke="blue" width="1" height="1"/></g>)"
      R"(<g inkscape:groupmode="layer" inkscape:label="back" data-kind="z"><rect class="a" fill="#00f" width="1" height="1"/></g>)";
  auto names = [&](const std::string& rule) {
    ReaderOptions options = groups_rule();
    options.category_by = CategoryRule::parse(rule);
    const Scene scene = read(body, options);
    std::vector<std::string> result;
    for (const auto& e : scene.elements) result.push_back(scene.categories[e.category].name);
    return result;
  };
  EXPECT_EQ(names("none"), (std::vector<std::string>{"default", "default", "default"}));
  EXPECT_EQ(names("fill"), (std::vector<std::string>{"#ff0000", "#ff0000", "#0000ff"}));
  EXPECT_EQ(names("stroke"), (std::vector<std::string>{"none", "#0000ff", "none"}));
  EXPECT_EQ(names("class"), (std::vector<std::string>{"a", "b", "a"}));
  EXPECT_EQ(names("layer"), (std::vector<std::string>{"front", "front", "back"}));
  EXPECT_EQ(names("attr:data-kind"), (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_THROW(CategoryRule::parse("colour"), core::UsageError);
}

}  // namespace
}  // namespace shapeproc::io
