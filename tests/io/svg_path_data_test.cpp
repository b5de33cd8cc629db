#include "libshapeproc/io/svg_path_data.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/io/svg_grammar.hpp"

namespace shapeproc::io {
namespace {

using geometry::Path2;
using geometry::Segment2;
using geometry::Vec2;

// A line, a cubic and the close: absolute commands, numbers as format_number writes them, and the
// text parses back to the same outlines.
TEST(SvgPathData, WritesAbsoluteCommandsThatParseBackToTheSameOutline) {
  Path2 path;
  path.segments = {Segment2::line(Vec2(0, 0), Vec2(10, 0.5)),
                   Segment2::bezier(Vec2(10, 0.5), Vec2(12, 2), Vec2(8, 6), Vec2(0, 4))};
  path.closed = true;
  EXPECT_EQ(svg_path_data(path), "M0 0L10 0.5C12 2 8 6 0 4Z");
  Path2 dot;
  dot.segments = {Segment2::line(Vec2(-1.25, 3), Vec2(-1, 3))};
  EXPECT_EQ(svg_path_data(std::vector<Path2>{path, dot}),
            "M0 0L10 0.5C12 2 8 6 0 4Z M-1.25 3L-1 3");
  EXPECT_EQ(svg_path_data(std::vector<Path2>{}), "");

  const std::vector<Path2> back = svg::parse_path_data(svg_path_data(path));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_TRUE(back[0].closed);
  ASSERT_GE(back[0].segments.size(), 2u);
  EXPECT_EQ(back[0].segments[0].end, Vec2(10, 0.5));
  EXPECT_TRUE(back[0].segments[1].cubic);
  EXPECT_EQ(back[0].segments[1].control2, Vec2(8, 6));
  EXPECT_EQ(back[0].segments[1].end, Vec2(0, 4));
}

}  // namespace
}  // namespace shapeproc::io
