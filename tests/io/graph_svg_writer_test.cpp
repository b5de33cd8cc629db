// The connectivity picture: a line per edge (across a seam, drawn once, leaving the window), a
// labelled dot per node.
#include "libshapeproc/io/graph_svg_writer.hpp"

#include <gtest/gtest.h>

#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

TEST(GraphSvgWriter, ALinePerEdgeADotAndALabelPerNode) {
  const testing::TempDir dir;
  const geometry::Box3 window(geometry::Vec3(0, 0, 0), geometry::Vec3(100, 100, 0));
  const std::vector<geometry::Vec3> nodes = {geometry::Vec3(10, 10, 0), geometry::Vec3(90, 10, 0),
                                             geometry::Vec3(50, 60, 0)};
  // 0–2 inside; 1 to 0 across the right seam: drawn from node 1 to (110, 10).
  const std::vector<GraphEdge> edges = {{0, geometry::Vec3(40, 50, 0)},
                                        {1, geometry::Vec3(20, 0, 0)}};
  write_graph_svg(dir.file("g.svg"), window, nodes, edges, {false, true, false});
  const std::string svg = testing::read_file(dir.file("g.svg"));
  EXPECT_EQ(testing::count_of(svg, "<line"), 2u);
  EXPECT_EQ(testing::count_of(svg, "<circle"), 3u);
  EXPECT_EQ(testing::count_of(svg, "<text"), 3u);
  EXPECT_NE(svg.find("x2=\"110\""), std::string::npos) << svg;
}

}  // namespace
}  // namespace shapeproc::io
