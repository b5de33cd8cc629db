#include "libshapeproc/model/interaction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace shapeproc::model {
namespace {

// Two categories; pair (0, 0) with two axes, pair (0, 1) with one axis, pair (1, 1) absent.
ShapeProcessModel two_category_model() {
  ShapeProcessModel m;
  m.dimension = 2;
  m.categories = {{"a", 0.5}, {"b", 0.25}};
  m.measurement.directions = 4;
  PairInteraction aa;
  aa.first = aa.second = 0;
  AxisParameters x, y;
  x.thresholds = {1.0, 2.0, 4.0};
  x.gammas = {0.5, 2.0};
  y.direction = geometry::Vec3::UnitY();
  y.thresholds = {0.5, 3.0};
  y.gammas = {0.25};
  aa.axes = {x, y};
  PairInteraction ab;
  ab.first = 0;
  ab.second = 1;
  AxisParameters iso;
  iso.thresholds = {2.0, 5.0};
  iso.gammas = {3.0};
  ab.axes = {iso, iso};
  m.interactions = {aa, ab};
  return m;
}

TEST(Interaction, BandsParametersAndLocationsOnATinyModel) {
  const Interaction interaction(two_category_model());
  EXPECT_EQ(interaction.category_count(), 2);
  // θ: β_a, β_b, then (0,0) axis 0 bands 0-1, axis 1 band 0, then (0,1) axis 0 band 0, axis 1 band
  // 0.
  EXPECT_EQ(interaction.parameter_count(), 2 + 3 + 2);
  EXPECT_DOUBLE_EQ(interaction.range(), 5.0);
  EXPECT_TRUE(interaction.interacts(0, 1));
  EXPECT_TRUE(interaction.interacts(1, 0));
  EXPECT_FALSE(interaction.interacts(1, 1));

  EXPECT_EQ(interaction.band(0, 0, 0, 0.99), Interaction::kHardCore);
  EXPECT_EQ(interaction.band(0, 0, 0, 1.0), 0);  // δ_0 ≤ d < δ_1
  EXPECT_EQ(interaction.band(0, 0, 0, 1.999), 0);
  EXPECT_EQ(interaction.band(0, 0, 0, 2.0), 1);
  EXPECT_EQ(interaction.band(0, 0, 0, 4.0), Interaction::kBeyond);
  EXPECT_EQ(interaction.band(0, 0, 1, 0.7), 0);
  EXPECT_EQ(interaction.band(0, 0, 1, 3.0), Interaction::kBeyond);
  EXPECT_EQ(interaction.band(1, 0, 0, 4.9), 0);  // the pair is unordered

  EXPECT_DOUBLE_EQ(interaction.min_hard_core(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(interaction.max_range(0, 0), 4.0);
  EXPECT_EQ(interaction.breakpoints(0, 0), (std::vector<double>{0.5, 1.0, 2.0, 3.0, 4.0}));

  EXPECT_DOUBLE_EQ(interaction.log_gamma(0, 0, 0, 1), std::log(2.0));
  EXPECT_DOUBLE_EQ(interaction.log_gamma(0, 0, 1, 0), std::log(0.25));
  EXPECT_DOUBLE_EQ(interaction.log_gamma(1, 0, 1, 0), std::log(3.0));

  // Every interaction parameter is located back where it came from; the betas come first.
  for (int c = 0; c < 2; ++c) {
    const Interaction::Location where = interaction.locate(c);
    EXPECT_EQ(where.pair, -1);
    EXPECT_EQ(where.axis, c);
  }
  const int p = interaction.parameter(0, 0, 0, 1);
  const Interaction::Location where = interaction.locate(p);
  EXPECT_EQ(where.pair, 0);
  EXPECT_EQ(where.axis, 0);
  EXPECT_EQ(where.band, 1);
  EXPECT_EQ(interaction.locate(interaction.parameter(0, 1, 1, 0)).pair, 1);
  std::vector<int> seen;
  for (int axis = 0; axis < 2; ++axis) seen.push_back(interaction.parameter(0, 1, axis, 0));
  EXPECT_NE(seen[0], seen[1]);
}

// A model file of 65,537 categories had its pair table's size wrap an int (65,537² > 2³¹) and
// was indexed past the end; validation now refuses more than kMaxCategories with the count, and
// the pair table of a model at the limit is sized and indexed in size_t.
TEST(Interaction, TooManyCategoriesAreRefusedBeforeAnyPairTable) {
  ShapeProcessModel m = two_category_model();
  m.categories.resize(65537, CategoryParameters{"c", 0.1});
  try {
    validate(m);
    FAIL() << "65,537 categories were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at most 4096 categories, got 65537"), std::string::npos)
        << e.what();
  }
  m.categories.resize(kMaxCategories);
  const Interaction at_limit(m);
  EXPECT_EQ(at_limit.band(4095, 4095, 0, 3.0), Interaction::kBeyond);
  EXPECT_EQ(at_limit.band(1, 0, 0, 3.0), 0);
}

TEST(InteractionCounts, KeepsSortedCountsAndDotsWithTheta) {
  InteractionCounts t;
  t.add(4);
  t.add(2);
  t.add(4);
  EXPECT_EQ(t.counts, (std::vector<std::pair<int, int>>{{2, 1}, {4, 2}}));
  const std::vector<double> theta = {0, 0, 0.5, 0, -1.0};
  EXPECT_DOUBLE_EQ(t.dot(theta), 0.5 - 2.0);
  t.hard_core = true;
  EXPECT_EQ(t.dot(theta), -INFINITY);
}

}  // namespace
}  // namespace shapeproc::model
