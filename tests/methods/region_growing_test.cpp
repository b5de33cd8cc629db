#include "libshapeproc/methods/davison2018/region_growing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/methods/davison2018/density_calibration.hpp"
#include "libshapeproc/methods/davison2018/detail/growth_palette.hpp"
#include "libshapeproc/metrics/novelty.hpp"
#include "tests/methods/method_scenes.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::methods {
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
  GrowthOptions circles;  // the paper's overlap test
  circles.exact_overlap = false;
  const RegionGrowing growth(exemplar, Boundary::open, domain, circles);
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

// Hero Patterns' bubbles tile (17 discs) grown over 3 x 3 tiles: as the paper grows it (no patch
// radius) it comes out the tile repeated; with the patch radius (the default) copied patches stay
// small and the density is kept (seed 1: largest copied patch 1.00 against 0.23; 153 and 147
// elements against 9 × 17).
TEST(RegionGrowing, ThePatchRadiusKeepsATileFromComingOutRepeated) {
  const geometry::Scene tile = testing::bubbles_tile();
  const geometry::Domain domain =
      geometry::Domain::from_sizes({300, 300}, geometry::Boundary::torus);
  GrowthOptions paper;
  paper.patch_radius = 0.0;
  const geometry::Scene copied = run(RegionGrowing(tile, Boundary::torus, domain, paper), 1).scene;
  const geometry::Scene grown =
      run(RegionGrowing(tile, Boundary::torus, domain, GrowthOptions{}), 1).scene;
  const metrics::Novelty a = metrics::measure_novelty(tile, copied, Boundary::torus);
  const metrics::Novelty b = metrics::measure_novelty(tile, grown, Boundary::torus);
  EXPECT_GT(a.output.largest_patch, 0.8);
  EXPECT_TRUE(a.repeats_exemplar);
  EXPECT_LT(b.output.largest_patch, 0.3);
  EXPECT_FALSE(b.repeats_exemplar);
  EXPECT_GT(static_cast<double>(grown.elements.size()), 0.8 * 9 * 17);
  EXPECT_LT(static_cast<double>(grown.elements.size()), 1.25 * 9 * 17);
}

// data/svg/dots-random.svg (30 dots on 200 x 200) grown over 4 x 4 windows: as the paper grows it
// (no limit on a copy's neighbours) it comes out about twice as dense (x2.18 at 2 x 2, seed 1);
// calibrated, the count is the exemplar's density's 480 within 4 Poisson standard errors (a grown
// arrangement is more regular than Poisson, so its own error is smaller), under a limit below the
// exemplar's mean count, and the close pairs stay: the smallest nearest distance is the
// exemplar's bounding circles' (the paper's radii are not scaled).
TEST(RegionGrowing, TheCalibrationKeepsASparseExemplarsDensity) {
  const geometry::Scene exemplar = io::read_scene(testing::data_path("svg/dots-random.svg"), {});
  const Domain domain = Domain::from_sizes({800, 800}, Boundary::torus);
  const double expected = 30.0 * 16.0;
  GrowthOptions paper;
  paper.exact_overlap = false;  // the paper's bounding circles, in both
  GrowthOptions circles = paper;
  paper.calibrate_density = false;
  const auto as_paper = run(RegionGrowing(exemplar, Boundary::open, domain, paper), 2);
  const auto calibrated = run(RegionGrowing(exemplar, Boundary::open, domain, circles), 2);
  EXPECT_GT(static_cast<double>(as_paper.scene.elements.size()), 1.6 * expected);
  EXPECT_NEAR(static_cast<double>(calibrated.scene.elements.size()), expected,
              4.0 * std::sqrt(expected));
  double crowding = 0.0;
  for (const auto& [key, value] : calibrated.record.options)
    if (key == "growth.crowding") crowding = std::stod(value);
  EXPECT_GE(crowding, kFewestNeighbours);
  EXPECT_LT(crowding, 1.0);
  const std::vector<double> paper_nearest = nearest_distances(as_paper.scene, domain);
  const std::vector<double> nearest = nearest_distances(calibrated.scene, domain);
  EXPECT_LT(*std::min_element(nearest.begin(), nearest.end()),
            1.2 * *std::min_element(paper_nearest.begin(), paper_nearest.end()));
}

TEST(GrowthPalette, EachExemplarKeepsItsOwnParameters) {
  // Lattices of spacing 10 and 25: every element keeps its own exemplar's neighbourhood radius
  // (2.5 spacings), spacing and bounding radius, and its candidates stay in its own exemplar.
  const GrowthExemplar small = analyse_growth_exemplar(
      testing::rectangle_lattice(6, 10.0, 3.0, 3.0), Boundary::torus, GrowthOptions{});
  const GrowthExemplar large = analyse_growth_exemplar(
      testing::rectangle_lattice(4, 25.0, 8.0, 8.0), Boundary::torus, GrowthOptions{});
  const std::size_t n = small.em.samples.size();
  const GrowthExemplar palette = merge_palette({small, large});
  ASSERT_EQ(palette.parts(), 2u);
  ASSERT_EQ(palette.em.samples.size(), n + large.em.samples.size());
  ASSERT_EQ(palette.em.scene.categories.size(), 2u);
  EXPECT_EQ(palette.em.scene.categories[1].name, "a #2");
  for (std::size_t s = 0; s < palette.em.samples.size(); ++s) {
    const bool second = s >= n;
    EXPECT_EQ(palette.part[s], second ? 1 : 0);
    EXPECT_DOUBLE_EQ(palette.reach[s], second ? 62.5 : 25.0);
    EXPECT_DOUBLE_EQ(palette.spacing[s], second ? 25.0 : 10.0);
    EXPECT_DOUBLE_EQ(palette.radius[s], second ? 12.5 : 5.0);
    EXPECT_EQ(
        palette.em.scene.elements[static_cast<std::size_t>(palette.em.samples.element[s])].category,
        second ? 1 : 0);
    for (const int m : palette.sets.sets[s]) EXPECT_EQ(static_cast<std::size_t>(m) >= n, second);
    for (const geometry::Neighbour& o : palette.em.wide[s].neighbours())
      EXPECT_EQ(static_cast<std::size_t>(o.element) >= n, second);
    EXPECT_EQ(palette.free[s].size(), (second ? large : small).free[second ? s - n : s].size());
  }
  EXPECT_NE(palette.em.attribute.front(), palette.em.attribute.back());
}

TEST(RegionGrowing, APaletteGrowsTwoLatticesAtTheirOwnScales) {
  const Domain domain = Domain::from_sizes({300, 150}, Boundary::open);
  const std::vector<GrowthSource> palette{
      {testing::rectangle_lattice(6, 10.0, 3.0, 3.0), Boundary::torus},
      {testing::rectangle_lattice(4, 25.0, 8.0, 8.0), Boundary::torus}};
  const RegionGrowing growth(palette, domain, GrowthOptions{});
  const geometry::Scene out = run(growth, 4).scene;
  std::vector<std::vector<Vec3>> by_part(2);
  for (const geometry::Element& e : out.elements)
    by_part[static_cast<std::size_t>(e.category)].push_back(e.position);
  // Each grew over a good part of its half of the domain.
  EXPECT_GT(by_part[0].size(), 0.3 * 150 * 150 / 100.0);
  EXPECT_GT(by_part[1].size(), 0.3 * 150 * 150 / 625.0);
  // Each is a lattice of its own spacing: nearest same-part distances within 5% of it.
  for (std::size_t p = 0; p < 2; ++p) {
    const double spacing = p == 0 ? 10.0 : 25.0;
    int on = 0;
    for (std::size_t i = 0; i < by_part[p].size(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < by_part[p].size(); ++j)
        if (j != i) nearest = std::min(nearest, (by_part[p][j] - by_part[p][i]).norm());
      on += std::abs(nearest - spacing) < 0.05 * spacing;
    }
    EXPECT_GE(on, 0.9 * static_cast<double>(by_part[p].size())) << "part " << p;
  }
  // Where the two meet, their bounding circles (5 and 12.5) do not overlap.
  for (const Vec3& a : by_part[0])
    for (const Vec3& b : by_part[1]) EXPECT_GE((a - b).norm(), 17.5 - 1e-9);
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
}  // namespace shapeproc::methods

namespace shapeproc::methods {
namespace {

// The overlap test chosen for the exemplar: on dots-random (irregular) the shapes, so that its
// close pairs grow too; on a lattice the circles, which hold its spacing. The paper's circles of
// half each nearest distance forbid close pairs: measured by the share of output elements whose
// nearest neighbour is nearer than the exemplar's first quartile of nearest distances (a quarter
// in the exemplar, with a binomial standard error of about 0.04 over the output's 120 elements).
TEST(RegionGrowing, OverlapTestFollowsTheExemplar) {  // NOLINT
  const geometry::Scene dots = io::read_scene(testing::data_path("svg/dots-random.svg"), {});
  std::vector<double> own = nearest_distances(dots, Domain(dots.window, 2, Boundary::open));
  std::sort(own.begin(), own.end());
  const double quartile = own[own.size() / 4];
  const Domain domain = Domain::from_sizes({400, 400}, Boundary::torus);
  const auto close_share = [&](const geometry::Scene& scene) {
    const std::vector<double> d = nearest_distances(scene, domain);
    return static_cast<double>(
               std::count_if(d.begin(), d.end(), [&](double x) { return x < quartile; })) /
           static_cast<double>(d.size());
  };
  const auto overlap = [](const synthesis::SynthesisResult& r) {
    for (const auto& [key, value] : r.record.options)
      if (key == "growth.overlap") return value;
    return std::string();
  };
  GrowthOptions circles;
  circles.exact_overlap = false;
  const RegionGrowing shapes(dots, Boundary::open, domain, GrowthOptions{});
  const RegionGrowing bounding(dots, Boundary::open, domain, circles);
  // Over seeds 1-4 (one seed's share spreads by about 0.06): seeds 1-10 gave 0.10-0.26 with the
  // shapes, 0.03-0.09 with the circles.
  double with_shapes = 0.0, with_circles = 0.0;
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const synthesis::SynthesisResult a = run(shapes, seed);
    const synthesis::SynthesisResult c = run(bounding, seed);
    EXPECT_EQ(overlap(a), "shapes");
    EXPECT_EQ(overlap(c), "circles");
    with_shapes += close_share(a.scene) / 4.0;
    with_circles += close_share(c.scene) / 4.0;
  }
  EXPECT_GT(with_shapes, 0.12);
  EXPECT_LT(with_circles, 0.09);
  EXPECT_GT(with_shapes, with_circles + 0.05);
  const geometry::Scene lattice = testing::rectangle_lattice(6, 10.0, 3.0, 3.0);
  const Domain square = Domain::from_sizes({100, 100}, Boundary::torus);
  EXPECT_EQ(overlap(run(RegionGrowing(lattice, Boundary::torus, square, GrowthOptions{}), 1)),
            "circles");
}

TEST(RegionGrowing, ExactOverlapsKeepLongShapesApart) {
  // Bars much longer than half their nearest distance: bounding circles let them overlap, the
  // shapes' own distance does not.
  const geometry::Scene exemplar = testing::bar_scatter(60, 4);
  const Domain domain = Domain::from_sizes({400, 400}, Boundary::torus);
  GrowthOptions options;
  options.exact_overlap = false;
  const RegionGrowing circles(exemplar, Boundary::torus, domain, options);
  options.exact_overlap = true;
  const RegionGrowing shapes(exemplar, Boundary::torus, domain, options);
  const synthesis::SynthesisResult a = run(circles, 1), b = run(shapes, 1);
  EXPECT_GT(testing::overlapping_bars(a.scene, domain), 0);
  EXPECT_EQ(testing::overlapping_bars(b.scene, domain), 0);
  EXPECT_GT(b.scene.elements.size(), 150u);  // still grown over the domain (4 x 60 at most)
}

}  // namespace
}  // namespace shapeproc::methods
