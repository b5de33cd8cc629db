#include "libshapeproc/sample/domain_decomposition.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/raster.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/sample/cell_layout.hpp"
#include "tests/point_model.hpp"
#include "tests/sample/hard_core_check.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::sample {
namespace {

using geometry::Box3;
using geometry::Vec3;

// A 100 × 100 torus in cells of at least 20: 5 fit, an odd count, so 4 of 25 per axis. Two
// cells of one colour are never neighbours, every point lies in the box of the cell that holds
// it (up to a period), and the cell around a point's cell is never the cell itself.
TEST(CellLayout, ColoursKeepNeighboursApartOnATorus) {
  const geometry::Domain torus =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::torus);
  std::optional<CellLayout> layout = CellLayout::plan(torus, 20.0);
  ASSERT_TRUE(layout);
  EXPECT_EQ(layout->count(), 16);
  EXPECT_EQ(layout->colours(), 4);
  EXPECT_DOUBLE_EQ(layout->side().x(), 25.0);
  layout->set_offset(Vec3(7, 13, 0));
  for (int c = 0; c < layout->count(); ++c) {
    const std::vector<int> around = layout->around(c);
    EXPECT_EQ(around.size(), 8U);
    for (int other : around) EXPECT_NE(layout->colour(other), layout->colour(c));
  }
  core::Random random(3);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 p(random.uniform(0, 100), random.uniform(0, 100), 0);
    const int c = layout->cell_of(p);
    const Box3 box = layout->box(c);
    const Vec3 q = layout->image_near(p, box.center());
    EXPECT_TRUE(q.x() >= box.min().x() - 1e-9 && q.x() <= box.max().x() + 1e-9) << p.transpose();
    EXPECT_TRUE(q.y() >= box.min().y() - 1e-9 && q.y() <= box.max().y() + 1e-9) << p.transpose();
  }
  // Too small: 3 cells of 30 per axis round down to 2, under the 4 a torus needs.
  EXPECT_FALSE(CellLayout::plan(torus, 30.0));
}

// A strip: a 160 × 8 torus in cells of at least 3 is cut into 52 along its length and not at
// all across (8 holds 2 cells of 3, under the 4 a torus needs): every cell spans the strip's
// width and wraps around it.
TEST(CellLayout, AThinAxisIsNotCut) {
  const geometry::Domain strip = geometry::Domain::from_sizes({160, 8}, geometry::Boundary::torus);
  std::optional<CellLayout> layout = CellLayout::plan(strip, 3.0);
  ASSERT_TRUE(layout);
  EXPECT_EQ(layout->count(), 52);
  EXPECT_TRUE(layout->cut(0));
  EXPECT_FALSE(layout->cut(1));
  EXPECT_EQ(layout->spanned_period(), Vec3(0, 8, 0));
  layout->set_offset(Vec3(1.5, 2.5, 0));
  EXPECT_EQ(layout->box(7).min().y(), 0.0);
  EXPECT_EQ(layout->box(7).max().y(), 8.0);
  EXPECT_EQ(layout->around(7).size(), 2U);
  EXPECT_EQ(layout->cell_of(Vec3(1.6, 7.9, 0)), layout->cell_of(Vec3(1.6, 0.1, 0)));
}

// An open 100 × 60 domain in cells of 20 (5 × 3) gets one partial cell more along each axis; the
// cells' boxes tile the domain whatever the offset.
TEST(CellLayout, AnOpenDomainIsTiledByItsShiftedCells) {
  const geometry::Domain open = geometry::Domain::from_sizes({100, 60}, geometry::Boundary::open);
  std::optional<CellLayout> layout = CellLayout::plan(open, 20.0);
  ASSERT_TRUE(layout);
  EXPECT_EQ(layout->count(), 6 * 4);
  layout->set_offset(Vec3(5, 11, 0));
  double total = 0.0;
  for (int c = 0; c < layout->count(); ++c) total += geometry::measure(layout->box(c), 2);
  EXPECT_NEAR(total, 6000.0, 1e-9);
  EXPECT_EQ(layout->cell_of(Vec3(0, 0, 0)), 0);
  EXPECT_EQ(layout->cell_of(Vec3(99.9, 59.9, 0)), layout->count() - 1);
}

const char* const kSquares = testing::kSquaresModel;

SampleResult decomposed(const model::ShapeProcessModel& m, const geometry::Domain& domain,
                        std::uint64_t seed, int threads) {
  SamplerOptions options;
  options.decompose = true;
  options.threads = threads;
  const ShapeProcessSampler sampler(m, domain, options);
  core::Random random(seed);
  return sampler.sample(random);
}

// An intensity map on a torus scales β in every cell (left half 0.25, right half 0.75: of a
// Poisson pattern's points, 3/4 fall on the right). A cell's chain runs on an open box about it
// and reads the torus's map at positions wrapped into it; it had read none, and the halves came
// out equal.
TEST(DomainDecomposition, AnIntensityMapOnATorusScalesEveryCell) {
  const model::ShapeProcessModel m = testing::point_model(0.05);
  geometry::Domain domain = geometry::Domain::from_sizes({200, 200}, geometry::Boundary::torus);
  geometry::Raster map;
  map.width = 2;
  map.height = 1;
  map.values = {0.25f, 0.75f};
  domain.set_intensity(std::make_shared<const geometry::Raster>(map));
  int left = 0, right = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const SampleResult out = decomposed(m, domain, seed, 2);
    ASSERT_GT(out.cells, 0) << "the domain is decomposed";
    for (const geometry::Element& e : out.scene.elements) (e.position.x() < 100 ? left : right)++;
  }
  const double n = left + right;
  EXPECT_NEAR(n / 3, 0.05 * 40000 * 0.5, 4 * std::sqrt(1000.0 / 3));
  EXPECT_NEAR(right / n, 0.75, 4 * std::sqrt(0.75 * 0.25 / n));
}

// The decomposed output depends on the seed alone, not on the threads; it keeps every hard core,
// across cell boundaries and the torus's seam.
TEST(DomainDecomposition, SameSeedSameOutputWithAnyThreadsAndNoHardCoreBroken) {
  const model::ShapeProcessModel m = io::parse_model(kSquares, "squares.json");
  const geometry::Domain domain =
      geometry::Domain::from_sizes({120, 120}, geometry::Boundary::torus);
  const SampleResult one = decomposed(m, domain, 5, 1);
  const SampleResult two = decomposed(m, domain, 5, 2);
  ASSERT_GT(one.cells, 0) << "the domain is decomposed";
  // The automatic rule stopped on its test, whose quarters the result keeps.
  EXPECT_TRUE(one.stationary);
  EXPECT_TRUE(one.trend.stationary);
  EXPECT_GT(one.trend.first, 0.0);
  // Its elements' mean nearest distance, once per sweep, passed the same test.
  EXPECT_TRUE(one.spacing_trend.stationary);
  EXPECT_GT(one.spacing_trend.first, 0.0);
  EXPECT_GE(one.sweeps, 20);
  ASSERT_GT(one.scene.elements.size(), 50U);
  ASSERT_EQ(one.scene.elements.size(), two.scene.elements.size());
  for (std::size_t i = 0; i < one.scene.elements.size(); ++i)
    EXPECT_EQ(one.scene.elements[i].position, two.scene.elements[i].position);
  EXPECT_EQ(testing::hard_core_violations(one.scene, m), std::vector<std::string>{});
}

// A start configuration is kept where the hard core allows: of two points 0.5 apart (hard core
// 1), whichever cell is visited second refuses its own.
TEST(DomainDecomposition, AStartKeepsWhatTheHardCoreAllows) {
  const model::ShapeProcessModel m = testing::point_model(0.08, {1.0, 3.0}, {0.4});
  const geometry::Domain domain = geometry::Domain::from_sizes({40, 40}, geometry::Boundary::torus);
  SamplerOptions options;
  options.decompose = true;
  options.iterations = 10;
  options.start = {{0, 0, Vec3(10, 10, 0)}, {0, 0, Vec3(10.5, 10, 0)}, {0, 0, Vec3(30, 30, 0)}};
  const ShapeProcessSampler sampler(m, domain, options);
  core::Random random(4);
  const SampleResult r = sampler.sample(random);
  ASSERT_GT(r.cells, 0);
  EXPECT_EQ(r.start_kept, 2);
  EXPECT_EQ(r.start_left_out, 1);
}

// Count, close pairs and mean nearest-neighbour distance of points on a torus.
struct PointMoments {
  double count = 0, pairs = 0, nearest = 0;
};

PointMoments moments(const std::vector<geometry::Element>& points, double size, double r) {
  PointMoments m;
  m.count = static_cast<double>(points.size());
  double nearest_sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    double nearest = size;
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (i == j) continue;
      const Vec3 d =
          geometry::minimum_image(points[j].position - points[i].position, Vec3(size, size, 0));
      const double distance = d.norm();
      nearest = std::min(nearest, distance);
      if (j > i && distance < r) m.pairs += 1;
    }
    nearest_sum += nearest;
  }
  m.nearest = points.empty() ? 0 : nearest_sum / static_cast<double>(points.size());
  return m;
}

// A Strauss process (β 0.08, hard core 1, γ 0.4 up to 3) on a 40 × 40 torus, in 144 cells:
// 60 outputs of the decomposed sampler (its automatic stopping rule, as users run it) and 60 of
// the whole-domain chain run 300,000 steps (about 5,000 per element): their means of the count,
// the pairs closer than 3 and the mean nearest distance agree within 3 standard errors of the
// difference. (The whole-domain chain's own automatic rule stops low on this model: 56.5 elements
// against 60.0 over 400 runs; docs/sample.md.)
TEST(DomainDecomposition, MomentsAgreeWithTheWholeDomainChain) {
  const model::ShapeProcessModel m = testing::point_model(0.08, {1.0, 3.0}, {0.4});
  const geometry::Domain domain = geometry::Domain::from_sizes({40, 40}, geometry::Boundary::torus);
  constexpr int kRuns = 60;
  std::vector<PointMoments> cut, whole;
  for (int run = 0; run < kRuns; ++run) {
    const SampleResult a = decomposed(m, domain, 100 + static_cast<std::uint64_t>(run), 2);
    ASSERT_GT(a.cells, 0);
    cut.push_back(moments(a.scene.elements, 40, 3));
    core::Random random(500 + static_cast<std::uint64_t>(run));
    SamplerOptions long_run;
    long_run.iterations = 300000;
    const SampleResult b = sample_shape_process(m, domain, long_run, random);
    whole.push_back(moments(b.scene.elements, 40, 3));
  }
  const auto compare = [&](double PointMoments::*field, const char* name) {
    double ma = 0, mb = 0, va = 0, vb = 0;
    for (int i = 0; i < kRuns; ++i) {
      ma += cut[static_cast<std::size_t>(i)].*field / kRuns;
      mb += whole[static_cast<std::size_t>(i)].*field / kRuns;
    }
    for (int i = 0; i < kRuns; ++i) {
      va += std::pow(cut[static_cast<std::size_t>(i)].*field - ma, 2) / (kRuns - 1);
      vb += std::pow(whole[static_cast<std::size_t>(i)].*field - mb, 2) / (kRuns - 1);
    }
    const double se = std::sqrt(va / kRuns + vb / kRuns);
    EXPECT_NEAR(ma, mb, 3 * se) << name << ": decomposed " << ma << ", whole " << mb;
  };
  compare(&PointMoments::count, "count");
  compare(&PointMoments::pairs, "pairs closer than 3");
  compare(&PointMoments::nearest, "mean nearest distance");
}

}  // namespace
}  // namespace shapeproc::sample

namespace shapeproc::sample {
namespace {

// The same Strauss process on a 320 × 8 torus strip, cut along its length only (the cells wrap
// across it): 60 decomposed outputs against 60 whole-domain outputs of 300,000 steps, mean count
// and close pairs within 3 standard errors of the difference.
TEST(DomainDecomposition, AStripCutAlongItsLengthKeepsTheModel) {
  const model::ShapeProcessModel m = testing::point_model(0.08, {1.0, 3.0}, {0.4});
  const geometry::Domain strip = geometry::Domain::from_sizes({320, 8}, geometry::Boundary::torus);
  constexpr int kRuns = 60;
  double count[2] = {0, 0}, count2[2] = {0, 0}, pairs[2] = {0, 0}, pairs2[2] = {0, 0};
  for (int run = 0; run < kRuns; ++run) {
    for (int whole = 0; whole < 2; ++whole) {
      SamplerOptions options;
      options.decompose = whole == 0;
      if (whole) options.iterations = 300000;
      const ShapeProcessSampler sampler(m, strip, options);
      core::Random random(static_cast<std::uint64_t>(1000 * whole + run + 1));
      const SampleResult r = sampler.sample(random);
      if (whole == 0) {
        ASSERT_GT(r.cells, 0);
      }
      double close = 0;
      const auto& e = r.scene.elements;
      for (std::size_t i = 0; i < e.size(); ++i)
        for (std::size_t j = i + 1; j < e.size(); ++j)
          if (geometry::minimum_image(e[j].position - e[i].position, Vec3(320, 8, 0)).norm() < 3)
            close += 1;
      const double n = static_cast<double>(e.size());
      count[whole] += n / kRuns;
      count2[whole] += n * n / kRuns;
      pairs[whole] += close / kRuns;
      pairs2[whole] += close * close / kRuns;
    }
  }
  const auto se = [&](const double* mean, const double* square) {
    double v = 0;
    for (int k = 0; k < 2; ++k) v += (square[k] - mean[k] * mean[k]) / (kRuns - 1);
    return std::sqrt(v);
  };
  EXPECT_NEAR(count[0], count[1], 3 * se(count, count2));
  EXPECT_NEAR(pairs[0], pairs[1], 3 * se(pairs, pairs2));
}

// No seam: pairs closer than 3 cross the last sweep's cell boundaries as often as a stationary
// pattern's would. A pair d apart, placed at random, crosses the lines x = o + k s or y = o + k s
// with probability p(d) = |d_x| / s + |d_y| / s − |d_x| |d_y| / s²; over 40 outputs of a Strauss
// process on a 160 × 160 torus in 16 cells of 40, the crossing pairs' count is within 3 standard
// deviations (Σ p (1 − p)) of Σ p. (A sampler that handled the boundaries wrongly would thin or
// crowd the pairs there.)
TEST(DomainDecomposition, PairsCrossCellBoundariesAsOftenAsAnywhere) {
  const model::ShapeProcessModel m = testing::point_model(0.08, {1.0, 3.0}, {0.4});
  const geometry::Domain domain =
      geometry::Domain::from_sizes({160, 160}, geometry::Boundary::torus);
  double crossing = 0, expected = 0, variance = 0;
  for (std::uint64_t run = 0; run < 40; ++run) {
    SamplerOptions options;
    options.decompose = true;
    const ShapeProcessSampler sampler(m, domain, options);
    core::Random random(900 + run);
    const SampleResult r = sampler.sample(random);
    ASSERT_EQ(r.cells, 16);
    const Vec3 side = r.cell_side, offset = r.cell_offset;
    const auto& points = r.scene.elements;
    const auto cell = [&](double v, int axis) {
      return std::floor((v - offset[axis]) / side[axis]);
    };
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (std::size_t j = i + 1; j < points.size(); ++j) {
        const Vec3 d =
            geometry::minimum_image(points[j].position - points[i].position, Vec3(160, 160, 0));
        if (d.norm() >= 3) continue;
        const Vec3 a = points[i].position, b = a + d;  // b unwrapped next to a
        const bool crosses = cell(a.x(), 0) != cell(b.x(), 0) || cell(a.y(), 1) != cell(b.y(), 1);
        const double px = std::abs(d.x()) / side.x(), py = std::abs(d.y()) / side.y();
        const double p = px + py - px * py;
        crossing += crosses ? 1 : 0;
        expected += p;
        variance += p * (1 - p);
      }
    }
  }
  ASSERT_GT(expected, 100) << "the test needs crossing pairs";
  EXPECT_NEAR(crossing, expected, 3 * std::sqrt(variance));
}

}  // namespace
}  // namespace shapeproc::sample
