#include "libshapeproc/compare/region_growing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "tests/compare/compare_scenes.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::compare {
namespace {

using geometry::Boundary;
using geometry::Domain;

using testing::nearest_distances;
using testing::run;

TEST(FreeSpace, ALatticeGivesItsLatticeOffsets) {
  // A 6 x 6 lattice of spacing 10 on a torus: every neighbourhood is the same, so each element's
  // free space is exactly its 20 lattice neighbours within 2.5 spacings.
  const GrowthExemplar g = analyse_growth_exemplar(testing::rectangle_lattice(6, 10.0, 3.0, 3.0),
                                                   Boundary::torus, GrowthOptions{});
  for (std::size_t e = 0; e < g.free.size(); ++e) {
    ASSERT_EQ(g.free[e].size(), 20u) << "element " << e;
    for (const FreeSpaceVector& v : g.free[e]) {
      EXPECT_NEAR(v.offset.x(), 10.0 * std::round(v.offset.x() / 10.0), 1e-9);
      EXPECT_NEAR(v.offset.y(), 10.0 * std::round(v.offset.y() / 10.0), 1e-9);
      EXPECT_LT(v.offset.norm(), 25.0);
      EXPECT_NEAR(v.radius, 5.0, 1e-9);  // half the nearest distance
    }
  }
}

TEST(RegionGrowing, ALatticeGrowsIntoALattice) {
  const geometry::Scene exemplar = testing::rectangle_lattice(6, 10.0, 3.0, 3.0);
  const Domain domain = Domain::from_sizes({150, 150}, Boundary::torus);
  const RegionGrowing growth(exemplar, Boundary::torus, domain, GrowthOptions{});
  const synthesis::SynthesisResult result = run(growth, 3);
  EXPECT_EQ(result.scene.elements.size(), 225u);
  int off = 0;
  for (const double d : nearest_distances(result.scene, domain)) off += std::abs(d - 10.0) > 0.5;
  EXPECT_EQ(off, 0);
}

TEST(RegionGrowing, FillsAnOpenDomainWithoutOverlapsAndRepeats) {
  const geometry::Scene exemplar = testing::rectangle_scatter(40, 100.0, 4.0, 8.0, 7);
  const Domain domain = Domain::from_sizes({220, 160}, Boundary::open);
  const RegionGrowing growth(exemplar, Boundary::open, domain, GrowthOptions{});
  const auto a = run(growth, 5), b = run(growth, 5), c = run(growth, 6);
  // Grown to the domain's edges: at least the exemplar's density over most of it.
  EXPECT_GT(a.scene.elements.size(), 0.8 * 40 * (220.0 * 160.0) / (100.0 * 100.0));
  for (const geometry::Element& e : a.scene.elements) EXPECT_TRUE(domain.contains(e.position));
  // No bounding circles overlap: every nearest distance at least the exemplar's smallest.
  for (const double d : nearest_distances(a.scene, domain)) EXPECT_GE(d, 8.0 - 1e-9);
  ASSERT_EQ(a.scene.elements.size(), b.scene.elements.size());
  for (std::size_t i = 0; i < a.scene.elements.size(); ++i)
    EXPECT_EQ(a.scene.elements[i].position, b.scene.elements[i].position);
  EXPECT_FALSE(a.scene.elements.size() == c.scene.elements.size() &&
               a.scene.elements.back().position == c.scene.elements.back().position);
}

TEST(RegionGrowing, GrowsIn3D) {
  const geometry::Scene exemplar =
      io::read_scene(testing::data_path("mesh/pebbles.obj"), io::ReaderOptions{});
  const Domain domain = Domain::from_sizes({22.6, 22.4, 5.3}, Boundary::torus);
  GrowthOptions options;
  options.rings = 1.0;  // a 12-element exemplar: one ring
  const RegionGrowing growth(exemplar, Boundary::open, domain, options);
  const synthesis::SynthesisResult result = run(growth, 1);
  // About the exemplar's density: 12 elements in 662 units³, 2683 units³ here.
  EXPECT_GT(result.scene.elements.size(), 30u);
  EXPECT_LT(result.scene.elements.size(), 80u);
}

TEST(RegionGrowing, RefusesBadOptions) {
  const geometry::Scene exemplar = testing::rectangle_lattice(4, 10.0, 3.0, 3.0);
  const Domain domain = Domain::from_sizes({100, 100}, Boundary::torus);
  GrowthOptions bad;
  bad.ratio = 1.0;
  EXPECT_THROW(RegionGrowing growth(exemplar, Boundary::torus, domain, bad), core::ArgumentError);
  bad = GrowthOptions{};
  bad.k = 0;
  EXPECT_THROW(RegionGrowing growth(exemplar, Boundary::torus, domain, bad), core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::compare

namespace shapeproc::compare {
namespace {

TEST(RegionGrowing, ExactOverlapsKeepLongShapesApart) {
  // Bars much longer than half their nearest distance: bounding circles let them overlap, the
  // shapes' own distance does not.
  const geometry::Scene exemplar = testing::bar_scatter(60, 4);
  const Domain domain = Domain::from_sizes({400, 400}, Boundary::torus);
  GrowthOptions options;
  const RegionGrowing circles(exemplar, Boundary::torus, domain, options);
  options.exact_overlap = true;
  const RegionGrowing shapes(exemplar, Boundary::torus, domain, options);
  const synthesis::SynthesisResult a = run(circles, 1), b = run(shapes, 1);
  EXPECT_GT(testing::overlapping_bars(a.scene, domain), 0);
  EXPECT_EQ(testing::overlapping_bars(b.scene, domain), 0);
  EXPECT_GT(b.scene.elements.size(), 150u);  // still grown over the domain (4 x 60 at most)
}

}  // namespace
}  // namespace shapeproc::compare
