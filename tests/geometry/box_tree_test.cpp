// The box hierarchy finds exactly the boxes a query meets, as a look at every box would.
#include "libshapeproc/geometry/box_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace shapeproc::geometry {
namespace {

TEST(BoxTree, FindsWhatABruteForceSearchFinds) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> at(0.0, 100.0), side(0.0, 6.0);
  std::vector<BoxTree<2>::Box> boxes;
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector2d corner(at(random), at(random));
    boxes.emplace_back(corner, corner + Eigen::Vector2d(side(random), side(random)));
  }
  const BoxTree<2> tree = BoxTree<2>::build(boxes);
  for (int q = 0; q < 200; ++q) {
    const Eigen::Vector2d corner(at(random), at(random));
    const BoxTree<2>::Box query(corner, corner + Eigen::Vector2d(side(random), side(random)));
    std::vector<int> found, expected;
    tree.for_each_intersecting(query, boxes, [&](int i) { found.push_back(i); });
    for (int i = 0; i < 500; ++i)
      if (boxes[static_cast<std::size_t>(i)].intersects(query)) expected.push_back(i);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected);
  }
  // A point query, and an empty tree.
  const Eigen::Vector2d p = boxes[3].center();
  bool met = false;
  tree.for_each_intersecting(BoxTree<2>::Box(p, p), boxes, [&](int i) { met |= i == 3; });
  EXPECT_TRUE(met);
  int calls = 0;
  BoxTree<2>::build({}).for_each_intersecting(BoxTree<2>::Box(p, p), {}, [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace shapeproc::geometry
