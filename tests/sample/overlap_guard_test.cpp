#include "libshapeproc/sample/overlap_guard.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::sample {
namespace {

// Discs of radius 10 drawn as two arcs, that may touch but not overlap (δ_0 = 0 on every axis)
// and attract each other within 2 of contact: chains press them together.
const char* kDiscs = R"({
  "format": "shapeproc-model", "version": 1, "dimension": 2,
  "categories": [ { "name": "discs", "beta": 0.01 } ],
  "interaction": [ { "categories": [0, 0], "axes": [
      { "direction": [1, 0], "thresholds": [0, 2], "gammas": [20] },
      { "direction": [0.7071067811865476, 0.7071067811865476], "thresholds": [0, 2], "gammas": [20] },
      { "direction": [0, 1], "thresholds": [0, 2], "gammas": [20] },
      { "direction": [-0.7071067811865476, 0.7071067811865476], "thresholds": [0, 2], "gammas": [20] } ] } ],
  "shapes": [ { "category": 0, "geometry": { "type": "paths", "parts": [
      { "d": "M-10 0a10 10 0 1 0 20 0a10 10 0 1 0 -20 0z" } ] } } ]
})";

struct Discs {
  model::ShapeProcessModel m = io::parse_model(kDiscs, "discs.json");
  model::Interaction interaction{m};
  geometry::Scene space = m.shape_space();
  geometry::MeasurementOptions options = m.measurement_options(false);
  geometry::PairMeasurer proxies{space, options};
  OverlapGuard guard{interaction, space, proxies};
};

// Two discs 20 − ε apart between centres overlap by ε as drawn; the proxies' chords cut inside
// the arcs, so in some directions they are still apart. Where the outlines as collisions are
// judged (geometry::kOutlineTolerance) overlap, the guard finds it; where they do not, it never
// reports an overlap.
TEST(OverlapGuard, FindsTheOverlapsOfTheOutlinesThatTheProxiesMiss) {
  const Discs d;
  ASSERT_TRUE(d.guard.active());
  geometry::MeasurementOptions fine = d.options;
  fine.proxy.tolerance = geometry::kOutlineTolerance;
  const geometry::PairMeasurer outlines(d.space, fine);
  const geometry::Element at_origin{0, 0, geometry::Vec3::Zero()};
  int missed_by_proxies = 0, apart = 0;
  for (const double gap : {-0.4, -0.2, -0.1, 0.0, 0.05}) {
    for (int k = 0; k < 360; ++k) {
      const double angle = k * M_PI / 180.0;
      const geometry::Vec3 offset =
          (20.0 + gap) * geometry::Vec3(std::cos(angle), std::sin(angle), 0.0);
      const double proxy_distance = d.proxies.distance(0, 0, offset);
      if (proxy_distance < 0.0) continue;  // the hard core rejects it before the guard
      const bool drawn_overlap = outlines.distance(0, 0, offset) < 0.0;
      (drawn_overlap ? missed_by_proxies : apart) += 1;
      EXPECT_EQ(
          d.guard.overlaps(at_origin, geometry::Element{0, 0, offset}, offset, proxy_distance),
          drawn_overlap)
          << "gap " << gap << " at " << k << " degrees";
    }
  }
  EXPECT_GT(missed_by_proxies, 100);  // else the test shows nothing
  EXPECT_GT(apart, 100);
}

// With proxies as fine as the outlines', polygons (their proxies are their outlines at any
// tolerance) or distances between centroids, there is nothing to guard.
TEST(OverlapGuard, IsInactiveWhereTheProxiesAreTheOutlinesOrTheDistanceIgnoresShapes) {
  const Discs d;
  geometry::MeasurementOptions fine = d.options;
  fine.proxy.tolerance = geometry::kOutlineTolerance;
  EXPECT_FALSE(
      OverlapGuard(d.interaction, d.space, geometry::PairMeasurer(d.space, fine)).active());
  geometry::MeasurementOptions centroids = d.options;
  centroids.distance = geometry::DistanceKind::centroid;
  EXPECT_FALSE(
      OverlapGuard(d.interaction, d.space, geometry::PairMeasurer(d.space, centroids)).active());
  const model::ShapeProcessModel squares = io::parse_model(testing::kSquaresModel, "squares.json");
  const geometry::Scene space = squares.shape_space();
  EXPECT_FALSE(OverlapGuard(model::Interaction(squares), space,
                            geometry::PairMeasurer(space, squares.measurement_options(false)))
                   .active());
}

// Chains that press discs together leave no pair overlapping as `stats` judges collisions.
TEST(OverlapGuard, PressedDiscsNeverOverlapAsDrawn) {
  const model::ShapeProcessModel m = io::parse_model(kDiscs, "discs.json");
  const geometry::Domain domain =
      geometry::Domain::from_sizes({120, 120}, geometry::Boundary::torus);
  SamplerOptions options;
  options.iterations = 40000;
  int elements = 0, overlapping = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    core::Random random(seed);
    const SampleResult result = sample_shape_process(m, domain, options, random);
    metrics::StatisticsOptions judge;
    judge.measurement.periodic = true;
    judge.offset_samples = 16;
    elements += static_cast<int>(result.scene.elements.size());
    overlapping += static_cast<int>(
        metrics::compute_statistics(result.scene, judge, core::Random(1)).collisions.pairs.size());
  }
  EXPECT_GT(elements, 60);
  EXPECT_EQ(overlapping, 0);
}

}  // namespace
}  // namespace shapeproc::sample
