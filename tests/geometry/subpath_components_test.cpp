#include "libshapeproc/geometry/subpath_components.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/geometry/arc.hpp"

namespace shapeproc::geometry {
namespace {

Path2 square(double x, double y, double side, bool reversed = false) {
  std::vector<Vec2> c = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  if (reversed) std::reverse(c.begin(), c.end());
  Path2 path;
  for (int i = 0; i < 4; ++i) path.segments.push_back(Segment2::line(c[i], c[(i + 1) % 4]));
  path.closed = true;
  return path;
}

std::vector<std::size_t> piece_sizes(const Drawable2& drawable) {
  std::vector<std::size_t> sizes;
  for (const Drawable2& piece : split_disjoint_subpaths(drawable))
    sizes.push_back(piece.paths.size());
  return sizes;
}

TEST(SplitSubpaths, RingKeepsItsHoleAndADotInTheHoleIsSeparate) {
  Drawable2 d;
  d.paths = {ellipse_path({0, 0}, 10, 10), ellipse_path({0, 0}, 6, 6), ellipse_path({0, 0}, 2, 2),
             ellipse_path({30, 0}, 3, 3)};
  const auto pieces = split_disjoint_subpaths(d);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[0].paths.size(), 2u);  // ring: outline + hole
  EXPECT_EQ(pieces[1].paths.size(), 1u);  // dot inside the hole
  EXPECT_EQ(pieces[2].paths.size(), 1u);  // dot outside
}

TEST(SplitSubpaths, CheckerboardSquaresTouchingAtCornersAreSeparate) {
  Drawable2 d;
  d.paths = {square(0, 0, 1), square(1, 1, 1), square(2, 0, 1)};
  EXPECT_EQ(piece_sizes(d), (std::vector<std::size_t>{1, 1, 1}));
}

TEST(SplitSubpaths, OverlappingOrEdgeSharingSubpathsStayTogether) {
  Drawable2 d;
  d.paths = {square(0, 0, 2), square(1, 1, 2), square(3, 0, 1), square(10, 0, 1)};
  // The first two cross; the third touches the second only at the corner (3, 1); the last is apart.
  EXPECT_EQ(piece_sizes(d), (std::vector<std::size_t>{2, 1, 1}));
  Drawable2 shared;
  shared.paths = {square(0, 0, 1), square(1, 0, 1)};
  EXPECT_EQ(piece_sizes(shared), (std::vector<std::size_t>{2}));
}

TEST(SplitSubpaths, SquareWithTwoHolesIsOnePiece) {
  Drawable2 d;
  d.paths = {square(0, 0, 10), square(1, 1, 2, true), square(5, 5, 2, true)};
  EXPECT_EQ(piece_sizes(d), (std::vector<std::size_t>{3}));
}

}  // namespace
}  // namespace shapeproc::geometry
