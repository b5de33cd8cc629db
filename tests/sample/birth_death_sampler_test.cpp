#include "libshapeproc/sample/birth_death_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"
#include "tests/point_model.hpp"
#include "tests/sample/hard_core_check.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::sample {
namespace {

using geometry::Box3;
using geometry::Vec3;

SampleResult sample_with_seed(const model::ShapeProcessModel& m, const geometry::Domain& domain,
                              const SamplerOptions& options, std::uint64_t seed) {
  core::Random random(seed);
  return sample_shape_process(m, domain, options, random);
}

TEST(BirthDeath, PoissonCountsFollowPoisson) {
  // γ = 1 everywhere: the number of elements is Poisson(β|D|) = Poisson(20).
  const model::ShapeProcessModel m = testing::point_model(0.01);
  const geometry::Domain domain = geometry::Domain::from_sizes({50, 40}, geometry::Boundary::torus);
  const int runs = 300;
  std::vector<double> counts;
  for (int seed = 1; seed <= runs; ++seed) {
    SamplerOptions options;
    options.iterations = 4000;
    counts.push_back(
        static_cast<double>(sample_with_seed(m, domain, options, static_cast<std::uint64_t>(seed))
                                .scene.elements.size()));
  }
  double mean = 0, variance = 0;
  for (double c : counts) mean += c / runs;
  for (double c : counts) variance += (c - mean) * (c - mean) / (runs - 1);
  // Mean: standard error sqrt(20 / 300); dispersion s²/mean: sd about sqrt(2 / 299). 4 of each.
  EXPECT_NEAR(mean, 20.0, 4 * std::sqrt(20.0 / runs));
  EXPECT_NEAR(variance / mean, 1.0, 4 * std::sqrt(2.0 / (runs - 1)));
}

TEST(BirthDeath, AChainThatRunsAwayStopsNamingItsAttraction) {
  // γ 30 within 3 and no hard core: the count grows without bound; the stop at 300 elements
  // (Poisson: 20 expected) ends it with the attraction named.
  const model::ShapeProcessModel m = testing::point_model(0.01, {0.0, 3.0}, {30.0});
  const geometry::Domain domain = geometry::Domain::from_sizes({50, 40}, geometry::Boundary::torus);
  SamplerOptions options;
  options.runaway_count = 300;
  try {
    sample_with_seed(m, domain, options, 1);
    FAIL() << "no runaway";
  } catch (const core::ArgumentError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("ran away: 301 elements, past 300"), std::string::npos) << text;
    EXPECT_NE(text.find("γ 30 between 'points' and 'points' at distances 0 to 3"),
              std::string::npos)
        << text;
  }
  // Without the limit, and with γ = 1, the same chain is a Poisson process of 20 elements.
  options.runaway_count = 300;
  options.iterations = 4000;
  EXPECT_LT(sample_with_seed(testing::point_model(0.01), domain, options, 1).scene.elements.size(),
            300u);
}

// Border correction: fixed elements stay where they are, free ones are born only in the free
// region and keep the hard core against the fixed ones. Free points (category 0) do not interact
// with each other, only with the fixed kind (category 1, β ≈ 0: never born), so their count is
// Poisson with mean β (|R| − the disc the fixed point in R excludes) (300 chains, 4 standard
// errors).
TEST(BirthDeath, FixedElementsStayAndBirthsKeepToTheFreeRegion) {
  model::ShapeProcessModel m = testing::point_model(0.02);  // two categories: half the births each
  m.categories.push_back({"fixed", 1e-300});
  model::PairInteraction pair;
  pair.first = 0;
  pair.second = 1;
  model::AxisParameters axis;
  axis.thresholds = {3.0, 3.0};  // hard core below 3, no band
  axis.gammas = {1.0};
  pair.axes = {axis};
  m.interactions = {pair};
  const geometry::Domain domain = geometry::Domain::from_sizes({60, 60}, geometry::Boundary::open);
  SamplerOptions options;
  options.iterations = 4000;
  options.free_region = geometry::Box3(geometry::Vec3(10, 10, 0), geometry::Vec3(50, 50, 0));
  options.fixed = {{0, 1, geometry::Vec3(5, 5, 0)}, {0, 1, geometry::Vec3(30, 30, 0)}};
  const int runs = 300;
  double mean = 0;
  for (int seed = 1; seed <= runs; ++seed) {
    const SampleResult r = sample_with_seed(m, domain, options, static_cast<std::uint64_t>(seed));
    int fixed_seen = 0;
    for (const geometry::Element& e : r.scene.elements) {
      const bool fixed = (e.position - geometry::Vec3(5, 5, 0)).norm() == 0 ||
                         (e.position - geometry::Vec3(30, 30, 0)).norm() == 0;
      fixed_seen += fixed;
      if (!fixed) {
        ASSERT_TRUE(options.free_region.contains(e.position)) << e.position.transpose();
        ASSERT_GE((e.position - geometry::Vec3(30, 30, 0)).norm(), 3.0);
      }
    }
    ASSERT_EQ(fixed_seen, 2);
    mean += static_cast<double>(r.scene.elements.size() - 2) / runs;
  }
  // β |R| = 32, less the disc of radius 3 the fixed element at (30, 30) excludes: 32 − 0.565.
  const double expected = 0.02 * (1600 - 9 * 3.14159265358979);
  EXPECT_NEAR(mean, expected, 4 * std::sqrt(expected / runs));
}

const char* const kSquares = testing::kSquaresModel;

// A start configuration: elements the hard core allows are kept (and then moved and removed like
// any other), one closer than the hard core to one before it and one outside the domain are left
// out.
TEST(BirthDeath, AStartConfigurationKeepsWhatTheHardCoreAllows) {
  const model::ShapeProcessModel m = testing::point_model(1e-300, {3.0, 3.0}, {1.0});  // no births
  const geometry::Domain domain = geometry::Domain::from_sizes({60, 60}, geometry::Boundary::open);
  SamplerOptions options;
  options.iterations = 1;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) options.start.push_back({0, 0, Vec3(2.5 + 5 * x, 2.5 + 5 * y, 0)});
  options.start.push_back({0, 0, Vec3(3.5, 2.5, 0)});  // 1 from the first: inside its hard core
  options.start.push_back({0, 0, Vec3(70, 30, 0)});    // outside the domain
  const SampleResult r = sample_with_seed(m, domain, options, 3);
  EXPECT_EQ(r.start_kept, 144);
  EXPECT_EQ(r.start_left_out, 2);
  EXPECT_GE(r.scene.elements.size(), 143u);  // one step: at most one death
  // A start element of a category the model does not have is refused up front.
  options.start.push_back({0, 4, Vec3(10, 10, 0)});
  EXPECT_THROW(ShapeProcessSampler(m, domain, options), core::ArgumentError);
}

// From a start four times too full, the chain still reaches its target: the count of a Poisson
// process of mean 50 after 20,000 steps, over 40 chains, within 4 standard errors of 50.
TEST(BirthDeath, FromAFullStartTheChainReachesItsTarget) {
  const model::ShapeProcessModel m = testing::point_model(0.02);
  const geometry::Domain domain = geometry::Domain::from_sizes({50, 50}, geometry::Boundary::torus);
  SamplerOptions options;
  options.iterations = 20000;
  core::Random place(1);
  for (int i = 0; i < 200; ++i)
    options.start.push_back({0, 0, Vec3(place.uniform(0, 50), place.uniform(0, 50), 0)});
  const int chains = 40;
  double mean = 0.0;
  for (int seed = 1; seed <= chains; ++seed)
    mean += static_cast<double>(sample_with_seed(m, domain, options, seed).scene.elements.size());
  mean /= chains;
  EXPECT_NEAR(mean, 50.0, 4.0 * std::sqrt(50.0 / chains));
}

// The compressing burn-in's schedule, exactly: B for its first phase, then B falling linearly to
// 0 over as many steps, then done; off, it is done from the start.
TEST(Compression, TheBoostHoldsThenFallsLinearly) {
  CompressionOptions c;
  c.burn_in_kind = model::BurnIn::compressing;
  c.release_steps = 10;
  c.log_boost = 2.0;
  CompressionSchedule schedule(c);
  std::vector<double> boosts;
  for (long long step = 1; !schedule.done(); ++step) {
    boosts.push_back(schedule.log_boost());
    schedule.after_step(step, 0);
  }
  ASSERT_EQ(boosts.size(), 20u);
  for (std::size_t k = 0; k < 11; ++k) EXPECT_DOUBLE_EQ(boosts[k], 2.0) << k;
  for (std::size_t k = 11; k < 20; ++k)
    EXPECT_DOUBLE_EQ(boosts[k], 2.0 * (1.0 - static_cast<double>(k - 10) / 10.0));
  EXPECT_EQ(schedule.finished_at(), 20);
  EXPECT_EQ(schedule.compressed_for(), 10);
  EXPECT_TRUE(CompressionSchedule({}).done());
  c.log_boost = -1.0;
  EXPECT_THROW(CompressionSchedule{c}, core::ArgumentError);
}

// Hard discs of diameter 9.5 at a large β on a 100 x 100 torus: from empty the plain chain jams
// near random sequential filling; the compressing burn-in (hard cores grown from half their size
// in 10 stages, then β released) packs a little more (about 4%), with no hard-core violation,
// records its steps, and the chain after it is the model's (the same seed, the same output). Given
// steps need the burn-in's own, fewer than half of them.
TEST(BirthDeath, TheCompressingBurnInPacksPastRandomFilling) {
  const model::ShapeProcessModel m = testing::point_model(1e6, {9.5, 9.5}, {1.0});
  const geometry::Domain domain =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::torus);
  SamplerOptions plain;
  plain.iterations = 60000;
  SamplerOptions compressed = plain;
  compressed.compression.burn_in_kind = model::BurnIn::compressing;
  compressed.compression.steps = 20000;
  compressed.compression.release_steps = 20000;
  compressed.compression.stages = 10;
  // Over 6 seeds, the mean counts apart by more than 2.5 standard errors of their difference.
  double plain_sum = 0, plain_squares = 0, compressed_sum = 0, compressed_squares = 0;
  const int seeds = 6;
  for (int seed = 1; seed <= seeds; ++seed) {
    const double x =
        static_cast<double>(sample_with_seed(m, domain, plain, seed).scene.elements.size());
    const double y =
        static_cast<double>(sample_with_seed(m, domain, compressed, seed).scene.elements.size());
    plain_sum += x;
    plain_squares += x * x;
    compressed_sum += y;
    compressed_squares += y * y;
  }
  const double plain_mean = plain_sum / seeds, compressed_mean = compressed_sum / seeds;
  const double variance = (plain_squares / seeds - plain_mean * plain_mean +
                           compressed_squares / seeds - compressed_mean * compressed_mean) *
                          seeds / (seeds - 1.0);
  // Seeds 1–6: 84.7 against 88.3, standard error of the difference 1.2 (a gain of 4%).
  EXPECT_GT(compressed_mean - plain_mean, 2.5 * std::sqrt(variance / seeds))
      << compressed_mean << " against " << plain_mean;
  const SampleResult b = sample_with_seed(m, domain, compressed, 3);
  EXPECT_EQ(b.compression_steps, 10 * 20000 + 2 * 20000);  // 10 growth stages, boost, release
  EXPECT_GT(b.compressed_count, 0);
  EXPECT_EQ(testing::hard_core_violations(b.scene, m), std::vector<std::string>{});
  const SampleResult again = sample_with_seed(m, domain, compressed, 3);
  ASSERT_EQ(again.scene.elements.size(), b.scene.elements.size());
  for (std::size_t i = 0; i < b.scene.elements.size(); ++i)
    EXPECT_EQ(again.scene.elements[i].position, b.scene.elements[i].position);
  compressed.compression.release_steps = 30000;
  EXPECT_THROW(ShapeProcessSampler(m, domain, compressed), core::ArgumentError);
  // Automatic steps: the rule starts once the burn-in is over.
  SamplerOptions automatic;
  automatic.compression.burn_in_kind = model::BurnIn::compressing;
  const SampleResult c = sample_with_seed(m, domain, automatic, 4);
  EXPECT_GT(c.compression_steps, 0);
  EXPECT_GT(c.iterations, c.compression_steps);
}

// The same discs (with a neutral band out to 12, so that the neighbour grid reaches the offsets)
// and a square lattice's neighbour offsets (spacing 10): grown as a crystal, from one element by
// births at the offsets, the chain fills the torus's 100 sites, where the growing hard cores jam
// near 88; no hard core is violated, and the count holds through exact Metropolis–Hastings at
// the model.
TEST(BirthDeath, ACrystalsGrowthFillsTheLattice) {
  model::ShapeProcessModel m = testing::point_model(1e6, {9.5, 12.0}, {1.0});
  for (const Vec3& d : {Vec3(10, 0, 0), Vec3(-10, 0, 0), Vec3(0, 10, 0), Vec3(0, -10, 0)})
    m.neighbour_offsets.offsets.push_back({0, 0, d, 1.0});
  m.neighbour_offsets.radii = {0.1, 1.0};
  const geometry::Domain domain =
      geometry::Domain::from_sizes({100, 100}, geometry::Boundary::torus);
  SamplerOptions crystal;
  crystal.iterations = 60000;
  crystal.compression.burn_in_kind = model::BurnIn::crystal;
  crystal.compression.steps = 4000;
  crystal.compression.release_steps = 10000;
  for (int seed = 1; seed <= 3; ++seed) {
    const SampleResult r = sample_with_seed(m, domain, crystal, seed);
    EXPECT_GE(r.scene.elements.size(), 98u) << seed;
    EXPECT_GT(r.growth_moves.births_accepted, 90) << seed;
    EXPECT_EQ(testing::hard_core_violations(r.scene, m), std::vector<std::string>{});
  }
  // Without offsets the growth is the hard cores' (no crystal to grow).
  m.neighbour_offsets = {};
  EXPECT_LT(sample_with_seed(m, domain, crystal, 1).scene.elements.size(), 95u);
}

TEST(BirthDeath, HardCoreIsNeverViolated) {
  const model::ShapeProcessModel m = io::parse_model(kSquares, "squares.json");
  const geometry::Domain domain = geometry::Domain::from_sizes({60, 60}, geometry::Boundary::torus);
  SamplerOptions options;
  options.iterations = 30000;
  const SampleResult result = sample_with_seed(m, domain, options, 11);
  ASSERT_GT(result.scene.elements.size(), 10u);
  EXPECT_EQ(testing::hard_core_violations(result.scene, m), std::vector<std::string>{});
}

TEST(BirthDeath, SameSeedSameOutput) {
  const model::ShapeProcessModel m = io::parse_model(kSquares, "squares.json");
  const geometry::Domain domain = geometry::Domain::from_sizes({40, 40}, geometry::Boundary::torus);
  SamplerOptions options;
  options.iterations = 5000;
  const SampleResult a = sample_with_seed(m, domain, options, 5);
  const SampleResult b = sample_with_seed(m, domain, options, 5);
  ASSERT_EQ(a.scene.elements.size(), b.scene.elements.size());
  for (std::size_t i = 0; i < a.scene.elements.size(); ++i)
    EXPECT_EQ(a.scene.elements[i].position, b.scene.elements[i].position);
  const SampleResult c = sample_with_seed(m, domain, options, 6);
  EXPECT_TRUE(c.scene.elements.size() != a.scene.elements.size() ||
              c.scene.elements.front().position != a.scene.elements.front().position);
}

// A sampler given the proxies of another model with the same shapes and thresholds (an earlier
// maximum-likelihood iteration's) runs the chain it would run with its own.
TEST(BirthDeath, ASharedChainGeometryGivesTheSameChain) {
  const model::ShapeProcessModel earlier = io::parse_model(kSquares, "squares.json");
  model::ShapeProcessModel m = earlier;
  m.categories[0].beta = 0.35;
  for (model::AxisParameters& axis : m.interactions[0].axes) axis.gammas[0] = 0.8;
  const geometry::Domain domain = geometry::Domain::from_sizes({40, 40}, geometry::Boundary::torus);
  SamplerOptions options;
  options.iterations = 5000;
  const SampleResult own = sample_with_seed(m, domain, options, 5);
  options.geometry =
      std::make_shared<const ChainGeometry>(earlier, model::Interaction(earlier), domain);
  const SampleResult shared = sample_with_seed(m, domain, options, 5);
  ASSERT_GT(own.scene.elements.size(), 10u);
  ASSERT_EQ(shared.scene.elements.size(), own.scene.elements.size());
  for (std::size_t i = 0; i < own.scene.elements.size(); ++i)
    EXPECT_EQ(shared.scene.elements[i].position, own.scene.elements[i].position);
}

// A hard-core point process on the unit torus with δ0 = 0.6: no three points fit, and
//   P(n) ∝ β^n / n! ∫ 1{no pair closer than δ0} = 1, β, β² A / 2
// with A = 1 − |torus disc of radius 0.6| (computed here on a fine grid). The sampler's final
// counts over many seeds follow it (chi-square, 2 degrees of freedom).
TEST(BirthDeath, HardCoreCountsOnASmallTorusMatchTheExactDistribution) {
  const model::ShapeProcessModel m = testing::point_model(10.0, {0.6}, {});
  const int grid = 2000;
  double blocked = 0.0;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const double x = (i + 0.5) / grid - 0.5, y = (j + 0.5) / grid - 0.5;
      if (x * x + y * y < 0.36) blocked += 1.0 / (static_cast<double>(grid) * grid);
    }
  const double area = 1.0 - blocked;
  const double weights[3] = {1.0, 10.0, 50.0 * area};
  const double total = weights[0] + weights[1] + weights[2];
  const geometry::Domain domain = geometry::Domain::from_sizes({1, 1}, geometry::Boundary::torus);
  const int runs = 600;
  int observed[3] = {0, 0, 0};
  for (int seed = 1; seed <= runs; ++seed) {
    SamplerOptions options;
    options.iterations = 400;
    const std::size_t n = sample_with_seed(m, domain, options, static_cast<std::uint64_t>(seed))
                              .scene.elements.size();
    ASSERT_LE(n, 2u);
    ++observed[n];
  }
  double chi2 = 0.0;
  for (int n = 0; n < 3; ++n) {
    const double expected = runs * weights[n] / total;
    chi2 += (observed[n] - expected) * (observed[n] - expected) / expected;
  }
  EXPECT_LT(chi2, 13.8) << "P(chi2_2 > 13.8) = 0.001; observed " << observed[0] << " "
                        << observed[1] << " " << observed[2];
}

geometry::Raster raster(int width, int height, float (*value)(int, int)) {
  geometry::Raster r;
  r.width = width;
  r.height = height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) r.values.push_back(value(x, y));
  return r;
}

TEST(BirthDeath, ElementsLieInsideAShapedDomain) {
  const model::ShapeProcessModel m = io::parse_model(kSquares, "squares.json");
  // A ring: inside between radii 20 and 38 of the 80 x 80 domain's centre (1 pixel per unit).
  geometry::Domain domain = geometry::Domain::from_sizes({80, 80}, geometry::Boundary::open);
  domain.set_mask(std::make_shared<const geometry::Raster>(raster(80, 80, [](int x, int y) {
    const double r = std::hypot(x + 0.5 - 40, y + 0.5 - 40);
    return r >= 20 && r <= 38 ? 1.0f : 0.0f;
  })));
  SamplerOptions options;
  options.iterations = 40000;
  const SampleResult result = sample_with_seed(m, domain, options, 3);
  ASSERT_GT(result.scene.elements.size(), 20u);
  const geometry::PairMeasurer measurer(result.scene, m.measurement_options(false));
  for (const geometry::Element& e : result.scene.elements) {
    const geometry::Proxy2& proxy = measurer.proxies2()[static_cast<std::size_t>(e.shape)];
    for (std::size_t k = 0; k < proxy.segment_start.size(); ++k) {
      for (double t = 0; t <= 1.0; t += 0.05) {
        const geometry::Vec2 p = e.position.head<2>() + proxy.segment_start[k] +
                                 t * (proxy.segment_end[k] - proxy.segment_start[k]);
        const double r = std::hypot(p.x() - 40, p.y() - 40);
        EXPECT_TRUE(r >= 19.5 && r <= 38.5)
            << "element at " << e.position.transpose() << " reaches radius " << r;
      }
    }
  }
}

TEST(BirthDeath, IntensityMapScalesTheDensity) {
  // Left half 0.25, right half 0.75: of a Poisson pattern's points, 3/4 fall on the right.
  const model::ShapeProcessModel m = testing::point_model(0.05);
  geometry::Domain domain = geometry::Domain::from_sizes({40, 40}, geometry::Boundary::torus);
  domain.set_intensity(std::make_shared<const geometry::Raster>(
      raster(2, 1, [](int x, int) { return x == 0 ? 0.25f : 0.75f; })));
  int left = 0, right = 0;
  for (int seed = 1; seed <= 60; ++seed) {
    SamplerOptions options;
    options.iterations = 6000;
    for (const geometry::Element& e :
         sample_with_seed(m, domain, options, static_cast<std::uint64_t>(seed)).scene.elements)
      (e.position.x() < 20 ? left : right)++;
  }
  const double n = left + right;
  EXPECT_NEAR(n / 60, 0.05 * 1600 * 0.5, 4 * std::sqrt(40.0 / 60));
  EXPECT_NEAR(right / n, 0.75, 4 * std::sqrt(0.75 * 0.25 / n));
}

// Fit → sample → refit: an anisotropic Strauss-type point process (mild inhibition along x,
// strong along y; γ ≤ 1 keeps the point process stable) sampled on a large torus at six seeds,
// refitted with its own thresholds: the mean of each parameter's six estimates within the t
// quantile (5 degrees of freedom, two-sided 1%: 4.03) of its standard error from their spread.
// The pseudo-likelihood's own standard errors ignore the pattern's dependence: over ten seeds
// (samples run to twice the automatic rule's length) its estimates strayed from the truth by
// about twice them (z up to 4.3), so one seed judged by them passes or fails by luck.
TEST(BirthDeath, FitSampleRefitRecoversAnAnisotropicModel) {
  model::ShapeProcessModel truth = testing::point_model(0.02);
  truth.measurement.directions = 4;
  truth.measurement.direction = geometry::DirectionKind::centroid;
  model::PairInteraction pair;
  model::AxisParameters along_x, along_y;
  along_x.direction = Vec3::UnitX();
  along_x.thresholds = {0.0, 4.0, 8.0};
  along_x.gammas = {0.6, 0.9};
  along_y.direction = Vec3::UnitY();
  along_y.thresholds = {0.0, 4.0, 8.0};
  along_y.gammas = {0.2, 0.5};
  pair.axes = {along_x, along_y};
  truth.interactions.push_back(pair);
  const geometry::Domain domain =
      geometry::Domain::from_sizes({300, 300}, geometry::Boundary::torus);
  SamplerOptions options;
  fit::FitOptions fit_options;
  fit_options.measurement.directions = 4;
  fit_options.measurement.direction = geometry::DirectionKind::centroid;
  fit_options.thresholds = {0.0, 4.0, 8.0};
  fit_options.boundary = geometry::Boundary::torus;
  fit_options.quadrature = 128;
  constexpr int kSeeds = 6;
  constexpr double kQuantile = 4.03;  // t, 5 degrees of freedom, 0.995
  // Per replicate: β, then γ of axis 0 bands 1–2 and axis 1 bands 1–2.
  std::vector<std::vector<double>> estimates(5);
  for (int seed = 2020; seed < 2020 + kSeeds; ++seed) {
    const SampleResult sampled =
        sample_with_seed(truth, domain, options, static_cast<std::uint64_t>(seed));
    ASSERT_GT(sampled.scene.elements.size(), 700u);
    const fit::FitResult refit = fit::fit_shape_process(sampled.scene, fit_options);
    estimates[0].push_back(refit.model.categories[0].beta);
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t k = 0; k < 2; ++k)
        estimates[1 + 2 * a + k].push_back(refit.model.interactions[0].axes[a].gammas[k]);
  }
  const std::vector<double> true_values = {0.02, 0.6, 0.9, 0.2, 0.5};
  for (std::size_t p = 0; p < estimates.size(); ++p) {
    double mean = 0.0, spread = 0.0;
    for (double e : estimates[p]) mean += e / kSeeds;
    for (double e : estimates[p]) spread += (e - mean) * (e - mean);
    const double standard_error = std::sqrt(spread / (kSeeds - 1) / kSeeds);
    EXPECT_NEAR(mean, true_values[p], kQuantile * standard_error) << "parameter " << p;
  }
}

}  // namespace
}  // namespace shapeproc::sample

namespace shapeproc::sample {
namespace {

// The configuration keeps t(x) up to date through births, deaths and shifts: at the end it equals
// a recount of the output's pairs by the measurement code, band by band.
TEST(BirthDeath, SufficientStatisticsMatchARecountOfTheOutput) {
  const model::ShapeProcessModel m = io::parse_model(kSquares, "squares.json");
  const geometry::Domain domain = geometry::Domain::from_sizes({60, 60}, geometry::Boundary::torus);
  SamplerOptions options;
  options.iterations = 30000;
  options.observe_every = 1000;
  const SampleResult result = sample_with_seed(m, domain, options, 21);
  ASSERT_GT(result.scene.elements.size(), 10u);

  const model::Interaction interaction(m);
  std::vector<double> recount(static_cast<std::size_t>(interaction.parameter_count()), 0.0);
  for (const geometry::Element& e : result.scene.elements)
    recount[static_cast<std::size_t>(e.category)] += 1;
  const geometry::PairMeasurer measurer(result.scene, m.measurement_options(true));
  for (const geometry::PairRecord& p :
       measurer.all_pairs(result.scene.elements, interaction.range())) {
    const geometry::Element& a = result.scene.elements[static_cast<std::size_t>(p.i)];
    const geometry::Element& b = result.scene.elements[static_cast<std::size_t>(p.j)];
    const int band =
        interaction.band(a.category, b.category, p.measurement.axis, p.measurement.distance);
    ASSERT_NE(band, model::Interaction::kHardCore);
    if (band >= 0)
      recount[static_cast<std::size_t>(
          interaction.parameter(a.category, b.category, p.measurement.axis, band))] += 1;
  }
  EXPECT_EQ(result.statistics, recount);
  double pairs = 0;
  for (std::size_t k = 1; k < recount.size(); ++k) pairs += recount[k];
  EXPECT_GT(pairs, 0.0) << "the test needs interacting pairs";
  // Observations every 1000 steps; the last is the final state.
  ASSERT_EQ(result.observations.size(), 30u);
  EXPECT_EQ(result.observations.back(), result.statistics);
}

}  // namespace
}  // namespace shapeproc::sample
