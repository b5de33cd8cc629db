// Novelty: copies, patches, repetition and the lattice exception, on scenes whose answer is known.
#include "libshapeproc/metrics/novelty.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"
#include "tests/methods/method_scenes.hpp"
#include "tests/metrics/metric_scenes.hpp"

namespace shapeproc::metrics {
namespace {

using geometry::Box3;
using geometry::Vec3;

// An irregular tile: Poisson points on a 100 × 100 window.
geometry::Scene irregular_tile() { return testing::poisson(100, 100, 20, 7); }

// The tile repeated 3 × 3 and moved by `shift`, on a 300 × 300 output.
geometry::Scene tiled_output(const geometry::Scene& tile, const Vec3& shift) {
  geometry::Scene out = tile;
  out.window = Box3(Vec3::Zero(), Vec3(300, 300, 0));
  out.elements = geometry::tile_over(tile, Box3(Vec3(-100, -100, 0), Vec3(400, 400, 0)));
  std::vector<geometry::Element> kept;
  for (geometry::Element e : out.elements) {
    e.position += shift;
    if (out.window.contains(e.position)) kept.push_back(e);
  }
  out.elements = kept;
  return out;
}

TEST(Novelty, TheTileRepeatedIsACopyEverywhere) {
  const geometry::Scene tile = irregular_tile();
  const Novelty n =
      measure_novelty(tile, tiled_output(tile, Vec3(13, 29, 0)), geometry::Boundary::torus);
  EXPECT_EQ(n.elements, 180);
  EXPECT_DOUBLE_EQ(n.output.copy, 1.0);
  EXPECT_DOUBLE_EQ(n.output.patch, 1.0);
  EXPECT_DOUBLE_EQ(n.output.largest_patch, 1.0);
  EXPECT_DOUBLE_EQ(n.output.repetition, 1.0);
  // The translation found is the shift, modulo the tile's period.
  EXPECT_NEAR(std::fmod(n.translation.x() + 1000.0, 100.0), 13.0, 1e-9);
  EXPECT_NEAR(std::fmod(n.translation.y() + 1000.0, 100.0), 29.0, 1e-9);
  EXPECT_FALSE(n.lattice_exemplar);
  EXPECT_TRUE(n.repeats_exemplar);
  EXPECT_LT(n.chance.patch, 0.1);
  EXPECT_LT(n.chance.repetition, 0.2);
}

TEST(Novelty, APoissonOutputIsNoCopy) {
  const geometry::Scene tile = irregular_tile();
  const geometry::Scene out = testing::poisson(300, 300, 180, 99);
  const Novelty n = measure_novelty(tile, out, geometry::Boundary::torus);
  EXPECT_FALSE(n.repeats_exemplar);
  // A random placement is its own chance level: within a few standard errors of a binomial share.
  const double se = std::sqrt(n.chance.copy * (1 - n.chance.copy) / 180.0);
  EXPECT_NEAR(n.output.copy, n.chance.copy, 4 * se + 0.02);
  EXPECT_LT(n.output.patch, 0.05);
  EXPECT_LT(n.output.largest_patch, 0.05);
}

TEST(Novelty, PiecesPastedAtSeveralOffsetsAreCaughtPieceByPiece) {
  // Left half the tile repeated at one offset, right half at another: t* covers one half only,
  // the largest patch one half, and the copied neighbourhoods (of any offset) most of the output.
  const geometry::Scene tile = irregular_tile();
  geometry::Scene out = tiled_output(tile, Vec3(0, 0, 0));
  const geometry::Scene other = tiled_output(tile, Vec3(37, 51, 0));
  out.elements.erase(std::remove_if(out.elements.begin(), out.elements.end(),
                                    [](const auto& e) { return e.position.x() >= 150; }),
                     out.elements.end());
  for (const auto& e : other.elements)
    if (e.position.x() >= 170) out.elements.push_back(e);
  const Novelty n = measure_novelty(tile, out, geometry::Boundary::open);
  EXPECT_GT(n.output.copy, 0.35);
  EXPECT_LT(n.output.copy, 0.75);
  EXPECT_GT(n.output.largest_patch, 0.3);
  EXPECT_LT(n.output.largest_patch, 0.75);
  EXPECT_TRUE(n.repeats_exemplar);
}

TEST(Novelty, ALatticeIsItsOwnRepeat) {
  const geometry::Scene tile = testing::lattice(20, 1, 1);  // one element per cell
  EXPECT_TRUE(is_lattice_exemplar(tile));
  EXPECT_TRUE(is_lattice_exemplar(testing::lattice(20, 4, 4)));
  EXPECT_TRUE(is_lattice_exemplar(testing::triangular_lattice(20, 4, 4)));
  EXPECT_FALSE(is_lattice_exemplar(irregular_tile()));
  EXPECT_FALSE(is_lattice_exemplar(testing::jittered_lattice(20, 4, 4, 4.0, 3)));
  // A lattice output of a lattice exemplar copies it, and is not condemned for it.
  const Novelty n = measure_novelty(testing::lattice(20, 4, 4), testing::lattice(20, 12, 12),
                                    geometry::Boundary::torus);
  EXPECT_TRUE(n.lattice_exemplar);
  EXPECT_DOUBLE_EQ(n.output.patch, 1.0);
  EXPECT_FALSE(n.repeats_exemplar);
}

TEST(Novelty, ACheckerboardOfTwoShapesIsALatticeButEveryShapeApartIsNot) {
  const auto disc = [](double side) { return testing::rectangle(side, side); };  // its size counts

  geometry::Scene checker;
  checker.window = Box3(Vec3::Zero(), Vec3(40, 40, 0));
  checker.categories.push_back({"default"});
  checker.shapes = {disc(3), disc(6)};
  checker.elements = {{0, 0, Vec3(10, 10, 0)},
                      {0, 0, Vec3(30, 30, 0)},
                      {1, 0, Vec3(30, 10, 0)},
                      {1, 0, Vec3(10, 30, 0)}};
  EXPECT_TRUE(is_lattice_exemplar(checker));
  geometry::Scene distinct = checker;
  distinct.shapes = {disc(2), disc(4), disc(6), disc(8)};
  for (int i = 0; i < 4; ++i) distinct.elements[static_cast<std::size_t>(i)].shape = i;
  EXPECT_FALSE(is_lattice_exemplar(distinct));
}

// Equal bars on a grid: all along, a lattice; turned every way at random (across or along), the
// same sizes make no lattice, since a turned shape is another shape as drawn.
TEST(Novelty, TurnedShapesAreOtherShapes) {
  geometry::Scene bars;
  bars.window = Box3(Vec3::Zero(), Vec3(80, 80, 0));
  bars.categories.push_back({"default"});
  bars.shapes = {testing::rectangle(12, 2), testing::rectangle(2, 12)};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) bars.elements.push_back({0, 0, Vec3(10 + 20 * i, 10 + 20 * j, 0)});
  EXPECT_TRUE(is_lattice_exemplar(bars));
  core::Random random(4);
  for (geometry::Element& e : bars.elements) e.shape = static_cast<int>(random.index(2));
  EXPECT_FALSE(is_lattice_exemplar(bars));
}

TEST(Novelty, BadScenesAreRefused) {
  geometry::Scene empty = irregular_tile();
  empty.elements.clear();
  EXPECT_THROW(measure_novelty(empty, irregular_tile(), geometry::Boundary::torus),
               core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::metrics
