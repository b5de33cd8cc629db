#include "libshapeproc/metrics/relations.hpp"

#include <gtest/gtest.h>

#include "tests/disc_scene.hpp"

namespace shapeproc::metrics {
namespace {

using testing::add_disc;

// A base disc of radius 10 at (50, 50); small discs of radius 2: one inside it, one across its
// rim, one just touching it from outside, one apart; and a small one inside a second base.
geometry::Scene scene() {
  geometry::Scene s;
  s.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(100, 100, 0));
  s.category_index("base");
  s.category_index("small");
  add_disc(s, 50, 50, 10, 0);
  add_disc(s, 52, 50, 2, 1);  // inside
  add_disc(s, 60, 50, 2, 1);  // across the rim
  add_disc(s, 50, 62, 2, 1);  // touching
  add_disc(s, 80, 80, 2, 1);  // apart
  add_disc(s, 20, 20, 10, 0);
  add_disc(s, 20, 20, 2, 1);  // inside the second base
  return s;
}

geometry::MeasurementOptions fine() {
  geometry::MeasurementOptions m;
  m.proxy.tolerance = geometry::kOutlineTolerance;
  return m;
}

TEST(Relations, DiscsAreApartTouchingOverlappingOrInside) {
  const geometry::Scene s = scene();
  const geometry::PairMeasurer measurer(s, fine());
  const auto shape = [&](int k) { return s.elements[static_cast<std::size_t>(k)].shape; };
  const auto offset = [&](int a, int b) {
    return geometry::Vec3(s.elements[static_cast<std::size_t>(b)].position -
                          s.elements[static_cast<std::size_t>(a)].position);
  };
  EXPECT_EQ(relation(measurer, shape(1), shape(0), offset(1, 0)), Relation::inside);
  EXPECT_EQ(relation(measurer, shape(0), shape(1), offset(0, 1)), Relation::contains);
  EXPECT_EQ(relation(measurer, shape(0), shape(2), offset(0, 2)), Relation::overlapping);
  EXPECT_EQ(relation(measurer, shape(0), shape(4), offset(0, 4)), Relation::apart);
}

TEST(Relations, CategorySharesCountElementsInsideOrOverlappingAnotherCategory) {
  const geometry::Scene s = scene();
  const CategoryRelations r = category_relations(s, geometry::PairMeasurer(s, fine()));
  ASSERT_EQ(r.nested.size(), 2u);
  // Small discs: 2 of 5 inside a base, 1 across a rim; bases: none inside, 1 of 2 overlapped.
  EXPECT_DOUBLE_EQ(r.nested[1], 2.0 / 5.0);
  EXPECT_DOUBLE_EQ(r.overlapping[1], 1.0 / 5.0);
  EXPECT_DOUBLE_EQ(r.nested[0], 0.0);
  EXPECT_DOUBLE_EQ(r.overlapping[0], 1.0 / 2.0);
}

TEST(Relations, OneCategoryHasNone) {
  geometry::Scene s = scene();
  for (auto& e : s.elements) e.category = 0;
  s.categories.resize(1);
  EXPECT_TRUE(category_relations(s, geometry::PairMeasurer(s, fine())).empty());
}

}  // namespace
}  // namespace shapeproc::metrics
