// Nearest offsets on a grid: exact on a square lattice on a torus, and the count capped by the
// points there are.
#include "libshapeproc/geometry/nearest_neighbours.hpp"

#include <gtest/gtest.h>

namespace shapeproc::geometry {
namespace {

TEST(NearestNeighbours, FindsTheLatticeNeighboursAcrossTheTorus) {
  // A 10 × 10 lattice of spacing 3 on a 30 × 30 torus: every point's 4 nearest are at 3.
  std::vector<Vec3> points;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) points.emplace_back(1.5 + 3 * i, 1.5 + 3 * j, 0);
  const Domain torus = Domain::from_sizes({30, 30}, Boundary::torus);
  const auto offsets = nearest_offsets(points, torus, 4);
  ASSERT_EQ(offsets.size(), points.size());
  for (const auto& near : offsets) {
    ASSERT_EQ(near.size(), 4u);
    for (const Vec3& o : near) EXPECT_NEAR(o.norm(), 3.0, 1e-12);
  }
  // The corner point's neighbours wrap: one of them is at (-3, 0).
  bool wrapped = false;
  for (const Vec3& o : offsets[0]) wrapped |= (o - Vec3(-3, 0, 0)).norm() < 1e-12;
  EXPECT_TRUE(wrapped);
  // The 5th to 8th nearest are the diagonals, nearest first.
  const auto eight = nearest_offsets(points, torus, 8);
  EXPECT_NEAR(eight[42][4].norm(), 3.0 * std::sqrt(2.0), 1e-12);
  for (std::size_t k = 1; k < 8; ++k) EXPECT_LE(eight[42][k - 1].norm(), eight[42][k].norm());
}

TEST(NearestNeighbours, GivesFewerWhenThereAreFewerOthers) {
  const std::vector<Vec3> points = {Vec3(1, 1, 0), Vec3(4, 5, 0), Vec3(9, 9, 0)};
  const Domain open = Domain::from_sizes({10, 10}, Boundary::open);
  const auto offsets = nearest_offsets(points, open, 5);
  ASSERT_EQ(offsets[0].size(), 2u);
  EXPECT_NEAR(offsets[0][0].norm(), 5.0, 1e-12);  // (3, 4)
  EXPECT_NEAR((offsets[0][1] - Vec3(8, 8, 0)).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace shapeproc::geometry
