#include "libshapeproc/fit/neighbour_offsets.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace shapeproc::fit {
namespace {

using geometry::Vec3;

geometry::Scene points(const std::vector<Vec3>& positions, double width, double height) {
  geometry::Scene s;
  s.window = geometry::Box3(Vec3(0, 0, 0), Vec3(width, height, 0));
  s.categories.push_back({"points"});
  for (const Vec3& p : positions) s.elements.push_back({0, 0, p});
  return s;
}

TEST(NeighbourOffsets, ASquareLatticeOnATorusGivesItsFourVectors) {
  std::vector<Vec3> grid;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) grid.emplace_back(i + 0.5, j + 0.5, 0);
  const model::NeighbourOffsets n = neighbour_offsets(points(grid, 3, 3), true);
  ASSERT_EQ(n.offsets.size(), 4u);
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)}) {
    const auto it = std::find_if(
        n.offsets.begin(), n.offsets.end(),
        [&](const model::NeighbourOffset& o) { return (o.offset - d).norm() < 1e-12; });
    ASSERT_NE(it, n.offsets.end()) << d.transpose();
    EXPECT_EQ(it->weight, 9.0);
  }
  ASSERT_EQ(n.radii.size(), 2u);
  EXPECT_DOUBLE_EQ(n.radii[0], 0.01);  // shares of the nearest-neighbour distance, 1
  EXPECT_DOUBLE_EQ(n.radii[1], 0.1);
}

TEST(NeighbourOffsets, KindsAreShapesAndALoneElementOnATorusMeetsItsImages) {
  geometry::Scene one = points({Vec3(1, 1, 0)}, 2, 4);
  one.shapes.resize(1);
  const model::NeighbourOffsets n = neighbour_offsets(one, true);
  EXPECT_EQ(n.offsets.size(), 4u);  // the images along both axes (the diagonals are farther)
  EXPECT_DOUBLE_EQ(n.radii[0], 0.02);
  EXPECT_TRUE(neighbour_offsets(points({Vec3(1, 1, 0)}, 2, 4), false).empty());
}

// Rows of points 1 apart, the rows 5 apart: the 4 nearest neighbours lie in the row, and each
// cone's nearest adds the next rows', so that the offsets span the plane.
TEST(NeighbourOffsets, EachAxisConeGivesItsNearestSoThatTheOffsetsSpan) {
  std::vector<Vec3> rows;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 6; ++i) rows.emplace_back(i + 0.5, 5 * j + 2.5, 0);
  const model::NeighbourOffsets n = neighbour_offsets(points(rows, 6, 15), true);
  ASSERT_EQ(n.offsets.size(), 6u);
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(2, 0, 0), Vec3(-2, 0, 0), Vec3(0, 5, 0),
                        Vec3(0, -5, 0)}) {
    const auto it = std::find_if(
        n.offsets.begin(), n.offsets.end(),
        [&](const model::NeighbourOffset& o) { return (o.offset - d).norm() < 1e-12; });
    ASSERT_NE(it, n.offsets.end()) << d.transpose();
    EXPECT_EQ(it->weight, 18.0);
  }
}

}  // namespace
}  // namespace shapeproc::fit
