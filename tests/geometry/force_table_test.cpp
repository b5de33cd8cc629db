#include "libshapeproc/geometry/force_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "tests/geometry/measurement_fixtures.hpp"

namespace shapeproc::geometry {
namespace {

// A field whose direction turns with the distance from the origin: 0.8 rad per unit.
Vec3 turning_field(const Vec3& t) {
  const double turn = 0.8 * t.norm();
  return Vec3(std::cos(turn) * t.x() - std::sin(turn) * t.y(),
              std::sin(turn) * t.x() + std::cos(turn) * t.y(), 0.0);
}

TEST(ForceTable, AnswersOncePairIsOpenWithTheAxesOfTheFieldItInterpolates) {
  const DirectionBins bins(2, 8);
  constexpr std::uint32_t kOpen = 100;
  const ForceTable table(2, bins, 1, ForceTable::kDefaultMaxPoints, kOpen);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> radius(1.0, 3.0), angle(-3.14159, 3.14159);
  int answered = 0, wrong = 0;
  constexpr int kQueries = 50000;
  for (int q = 0; q < kQueries; ++q) {
    const double r = radius(rng), phi = angle(rng);
    const Vec3 t(r * std::cos(phi), r * std::sin(phi), 0.0);
    const std::optional<int> axis = table.axis(0, 0.02, t, 1e-12, turning_field);
    if (q < static_cast<int>(kOpen)) {
      EXPECT_FALSE(axis.has_value()) << "query " << q << " came before the pair opened";
      continue;
    }
    if (!axis) continue;
    ++answered;
    wrong += *axis != bins.axis_of(turning_field(t));
  }
  EXPECT_EQ(wrong, 0);
  // Only cells within a few pitches of a sector's edge are left to the caller: those within
  // w = 2s + 0.005 rad of either edge of a 0.785 rad sector, s the corners' spread, at most
  // 0.8 rad a unit times a cell's diagonal 0.028 (w ≤ 0.05 rad): at least 87% are answered.
  EXPECT_GT(answered, 0.87 * (kQueries - kOpen));
  EXPECT_EQ(table.answered(), static_cast<std::size_t>(answered));
  EXPECT_EQ(table.queries(), static_cast<std::size_t>(kQueries));
}

TEST(ForceTable, AFullTableLeavesQueriesThatNeedNewPointsToTheCaller) {
  const DirectionBins bins(2, 8);
  const ForceTable table(2, bins, 1, 4, 0);
  int computed = 0;
  const auto field = [&](const Vec3& t) {
    ++computed;
    return turning_field(t);
  };
  const Vec3 inside(1.005, 0.005, 0.0);  // the cell [1, 1.01] x [0, 0.01] at pitch 0.01
  ASSERT_TRUE(table.axis(0, 0.01, inside, 1e-12, field).has_value());
  EXPECT_EQ(table.points(), 4u);
  EXPECT_EQ(computed, 4);
  EXPECT_TRUE(table.axis(0, 0.01, Vec3(1.002, 0.008, 0.0), 1e-12, field).has_value());
  EXPECT_FALSE(table.axis(0, 0.01, Vec3(2.5, 0.5, 0.0), 1e-12, field).has_value());
  EXPECT_EQ(computed, 4);
  EXPECT_EQ(table.points(), 4u);
}

// Two gears (radius 1 and 0.9 alternating, like a stamp's perforations) and a random polygon:
// detailed pairs, queried touching, interlocking and apart.
Scene detailed_shapes() {
  std::vector<Vec2> gear;
  constexpr int kTeeth = 120;
  for (int k = 0; k < kTeeth; ++k) {
    const double angle = 2 * 3.14159265358979323846 * k / kTeeth, r = k % 2 == 0 ? 1.0 : 0.9;
    gear.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  std::mt19937 rng(3);
  return fixtures::scene_of(
      {fixtures::planar({fixtures::polygon(gear)}), fixtures::random_polygon(rng, 100, 0.8)},
      {{0, 0}, {3, 0}});
}

TEST(ForceTable, MeasurerAxesOfDetailedPairsEqualTheExactAxes) {
  const Scene scene = detailed_shapes();
  MeasurementOptions options;
  options.proxy.tolerance = 0.0;
  const PairMeasurer measurer(scene, options);
  ASSERT_NE(measurer.force_table(), nullptr);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-2.2, 2.2);
  std::uniform_int_distribution<int> shape(0, 1);
  int wrong = 0;
  constexpr int kQueries = 40000;
  for (int q = 0; q < kQueries; ++q) {
    const int a = shape(rng), b = shape(rng);
    const Vec3 t(coordinate(rng), coordinate(rng), 0.0);
    wrong += measurer.axis(a, b, t) != measurer.bins().axis_of(measurer.direction(a, b, t));
  }
  EXPECT_EQ(wrong, 0);
  // The table saw the offsets whose circles about the centroids are near (the rest are the
  // pair's expansion's), the three pairs opened, and it answered most of them.
  const ForceTable& table = *measurer.force_table();
  EXPECT_GT(table.queries(), static_cast<std::size_t>(0.9 * kQueries));
  EXPECT_GT(table.answered(), table.queries() / 2);
}

}  // namespace
}  // namespace shapeproc::geometry
