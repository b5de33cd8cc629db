#include "libshapeproc/methods/davison2018/detail/dbscan.hpp"

#include <gtest/gtest.h>

namespace shapeproc::methods {
namespace {

using geometry::Vec3;

TEST(Dbscan, TwoBlobsABorderPointAndNoise) {
  // Ester et al.'s picture: two dense groups, a point on the edge of one, one far away.
  const std::vector<Vec3> points = {
      {0, 0, 0},   {1, 0, 0},  {0, 1, 0},  {1, 1, 0},   // blob A (each sees 4 within 1.5)
      {10, 0, 0},  {11, 0, 0}, {10, 1, 0}, {11, 1, 0},  // blob B
      {2.4, 1, 0},                                      // sees only (1, 1): a border point
      {30, 30, 0}};                                     // noise
  const std::vector<int> label = dbscan(points, 1.5, 4);
  const std::vector<int> expected = {0, 0, 0, 0, 1, 1, 1, 1, 0, kNoise};
  EXPECT_EQ(label, expected);
}

TEST(Dbscan, TooFewNeighboursIsAllNoiseAndOneIsEveryPointItsOwn) {
  const std::vector<Vec3> points = {{0, 0, 0}, {5, 0, 0}, {10, 0, 0}};
  EXPECT_EQ(dbscan(points, 1.0, 2), std::vector<int>(3, kNoise));
  EXPECT_EQ(dbscan(points, 1.0, 1), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(dbscan(points, 5.0, 2), (std::vector<int>{0, 0, 0}));  // a chain
}

}  // namespace
}  // namespace shapeproc::methods
