// Long-range order on patterns whose order is known: a square lattice, a jittered one, a
// triangular lattice and Poisson patterns.
#include "libshapeproc/metrics/bond_order.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/metrics/metric_scenes.hpp"

namespace shapeproc::metrics {
namespace {

using geometry::Boundary;

TEST(BondOrder, ASquareLatticeHasPerfectFourFoldOrder) {
  const BondOrder b = bond_order(testing::lattice(10.0, 20, 20), Boundary::torus);
  EXPECT_NEAR(b.global4, 1.0, 1e-9);
  EXPECT_NEAR(b.local4, 1.0, 1e-9);
  EXPECT_EQ(b.symmetry(), 4);
  EXPECT_NEAR(b.order(), 1.0, 1e-9);
}

TEST(BondOrder, ATriangularLatticeHasPerfectSixFoldOrder) {
  const BondOrder b = bond_order(testing::triangular_lattice(10.0, 20, 20), Boundary::torus);
  EXPECT_NEAR(b.global6, 1.0, 1e-9);
  EXPECT_EQ(b.symmetry(), 6);
}

TEST(BondOrder, SeparatesALatticeAJitteredLatticeAndPoisson) {
  // 400 elements: a Poisson pattern's |⟨ψ⟩| has mean about √(π/4) / √N ≈ 0.044 (Rayleigh), and
  // 0.15 is more than 6 of its standard deviations (≈ 0.023) out; a lattice jittered by a fifth
  // of its spacing keeps its bonds within about ±25°, so cos(4 · 25°)-like averages stay high.
  const double lattice = bond_order(testing::lattice(10.0, 20, 20), Boundary::torus).order();
  const double jittered =
      bond_order(testing::jittered_lattice(10.0, 20, 20, 2.0, 7), Boundary::torus).order();
  EXPECT_GT(jittered, 0.5);
  EXPECT_LT(jittered, lattice - 0.05);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const BondOrder poisson =
        bond_order(testing::poisson(200.0, 200.0, 400, seed), Boundary::torus);
    EXPECT_LT(poisson.order(), 0.15) << "seed " << seed;
    EXPECT_LT(poisson.order(), jittered - 0.3) << "seed " << seed;
    // Locally, Poisson neighbourhoods have some order of their own, but far below a lattice's.
    EXPECT_GT(poisson.local6, 0.2);
    EXPECT_LT(poisson.local6, 0.6);
  }
}

TEST(BondOrder, AnOpenWindowAndFewElements) {
  // An open window: border elements' neighbours are all on one side, yet the lattice's bonds
  // still point along its axes.
  EXPECT_NEAR(bond_order(testing::lattice(10.0, 12, 12), Boundary::open).global4, 1.0, 1e-9);
  // Fewer than 7 elements: no measure in an open window; a torus is a tile of the lattice.
  EXPECT_EQ(bond_order(testing::lattice(10.0, 2, 3), Boundary::open).order(), 0.0);
  EXPECT_NEAR(bond_order(testing::lattice(10.0, 2, 2), Boundary::torus).global4, 1.0, 1e-9);
}

}  // namespace
}  // namespace shapeproc::metrics
