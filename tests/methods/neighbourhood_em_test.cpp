#include "libshapeproc/methods/ma2011/neighbourhood_em.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/shape_size.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/metrics/novelty.hpp"
#include "tests/methods/method_scenes.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::methods {
namespace {

using geometry::Boundary;
using geometry::Domain;

using testing::nearest_distances;
using testing::run;

TEST(NeighbourhoodEm, ASquareLatticeGivesALattice) {
  // A seamless 6 x 6 tile of a lattice of spacing 10; patches land at random offsets, so the
  // initial output has broken seams that the EM must close.
  const geometry::Scene exemplar = testing::rectangle_lattice(6, 10.0, 3.0, 3.0);
  const Domain domain = Domain::from_sizes({150, 150}, Boundary::torus);
  const NeighbourhoodEm em(exemplar, Boundary::torus, domain, EmOptions{});
  // The tile (side 60) is smaller than 4r (100): analysed repeated 2 x 2.
  EXPECT_EQ(em.exemplar().samples.size(), 4 * 36u);
  EXPECT_NEAR(em.exemplar().spacing, 10.0, 1e-9);
  const synthesis::SynthesisResult result = run(em, 4);
  ASSERT_GT(result.scene.elements.size(), 150u);
  int off = 0;
  for (const double d : nearest_distances(result.scene, domain)) off += std::abs(d - 10.0) > 0.5;
  EXPECT_EQ(off, 0) << "of " << result.scene.elements.size() << " elements";
}

// crescents-grid (5 x 5 jittered crescents, 250 px, open) at 500 x 500: its 10 x 10 lattice
// whole, where its seams used to crowd a row and drop 8 to 13 elements or hold too many.
TEST(NeighbourhoodEm, CrescentsGridKeepsItsLatticeAcrossSeams) {  // NOLINT
  const geometry::Scene exemplar =
      io::read_scene(testing::data_path("svg/crescents-grid.svg"), io::ReaderOptions{});
  const Domain domain = Domain::from_sizes({500, 500}, Boundary::open);
  const NeighbourhoodEm em(exemplar, Boundary::open, domain, EmOptions{});
  for (const std::uint64_t seed : {1u, 3u, 5u}) {
    const synthesis::SynthesisResult result = run(em, seed);
    EXPECT_EQ(result.scene.elements.size(), 100u) << "seed " << seed;
  }
}

// Hero Patterns' tic-tac-toe (rings and crosses alternating on a lattice of spacing 32) drawn
// 3 x 3 into an open 192-px exemplar, at 384 x 384: all 144 sites filled, in the checkerboard.
// Seams judged the exemplar's edge neighbourhoods by what its window cuts off, and cells of 2r
// left the patch origins one spacing of room where the kinds repeat every two: a row or column
// was dropped at the seams (121 to 126 elements).
TEST(NeighbourhoodEm, ATwoKindLatticeKeepsEverySiteAndItsCheckerboard) {  // NOLINT
  io::ReaderOptions visual;
  visual.elements = io::ElementRule::visual;
  const geometry::Scene tile =
      io::read_scene(testing::data_path("third-party/hero-patterns/tic-tac-toe.svg"), visual);
  const geometry::Scene exemplar = geometry::repeat_tile(tile, 3);
  ASSERT_EQ(exemplar.elements.size(), 36u);
  const Domain domain = Domain::from_sizes({384, 384}, Boundary::torus);
  const NeighbourhoodEm em(exemplar, Boundary::open, domain, EmOptions{});
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const geometry::Scene out = run(em, seed).scene;
    ASSERT_EQ(out.elements.size(), 144u) << "seed " << seed;
    const auto ring = [&](const geometry::Element& e) {
      return geometry::shape_size(out.shapes[static_cast<std::size_t>(e.shape)]).area > 75.0;
    };
    int off = 0;
    for (const geometry::Element& e : out.elements) {
      const geometry::Vec3 d = domain.minimum_image(e.position - out.elements.front().position);
      const double i = std::round(d.x() / 32.0), j = std::round(d.y() / 32.0);
      const bool on_site = (d - 32.0 * geometry::Vec3(i, j, 0.0)).norm() < 3.2;
      const bool same_kind = ring(e) == ring(out.elements.front());
      off += !on_site || same_kind != (std::fmod(std::abs(i + j), 2.0) == 0.0);
    }
    EXPECT_EQ(off, 0) << "seed " << seed;
  }
}

TEST(NeighbourhoodEm, EnergyNeverIncreases) {
  const geometry::Scene exemplar =
      io::read_scene(testing::data_path("svg/dots-random.svg"), io::ReaderOptions{});
  const Domain domain = Domain::from_sizes({500, 400}, Boundary::torus);
  for (const Initialisation init :
       {Initialisation::patch_copy, Initialisation::random_copy, Initialisation::incremental_add}) {
    EmOptions options;
    options.initialisation = init;
    options.tolerance = 0.0;
    const NeighbourhoodEm em(exemplar, Boundary::open, domain, options);
    const synthesis::SynthesisResult result = run(em, 2);
    ASSERT_GE(result.trace.size(), 2u) << to_string(init);
    for (std::size_t i = 1; i < result.trace.size(); ++i)
      EXPECT_LE(result.trace[i].log_density, result.trace[i - 1].log_density)
          << to_string(init) << " iteration " << i;
    EXPECT_LT(result.trace.back().log_density, result.trace.front().log_density) << to_string(init);
  }
}

TEST(NeighbourhoodEm, KCoherenceReachesBruteForceEnergy) {
  const geometry::Scene exemplar = testing::rectangle_scatter(40, 100.0, 4.0, 8.0, 11);
  const Domain domain = Domain::from_sizes({250, 250}, Boundary::torus);
  EmOptions options;
  const NeighbourhoodEm coherent(exemplar, Boundary::torus, domain, options);
  options.search = SearchRule::brute_force;
  const NeighbourhoodEm brute(exemplar, Boundary::torus, domain, options);
  double coherent_energy = 0.0, brute_energy = 0.0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    coherent_energy += run(coherent, seed).trace.back().log_density;
    brute_energy += run(brute, seed).trace.back().log_density;
  }
  EXPECT_LE(coherent_energy, 1.10 * brute_energy);
}

TEST(NeighbourhoodEm, SameSeedSameOutput) {
  const geometry::Scene exemplar = testing::rectangle_scatter(30, 100.0, 4.0, 8.0, 5);
  const Domain domain = Domain::from_sizes({200, 200}, Boundary::torus);
  const NeighbourhoodEm em(exemplar, Boundary::open, domain, EmOptions{});
  const auto a = run(em, 9), b = run(em, 9), c = run(em, 10);
  ASSERT_EQ(a.scene.elements.size(), b.scene.elements.size());
  for (std::size_t i = 0; i < a.scene.elements.size(); ++i)
    EXPECT_EQ(a.scene.elements[i].position, b.scene.elements[i].position);
  EXPECT_NE(a.trace.back().log_density, c.trace.back().log_density);
}

TEST(NeighbourhoodEm, ElementsStayInsideTheDomainShape) {
  // A disc mask of radius 80 in a 200 x 200 open domain.
  auto mask = std::make_shared<geometry::Raster>();
  mask->width = mask->height = 100;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x)
      mask->values.push_back(std::hypot(x + 0.5 - 50, y + 0.5 - 50) < 40 ? 1.0f : 0.0f);
  Domain domain = Domain::from_sizes({200, 200}, Boundary::open);
  domain.set_mask(mask);
  const geometry::Scene exemplar = testing::rectangle_scatter(40, 100.0, 4.0, 8.0, 3);
  const NeighbourhoodEm em(exemplar, Boundary::open, domain, EmOptions{});
  const synthesis::SynthesisResult result = run(em, 1);
  // About the exemplar's density over the disc (40 per 100², disc area π 80²).
  const double expected = 40.0 / 1e4 * 3.14159265 * 80 * 80;
  EXPECT_NEAR(static_cast<double>(result.scene.elements.size()), expected, 0.25 * expected);
  int outside = 0;
  for (const auto& e : result.scene.elements)
    outside += std::hypot(e.position.x() - 100, e.position.y() - 100) > 80 + 4;
  EXPECT_EQ(outside, 0);
}

TEST(NeighbourhoodEm, AConstantOrientationTurnsTheOutput) {
  // Bars 8 x 2 along x in a lattice; turned by 90 degrees they lie along y.
  const geometry::Scene exemplar = testing::rectangle_lattice(5, 12.0, 8.0, 2.0);
  const Domain domain = Domain::from_sizes({120, 120}, Boundary::torus);
  EmOptions options;
  options.samples.per_element = 1;
  options.orientation = OrientationField::constant(90.0);
  const NeighbourhoodEm em(exemplar, Boundary::torus, domain, options);
  const synthesis::SynthesisResult result = run(em, 1);
  ASSERT_FALSE(result.scene.elements.empty());
  for (const auto& e : result.scene.elements) {
    const geometry::Box3 box =
        geometry::bounding_box(result.scene.shapes[static_cast<std::size_t>(e.shape)]);
    EXPECT_NEAR(box.sizes().x(), 2.0, 1e-6);
    EXPECT_NEAR(box.sizes().y(), 8.0, 1e-6);
  }
}

TEST(NeighbourhoodEm, ElongatedElementsKeepTheirShapeFromSeveralSamples) {
  // Bars 20 x 3 in rows: several samples each (elongation from the outline), rebuilt by a rigid
  // motion: every side keeps its length.
  const geometry::Scene exemplar = testing::rectangle_lattice(5, 25.0, 20.0, 3.0);
  const Domain domain = Domain::from_sizes({200, 200}, Boundary::torus);
  const NeighbourhoodEm em(exemplar, Boundary::torus, domain, EmOptions{});
  const int per = em.exemplar().samples.count_of(0);
  EXPECT_GE(per, 3);
  const synthesis::SynthesisResult result = run(em, 2);
  ASSERT_FALSE(result.scene.elements.empty());
  for (const auto& e : result.scene.elements) {
    const auto& shape = std::get<geometry::PlanarShape>(
        result.scene.shapes[static_cast<std::size_t>(e.shape)].geometry);
    const auto& sides = shape.parts.at(0).paths.at(0).segments;
    ASSERT_EQ(sides.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k)
      EXPECT_NEAR((sides[k].end - sides[k].start).norm(), k % 2 ? 3.0 : 20.0, 1e-9);
  }
}

// A rigid exemplar rebuilt by thin-plate splines: every output element keeps its source's size
// and proportions within the documented bound (kMaxSplineDistortion, 1.5 in area and aspect).
TEST(NeighbourhoodEm, SplinesStayWithinTheDistortionBound) {
  const geometry::Scene exemplar =
      io::read_scene(testing::data_path("svg/crescents-grid.svg").string(), {});
  double smallest = 1e300, largest = 0.0;
  for (const auto& shape : exemplar.shapes) {
    smallest = std::min(smallest, geometry::shape_size(shape).area);
    largest = std::max(largest, geometry::shape_size(shape).area);
  }
  const Domain domain = Domain::from_sizes({500, 500}, Boundary::torus);
  for (const Reconstruction rule : {Reconstruction::tps, Reconstruction::tps_approx}) {
    EmOptions options;
    options.reconstruction = rule;
    const NeighbourhoodEm em(exemplar, Boundary::open, domain, options);
    for (const std::uint64_t seed : {1, 2}) {
      const synthesis::SynthesisResult result = run(em, seed);
      ASSERT_GT(result.scene.elements.size(), 50u);
      for (const auto& e : result.scene.elements) {
        const double area =
            geometry::shape_size(result.scene.shapes[static_cast<std::size_t>(e.shape)]).area;
        EXPECT_GE(area, smallest / kMaxSplineDistortion * (1 - 1e-9)) << to_string(rule);
        EXPECT_LE(area, largest * kMaxSplineDistortion * (1 + 1e-9)) << to_string(rule);
      }
    }
  }
}

// Hero Patterns' bubbles tile (17 discs) over 3 x 3 tiles: with patch copy as the paper has it
// (--copy-patches) the EM keeps large copied patches; with its diversity (the default) they stay
// small and the density is kept (seed 1: largest copied patch 0.69 against 0.12; 150 and 153
// elements against 9 × 17).
TEST(NeighbourhoodEm, DiversePatchesKeepATileFromComingOutRepeated) {
  const geometry::Scene tile = testing::bubbles_tile();
  const geometry::Domain domain =
      geometry::Domain::from_sizes({300, 300}, geometry::Boundary::torus);
  EmOptions paper;
  paper.diverse_patches = false;
  const geometry::Scene copied =
      testing::run(NeighbourhoodEm(tile, geometry::Boundary::torus, domain, paper), 1).scene;
  const geometry::Scene diverse =
      testing::run(NeighbourhoodEm(tile, geometry::Boundary::torus, domain, EmOptions{}), 1).scene;
  const metrics::Novelty a = metrics::measure_novelty(tile, copied, geometry::Boundary::torus);
  const metrics::Novelty b = metrics::measure_novelty(tile, diverse, geometry::Boundary::torus);
  EXPECT_GT(a.output.largest_patch, b.output.largest_patch);
  EXPECT_LT(b.output.largest_patch, 0.3);
  EXPECT_GT(static_cast<double>(diverse.elements.size()), 0.8 * 9 * 17);
}

TEST(NeighbourhoodEm, RefusesBadOptions) {
  const geometry::Scene exemplar = testing::rectangle_lattice(3, 10.0, 3.0, 3.0);
  const Domain domain = Domain::from_sizes({50, 50}, Boundary::torus);
  EmOptions options;
  options.rings = 0.0;
  EXPECT_THROW(NeighbourhoodEm(exemplar, Boundary::open, domain, options), core::ArgumentError);
  options = EmOptions{};
  options.k = 0;
  EXPECT_THROW(NeighbourhoodEm(exemplar, Boundary::open, domain, options), core::ArgumentError);
  geometry::Scene one = exemplar;
  one.elements.resize(1);
  EXPECT_THROW(NeighbourhoodEm(one, Boundary::open, domain, EmOptions{}), core::ArgumentError);
  EXPECT_THROW(NeighbourhoodEm(exemplar, Boundary::open,
                               Domain::from_sizes({50, 50, 50}, Boundary::torus), EmOptions{}),
               core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::methods
