// Elements as seen (geometry/visual_elements.hpp through the SVG reader): each rule on a small
// hand-made drawing.
#include <gtest/gtest.h>

#include "libshapeproc/io/svg_reader.hpp"

namespace shapeproc::io {
namespace {

using geometry::Scene;

Scene read(const std::string& body, bool tile = false, bool nested_separate = false,
           const char* view_box = "0 0 100 100") {
  ReaderOptions options;
  options.tile = tile;
  options.nested_separate = nested_separate;
  return parse_svg(std::string(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox=")") + view_box +
                       "\">" + body + "</svg>",
                   "visual.svg", options);
}

std::size_t count(const std::string& body, bool tile = false, bool nested_separate = false) {
  return read(body, tile, nested_separate).elements.size();
}

TEST(VisualElements, DotInARingsHoleJoinsItUnlessNestedSeparate) {
  const std::string ring_and_dot =
      R"(<path fill-rule="evenodd" d="M10 10h40v40h-40z M20 20h20v20h-20z M28 28h4v4h-4z"/>)";
  EXPECT_EQ(count(ring_and_dot), 1u);
  EXPECT_EQ(count(ring_and_dot, false, true), 2u);
  // The same with the dot a drawable of its own, and with the ring drawn by nonzero winding.
  EXPECT_EQ(
      count(R"(<path d="M10 10h40v40h-40z M20 20v20h20v-20z"/><circle cx="30" cy="30" r="2"/>)"),
      1u);
  EXPECT_EQ(
      count(R"(<path d="M10 10h40v40h-40z M20 20v20h20v-20z"/><circle cx="30" cy="30" r="2"/>)",
            false, true),
      2u);
}

TEST(VisualElements, GearWithHubAndSeparateDrawablesThatOverlap) {
  // A toothed ring drawn as a ring plus separate teeth that overlap it, and a hub in its hole.
  const std::string gear =
      R"(<path fill-rule="evenodd" d="M30 30h40v40h-40z M40 40h20v20h-20z"/>)"
      R"(<rect x="45" y="25" width="10" height="10"/><rect x="45" y="65" width="10" height="10"/>)"
      R"(<circle cx="50" cy="50" r="4"/><circle cx="90" cy="90" r="3"/>)";
  EXPECT_EQ(count(gear), 2u);               // the gear, the far dot
  EXPECT_EQ(count(gear, false, true), 3u);  // the hub apart
}

TEST(VisualElements, SharedEdgesJoinCornersDoNot) {
  // Two squares sharing an edge are one element; two meeting at a corner stay two.
  EXPECT_EQ(
      count(
          R"(<rect x="10" y="10" width="10" height="10"/><rect x="20" y="10" width="10" height="10"/>)"),
      1u);
  EXPECT_EQ(
      count(
          R"(<rect x="10" y="10" width="10" height="10"/><rect x="20" y="20" width="10" height="10"/>)"),
      2u);
  // A checkerboard of four squares in one path: corners only.
  EXPECT_EQ(
      count(R"(<path d="M0 0h10v10h-10z M10 10h10v10h-10z M20 0h10v10h-10z M30 10h10v10h-10z"/>)"),
      4u);
}

TEST(VisualElements, DifferentCategoriesStayApart) {
  ReaderOptions options;
  options.category_by = CategoryRule::parse("fill");
  const Scene scene = parse_svg(
      R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)"
      R"(<rect fill="red" x="10" y="10" width="10" height="10"/><rect fill="blue" x="15" y="15" width="10" height="10"/>)"
      R"(<rect fill="red" x="18" y="12" width="10" height="10"/></svg>)",
      "categories.svg", options);
  EXPECT_EQ(scene.elements.size(), 2u);  // the red squares overlap; the blue one stays
}

TEST(VisualElements, TileJoinsPiecesCutByEachBorderAndACorner) {
  // A 100 x 100 tile: a bar cut by the left/right border, one cut by the top/bottom border, a
  // square cut at the corner into four pieces, and a whole dot.
  const std::string body =
      R"(<rect x="90" y="40" width="20" height="5"/><rect x="-10" y="40" width="20" height="5"/>)"
      R"(<rect x="40" y="-8" width="5" height="16"/><rect x="40" y="92" width="5" height="16"/>)"
      R"(<rect x="-5" y="-5" width="10" height="10"/><rect x="95" y="-5" width="10" height="10"/>)"
      R"(<rect x="-5" y="95" width="10" height="10"/><rect x="95" y="95" width="10" height="10"/>)"
      R"(<circle cx="60" cy="70" r="4"/>)";
  const Scene tile = read(body, true);
  ASSERT_EQ(tile.elements.size(), 4u);
  double area_sum = 0;
  for (std::size_t i = 0; i < tile.elements.size(); ++i) {
    const geometry::Box3 box = geometry::bounding_box(tile.placed_shape(i));
    // Whole elements: the bar 20 x 5, the bar 5 x 16, the corner square 10 x 10, the dot 8 x 8.
    area_sum += box.sizes().x() * box.sizes().y();
    EXPECT_TRUE(tile.window.contains(tile.elements[i].position)) << i;
  }
  EXPECT_NEAR(area_sum, 100 + 80 + 100 + 64, 1e-6);
  // Without --tile the pieces in the window are separate elements, clipped by nothing.
  EXPECT_EQ(read(body).elements.size(), 9u);
}

TEST(VisualElements, UseAndTransformsArePlacedBeforeJoining) {
  // A ring defined once and used twice, the second use moved onto a dot.
  const std::string body =
      R"(<defs><path id="ring" fill-rule="evenodd" d="M0 0h20v20h-20z M5 5h10v10h-10z"/></defs>)"
      R"svg(<use href="#ring" x="10" y="10"/><use href="#ring" transform="translate(50 50)"/>)svg"
      R"(<circle cx="60" cy="60" r="2"/>)";
  EXPECT_EQ(count(body), 2u);
  EXPECT_EQ(count(body, false, true), 3u);
}

TEST(VisualInk, StrokedBarsAreTheirInk) {
  // Two bars drawn as lines 10 thick, 12 apart between centrelines: a visible gap of 2.
  const Scene bars = read(R"(<path d="M10 10H90" stroke="black" stroke-width="10" fill="none"/>)"
                          R"(<path d="M10 22H90" stroke="black" stroke-width="10" fill="none"/>)");
  ASSERT_EQ(bars.elements.size(), 2u);
  const geometry::Box3 first = geometry::bounding_box(bars.placed_shape(0));
  const geometry::Box3 second = geometry::bounding_box(bars.placed_shape(1));
  EXPECT_NEAR(second.min().y() - first.max().y(), 2.0, 1e-9);
  EXPECT_NEAR(first.sizes().x(), 80.0, 1e-9);  // butt caps end at the path's ends
  // 4 apart between centrelines: their ink overlaps, one element as seen.
  EXPECT_EQ(count(R"(<path d="M10 10H90" stroke="black" stroke-width="10" fill="none"/>)"
                  R"(<path d="M10 14H90" stroke="black" stroke-width="10" fill="none"/>)"),
            1u);
}

TEST(VisualInk, TransformsScaleStrokesUnlessNonScaling) {
  const auto height_of = [](const std::string& extra) {
    const Scene s = read(R"(<path d="M1 5H9" stroke="black" stroke-width="2" fill="none" )"
                         R"svg(transform="scale(4)" )svg" +
                         extra + "/>");
    return geometry::bounding_box(s.placed_shape(0)).sizes().y();
  };
  EXPECT_NEAR(height_of(""), 8.0, 1e-9);
  EXPECT_NEAR(height_of(R"(vector-effect="non-scaling-stroke")"), 2.0, 1e-9);
}

TEST(VisualInk, CapsAndClosedOutlines) {
  const auto width_of = [](const std::string& cap) {
    const Scene s =
        read(R"(<path d="M10 10H50" stroke="black" stroke-width="4" fill="none" stroke-linecap=")" +
             cap + R"("/>)");
    return geometry::bounding_box(s.placed_shape(0)).sizes().x();
  };
  EXPECT_NEAR(width_of("butt"), 40.0, 1e-9);
  EXPECT_NEAR(width_of("square"), 44.0, 1e-9);
  EXPECT_NEAR(width_of("round"), 44.0, 1e-3);
  // A stroked square outline is a frame: a dot in its hole is nested, not overlapping.
  const std::string frame =
      R"(<rect x="20" y="20" width="40" height="40" fill="none" stroke="black" stroke-width="4"/>)"
      R"(<circle cx="40" cy="40" r="3"/>)";
  const Scene joined = read(frame);
  ASSERT_EQ(joined.elements.size(), 1u);
  const geometry::Box3 box = geometry::bounding_box(joined.placed_shape(0));
  EXPECT_NEAR(box.sizes().x(), 44.0, 1e-9);  // mitre joins: the frame's corners are square
  EXPECT_EQ(read(frame, false, true).elements.size(), 2u);
}

TEST(VisualInk, AStrokeOfTheFuzzersRescalingFindingKeepsEveryRing) {
  // The fuzzer's input (tests/fuzz/seeds/svg-boost-rescale-overflow.svg): a stroked path of rings
  // whose arcs reach 6666666666 beside coordinates near 100. Boost.Geometry's overlays rescaled
  // them to 64-bit integers and overflowed: UBSan in the sanitizer build, and in Release an ink
  // outline of 53 rings with one lost. On doubles every ring of the outline stays.
  const std::string d =
      "M116.12 26.694a9 9 0 1 1 0 18a9 9 0 1 1 0 -108zM116.12 30.294a5.4 5.4 0 1 0 0 10.8a5.4 5"
      ".4 0 1 0 0 -10.8zM116.12 33.194a2.5 2.5 0 1 1 0 5a2.5 2.5 0 1 0 0 -5zM171.134 85.646a9 9"
      " 0 1 1 0 18a9 9 0 1 1 0 -18zM171.134 89.246a5.4 5.4 0 1 0 0 10.8a5.4 5.4 0 1 0 0 -10.8zM"
      "46.363 128.784a9 9 0 1 1 0 18a9 9 0 1 1 0 -18zM46.363 132.384a5.4 5.4 0 1 0 0 10.8a5.488"
      "8888888888888888888888888888888888888888888888888888888888888888888888888888888888888888"
      "88888 5.4 0 1 0 0 -10.8zM82.719 148.652a12 12 0 1 1 0 24a12 12 0 1 1 0 -24zM82.719 153.4"
      "52a7.2 7.2 0 1 0 0 14.4a7.2 7.2 0 1 0 0 -14.4zM82.719 158.152a2.5 2.5 0 1 1 0 5a2.5 2.5 "
      "0 1 1 06666666666 -5zM123.466 155.04a9 9 0 1 1 0 18a9 9 0 1 1 0 -19zM123.466 158.64a0.4 "
      "5.4 0 1 0 0 10.8a5.4 6.4 0 1 0 0 -10.8zM140.53 116.797a12 12 0 1 1 0 2432a9 9 0 1 1 0 18"
      "a9 9 0 1 1 0 -18zM162.014 180.032a5.4 5.4 0 1 0 0 10.8a5.4 5.4 0 1 0 0 -10.8zM162.014 18"
      "2.932a2.5 2.5 0 1 1 0 5a2.5 2.5 0 1 1 0 -5zM134.559 60.792a9 9 0 1 1 0 18a9 9 0 1 1 0 -1"
      "8zM134.559 64.392a5.4 5.4 0 1 0 0 10.8a5.4 5.4 0 1 0 0 -10.8z";
  const Scene s =
      read(R"(<path stroke="#000" fill="#2f855a" d=")" + d + R"("/>)", false, false, "0 0 200 200");
  ASSERT_EQ(s.elements.size(), 2u);
  std::size_t rings = 0;
  for (const geometry::Shape& shape : s.shapes) rings += geometry::path_count(shape);
  EXPECT_EQ(rings, 54u);
}

TEST(VisualElements, ReaderNotesWhenSubpathsAndElementsDisagree) {
  // One path of 8 dots inside a big ring's hole: read as seen, one element from 10 subpaths.
  std::string dots;
  for (int i = 0; i < 8; ++i) dots += " M" + std::to_string(30 + 5 * i) + " 50h2v2h-2z";
  const Scene seen =
      read(R"(<path fill-rule="evenodd" d="M5 5h90v90h-90z M10 10h80v80h-80z)" + dots + R"("/>)");
  ASSERT_EQ(seen.elements.size(), 1u);
  ASSERT_EQ(seen.notes.size(), 1u);
  EXPECT_NE(seen.notes[0].find("nested_separate"), std::string::npos);
  // The reverse: two groups holding 4 separate squares each are two elements by the groups
  // rule (a single group would be a wrapper that only carries style).
  std::string squares[2];
  for (int i = 0; i < 8; ++i)
    squares[i / 4] +=
        R"(<rect x=")" + std::to_string(10 * i) + R"(" y="10" width="4" height="4"/>)";
  const Scene grouped = read("<g>" + squares[0] + "</g><g>" + squares[1] + "</g>");
  ASSERT_EQ(grouped.elements.size(), 2u);
  ASSERT_EQ(grouped.notes.size(), 1u);
  EXPECT_NE(grouped.notes[0].find("elements=visual"), std::string::npos);
}

TEST(VisualElements, MotifWrappingAroundTheTileIsNoted) {
  const Scene scene = read(R"(<rect x="0" y="40" width="100" height="5"/>)", true);
  EXPECT_EQ(scene.elements.size(), 1u);
  ASSERT_EQ(scene.notes.size(), 1u);
  EXPECT_NE(scene.notes[0].find("wraps around the tile"), std::string::npos);
}

// A 40 × 40 tile repeated 3 × 3, as a script writes one: a dot, and a bar the tile's top border
// cut in two, the halves written as one path whose pieces stand `gap` apart at the seam (as a
// drawing program rounds them: one ends at y = 39.977, the next starts at 40).
std::string tiled_three_by_three(double gap) {
  std::string body;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const double x = 40.0 * i, y = 40.0 * j;
      body += "<path d=\"M" + std::to_string(x + 5) + ' ' + std::to_string(y + 10) + "h6v6h-6z\"/>";
      if (j < 2) {
        const double seam = y + 40;
        body += "<path d=\"M" + std::to_string(x + 20) + ' ' + std::to_string(seam - 6) + "h10v" +
                std::to_string(6 - gap) + "h-10z M" + std::to_string(x + 20) + ' ' +
                std::to_string(seam) + "h10v6h-10z\"/>";
      }
    }
  }
  return body;
}

TEST(VisualElements, PiecesAHairApartAtASeamAreOneElement) {
  // 9 dots and 6 bars, each bar one path of two pieces 0.023 apart: 15 elements, as drawn.
  const Scene joined = read(tiled_three_by_three(0.023), false, false, "0 0 120 120");
  EXPECT_EQ(joined.elements.size(), 15u);
  EXPECT_TRUE(joined.notes.empty());
  // A gap a person sees (1 unit) keeps the halves apart, and the reader says that the file's
  // shapes and the elements as seen disagree, naming the option.
  const Scene apart = read(tiled_three_by_three(1.0), false, false, "0 0 120 120");
  EXPECT_EQ(apart.elements.size(), 21u);
  ASSERT_EQ(apart.notes.size(), 1u);
  EXPECT_NE(apart.notes[0].find("elements=paths"), std::string::npos) << apart.notes[0];
  // Shapes meeting at a corner a hair's breadth apart stay two: only outlines that run side by
  // side join.
  EXPECT_EQ(count(R"(<rect x="10" y="10" width="10" height="10"/>)"
                  R"(<rect x="20.02" y="20.02" width="10" height="10"/>)"),
            2u);
  EXPECT_EQ(count(R"(<rect x="10" y="10" width="10" height="10"/>)"
                  R"(<rect x="20.02" y="10" width="10" height="10"/>)"),
            1u);
}

// 200 squares nested in one even-odd path, 0.5 apart: 100 rings, each an outline and the hole
// inside it, or one element when nested pieces join. Beyond 64 deep, depth is counted along the
// chain of innermost containers (geometry/visual_elements.cpp), which must agree.
TEST(VisualElements, DeeplyNestedOutlinesCountTheirDepthExactly) {
  std::string d;
  for (int i = 1; i <= 200; ++i)
    d += "M" + std::to_string(300 - 0.5 * i) + " " + std::to_string(300 - 0.5 * i) + "h" +
         std::to_string(i) + "v" + std::to_string(i) + "h" + std::to_string(-i) + "z ";
  const std::string path = R"(<path fill-rule="evenodd" d=")" + d + R"("/>)";
  EXPECT_EQ(read(path, false, true, "0 0 600 600").elements.size(), 100u);
  EXPECT_EQ(read(path, false, false, "0 0 600 600").elements.size(), 1u);
}

}  // namespace
}  // namespace shapeproc::io
