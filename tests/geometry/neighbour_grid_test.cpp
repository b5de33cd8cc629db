#include "libshapeproc/geometry/neighbour_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::geometry {
namespace {

// For random points, every point within `distance` of a query (minimum image on a torus) is a
// candidate, and no candidate is reported twice: for_each_candidate at the cell size (distance
// 0), for_each_candidate_within at `distance`.
void expect_superset(int dimension, bool periodic, double cell_size, double distance = 0.0) {
  const Vec3 max = dimension == 2 ? Vec3(30, 20, 0) : Vec3(12, 10, 8);
  const Box3 window(Vec3::Zero(), max);
  const Domain domain(window, dimension, periodic ? Boundary::torus : Boundary::open);
  core::Random random(static_cast<std::uint64_t>(dimension * 10 + periodic));
  std::vector<Vec3> points;
  NeighbourGrid grid(window, dimension, cell_size, periodic);
  for (int i = 0; i < 400; ++i) {
    Vec3 p = Vec3::Zero();
    for (int axis = 0; axis < dimension; ++axis) p[axis] = random.uniform(0, max[axis]);
    points.push_back(p);
    grid.insert(i, p);
  }
  for (int q = 0; q < 100; ++q) {
    Vec3 at = Vec3::Zero();
    for (int axis = 0; axis < dimension; ++axis) at[axis] = random.uniform(0, max[axis]);
    std::map<int, int> seen;
    if (distance > 0)
      grid.for_each_candidate_within(at, distance, [&](int id) { ++seen[id]; });
    else
      grid.for_each_candidate(at, [&](int id) { ++seen[id]; });
    for (const auto& [id, times] : seen) EXPECT_EQ(times, 1) << id;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (domain.minimum_image(points[i] - at).norm() < (distance > 0 ? distance : cell_size)) {
        EXPECT_TRUE(seen.count(static_cast<int>(i)))
            << "point " << i << " missed (dimension " << dimension << ")";
      }
    }
  }
}

TEST(NeighbourGrid, CandidatesHoldEveryPointWithinTheCellSize) {
  for (int dimension : {2, 3})
    for (bool periodic : {false, true})
      for (double cell : {1.5, 4.0, 11.0}) expect_superset(dimension, periodic, cell);
}

TEST(NeighbourGrid, CandidatesWithinADistanceHoldEveryPointThatNear) {
  // Distances of a fraction of a cell, several cells, and more than a period (each id once).
  for (int dimension : {2, 3})
    for (bool periodic : {false, true})
      for (double distance : {0.7, 3.9, 9.0, 40.0})
        expect_superset(dimension, periodic, 1.5, distance);
}

TEST(NeighbourGrid, AnyCandidateStopsAtTheFirstThatPassesInTheVisitingOrder) {
  const Box3 window(Vec3::Zero(), Vec3(20, 20, 0));
  NeighbourGrid grid(window, 2, 2.0, true);
  core::Random random(7);
  for (int i = 0; i < 200; ++i)
    grid.insert(i, Vec3(random.uniform(0, 20), random.uniform(0, 20), 0));
  for (const Vec3& at : {Vec3(1, 1, 0), Vec3(10, 19.5, 0), Vec3(7.3, 4.1, 0)}) {
    std::vector<int> order, within;
    grid.for_each_candidate(at, [&](int id) { order.push_back(id); });
    grid.for_each_candidate_within(at, 5.0, [&](int id) { within.push_back(id); });
    ASSERT_GE(order.size(), 3u);
    for (const std::vector<int>* ids : {&order, &within}) {
      // A test passing at the third id visited: three visits, and true.
      const int target = (*ids)[2];
      std::vector<int> visited;
      const auto test = [&](int id) {
        visited.push_back(id);
        return id == target;
      };
      const bool found =
          ids == &order ? grid.any_candidate(at, test) : grid.any_candidate_within(at, 5.0, test);
      EXPECT_TRUE(found);
      EXPECT_EQ(visited, std::vector<int>(ids->begin(), ids->begin() + 3));
    }
    EXPECT_FALSE(grid.any_candidate(at, [](int) { return false; }));
    EXPECT_FALSE(grid.any_candidate_within(at, 5.0, [](int) { return false; }));
  }
}

TEST(NeighbourGrid, RemovedIdsAreNoLongerCandidates) {
  const Box3 window(Vec3::Zero(), Vec3(10, 10, 0));
  NeighbourGrid grid(window, 2, 2.0, false);
  grid.insert(1, Vec3(5, 5, 0));
  grid.insert(2, Vec3(5.5, 5, 0));
  grid.remove(1, Vec3(5, 5, 0));
  std::vector<int> ids;
  grid.for_each_candidate(Vec3(5, 5, 0), [&](int id) { ids.push_back(id); });
  EXPECT_EQ(ids, std::vector<int>{2});
}

TEST(NeighbourGrid, PeriodicQueriesWrapAroundTheWindow) {
  const Box3 window(Vec3::Zero(), Vec3(10, 10, 0));
  NeighbourGrid open(window, 2, 2.0, false), torus(window, 2, 2.0, true);
  open.insert(7, Vec3(9.8, 5, 0));
  torus.insert(7, Vec3(9.8, 5, 0));
  int found_open = 0, found_torus = 0;
  open.for_each_candidate(Vec3(0.2, 5, 0), [&](int) { ++found_open; });
  torus.for_each_candidate(Vec3(0.2, 5, 0), [&](int) { ++found_torus; });
  EXPECT_EQ(found_open, 0);
  EXPECT_EQ(found_torus, 1);
}

}  // namespace
}  // namespace shapeproc::geometry
