#include "libshapeproc/sample/configuration.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "tests/point_model.hpp"

namespace shapeproc::sample {
namespace {

// Points under one isotropic interaction with bands [0, 3) and [3, 6) on a 20 x 20 window, open or
// a torus, with a configuration of the points given.
struct Points {
  model::ShapeProcessModel m = testing::point_model(0.01, {0.0, 3.0, 6.0}, {0.5, 0.5});
  model::Interaction interaction{m};
  geometry::Scene space;
  std::unique_ptr<geometry::PairMeasurer> measurer;
  std::unique_ptr<Configuration> c;

  Points(geometry::Boundary boundary, const std::vector<Vec3>& positions) {
    space.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(20, 20, 0));
    space.categories.push_back({"points"});
    space.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
    const geometry::Domain domain(space.window, 2, boundary);
    measurer =
        std::make_unique<geometry::PairMeasurer>(space, m.measurement_options(domain.periodic()));
    c = std::make_unique<Configuration>(interaction, *measurer, nullptr, domain, 6.0);
    std::vector<Link> links;
    for (const Vec3& p : positions) {
      const Element e{0, 0, p};
      c->log_interaction(e, -1, links);
      c->add(e, 0.0, links);
    }
  }
};

// A–B 2 apart (band 1), B–C 5, A–D 4, B–D √20 (band 2), the others beyond 6. The window [0, 10]²
// holds A, B and D: its statistics count them and their three pairs, not C nor the pair B–C.
TEST(Configuration, AWindowsStatisticsCountItsElementsAndThePairsWithin) {
  const Points points(geometry::Boundary::open,
                      {Vec3(5, 5, 0), Vec3(7, 5, 0), Vec3(12, 5, 0), Vec3(5, 9, 0)});
  const Configuration& c = *points.c;
  EXPECT_EQ(c.statistics(), (std::vector<double>{4, 1, 3}));
  std::vector<double> window;
  c.statistics_in(geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(10, 10, 0)), window);
  EXPECT_EQ(window, (std::vector<double>{3, 1, 2}));
  c.statistics_in(geometry::Box3(geometry::Vec3(6, 0, 0), geometry::Vec3(20, 20, 0)), window);
  EXPECT_EQ(window, (std::vector<double>{2, 0, 1}));  // B and C, and their pair
}

// On a torus a window's statistics leave out the pairs that meet across the seam: the window as
// a piece of a larger drawing has its elements at opposite edges far apart. A at (1, 5), B at
// (19, 5) (2 apart across the seam, band 1) and C at (4, 5) (A–C 3 apart, band 2; B–C 5 across
// the seam, band 2): the torus counts three pairs, the window one.
TEST(Configuration, AWindowOnATorusLeavesOutThePairsAcrossItsSeam) {
  const Points points(geometry::Boundary::torus, {Vec3(1, 5, 0), Vec3(19, 5, 0), Vec3(4, 5, 0)});
  EXPECT_EQ(points.c->statistics(), (std::vector<double>{3, 1, 2}));
  std::vector<double> window;
  points.c->statistics_in(points.space.window, window);
  EXPECT_EQ(window, (std::vector<double>{3, 0, 1}));  // A–C only
}

}  // namespace
}  // namespace shapeproc::sample
