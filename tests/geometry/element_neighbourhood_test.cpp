#include "libshapeproc/geometry/element_neighbourhood.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/random.hpp"

namespace shapeproc::geometry {
namespace {

Element at(double x, double y, int category = 0) {
  Element e;
  e.position = Vec3(x, y, 0);
  e.category = category;
  return e;
}

TEST(NeighbourhoodIndex, MatchesABruteForceSearch) {
  for (bool periodic : {false, true}) {
    const Domain domain = Domain::from_sizes({40, 30}, periodic ? Boundary::torus : Boundary::open);
    core::Random random(periodic ? 5 : 6);
    std::vector<Element> elements;
    for (int i = 0; i < 300; ++i)
      elements.push_back(
          at(random.uniform(0, 40), random.uniform(0, 30), static_cast<int>(random.index(2))));
    const NeighbourhoodIndex index(elements, domain, 4.5);
    for (std::size_t c = 0; c < elements.size(); c += 7) {
      Neighbourhood expected;
      for (std::size_t j = 0; j < elements.size(); ++j) {
        const Vec3 t = domain.minimum_image(elements[j].position - elements[c].position);
        if (j != c && t.norm() < 4.5)
          expected.push_back({t, elements[j].category, static_cast<int>(j)});
      }
      const Neighbourhood found = index.of(c);
      ASSERT_EQ(found.size(), expected.size()) << "centre " << c;
      for (std::size_t k = 0; k < found.size(); ++k) {
        EXPECT_EQ(found[k].element, expected[k].element);
        EXPECT_EQ(found[k].key, expected[k].key);
        EXPECT_TRUE(found[k].offset.isApprox(expected[k].offset));
      }
    }
  }
}

TEST(NeighbourhoodIndex, RenumbersCategories) {
  const std::vector<Element> elements = {at(1, 1, 0), at(2, 1, 1)};
  const Domain domain = Domain::from_sizes({10, 10}, Boundary::open);
  const NeighbourhoodIndex index(elements, domain, 3.0, {5, -1});
  EXPECT_EQ(index.of(0).at(0).key, -1);
  EXPECT_EQ(index.of(1).at(0).key, 5);
}

TEST(NeighbourhoodDistance, ExactValuesOnTinyNeighbourhoods) {
  const double r = 2.0;
  const Neighbourhood exemplar = {{Vec3(1, 0, 0), 0, 0}, {Vec3(0, 1, 0), 0, 1}};
  // Identical: 0.
  EXPECT_DOUBLE_EQ(neighbourhood_distance(exemplar, exemplar, r), 0.0);
  // One neighbour moved by 0.5: 0.25.
  const Neighbourhood moved = {{Vec3(1.5, 0, 0), 0, 0}, {Vec3(0, 1, 0), 0, 1}};
  EXPECT_DOUBLE_EQ(neighbourhood_distance(moved, exemplar, r), 0.25);
  // An extra neighbour with no partner costs r²; a missing one costs nothing (eq. 1 sums over o').
  Neighbourhood extra = exemplar;
  extra.push_back({Vec3(-1, -1, 0), 0, 2});
  EXPECT_DOUBLE_EQ(neighbourhood_distance(extra, exemplar, r), r * r);
  EXPECT_DOUBLE_EQ(neighbourhood_distance(Neighbourhood{exemplar[0]}, exemplar, r), 0.0);
  // Another category never pairs.
  const Neighbourhood other = {{Vec3(1, 0, 0), 1, 0}};
  EXPECT_DOUBLE_EQ(neighbourhood_distance(other, exemplar, r), r * r);
}

TEST(NeighbourhoodDistance, GreedyPairingTakesTheClosestPairFirst) {
  // o0 is 0.1 from e0 and 0.3 from e1; o1 is 0.2 from e0 and 0.6 from e1. Greedy: (o0, e0) first
  // (0.01), then o1 must take e1 (0.36), total 0.37; the optimal pairing would cost 0.09 + 0.04.
  const Neighbourhood exemplar = {{Vec3(0, 0, 0), 0, 0}, {Vec3(0.4, 0, 0), 0, 1}};
  const Neighbourhood output = {{Vec3(0.1, 0, 0), 0, 0}, {Vec3(-0.2, 0, 0), 0, 1}};
  const auto pairs = match_neighbourhoods(output, exemplar, 2.0);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0], std::make_pair(0, 0));
  EXPECT_EQ(pairs[1], std::make_pair(1, 1));
  EXPECT_NEAR(neighbourhood_distance(output, exemplar, 2.0), 0.01 + 0.36, 1e-12);
}

TEST(NeighbourhoodDistance, AttributesCostAlphaAndKeysRestrictThePairs) {
  const double r = 3.0, alpha = 0.5;
  // Keys 0 and 1 (two sample ids); the exemplar's key-1 neighbour has attribute 2.
  const Neighbourhood exemplar = {{Vec3(1, 0, 0), 0, 0, 1}, {Vec3(0, 1, 0), 1, 1, 2}};
  const Neighbourhood output = {{Vec3(1, 0.5, 0), 0, 0, 1}, {Vec3(0, 1, 0), 1, 1, 1}};
  // (0.5² + 0) + (0 + α) = 0.75.
  EXPECT_DOUBLE_EQ(neighbourhood_distance(output, exemplar, r, alpha), 0.75);
  // Without α attributes are free.
  EXPECT_DOUBLE_EQ(neighbourhood_distance(output, exemplar, r), 0.25);
  // The key-0 neighbour cannot take the key-1 partner even if nearer: it is 1 away from its own.
  const Neighbourhood swapped = {{Vec3(0, 1, 0), 0, 0, 1}};
  EXPECT_DOUBLE_EQ(neighbourhood_distance(swapped, exemplar, r, alpha), 2.0);
  // A pair cost is capped at r².
  const Neighbour far{Vec3(0, 0, 0), 0, 0, 7};
  EXPECT_DOUBLE_EQ(pair_cost(far, exemplar[0], 1.2, 10.0), 1.44);
}

}  // namespace
}  // namespace shapeproc::geometry
