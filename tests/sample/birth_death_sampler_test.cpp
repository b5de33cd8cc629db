#include "libshapeproc/sample/birth_death_sampler.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/io/model_io.hpp"

namespace shapeproc::sample {
namespace {

using geometry::Box3;
using geometry::Vec3;

model::ShapeProcessModel poisson_points(double beta) {
  model::ShapeProcessModel m;
  m.categories.push_back({"points", beta});
  m.measurement.directions = 1;
  return m;
}

TEST(BirthDeath, PoissonCountsFollowPoisson) {
  // γ = 1 everywhere: the number of elements is Poisson(β|D|) = Poisson(20).
  const model::ShapeProcessModel m = poisson_points(0.01);
  const Box3 domain(Vec3(0, 0, 0), Vec3(50, 40, 0));
  const int runs = 300;
  std::vector<double> counts;
  for (int seed = 1; seed <= runs; ++seed) {
    SamplerOptions options;
    options.seed = static_cast<std::uint64_t>(seed);
    options.iterations = 4000;
    counts.push_back(static_cast<double>(sample_shape_process(m, domain, options).scene.elements.size()));
  }
  double mean = 0, variance = 0;
  for (double c : counts) mean += c / runs;
  for (double c : counts) variance += (c - mean) * (c - mean) / (runs - 1);
  // Mean: standard error sqrt(20 / 300); dispersion s²/mean: sd about sqrt(2 / 299). 4 of each.
  EXPECT_NEAR(mean, 20.0, 4 * std::sqrt(20.0 / runs));
  EXPECT_NEAR(variance / mean, 1.0, 4 * std::sqrt(2.0 / (runs - 1)));
}

const char* kSquares = R"({
  "format": "shapeproc-model", "version": 1, "dimension": 2,
  "categories": [ { "name": "squares", "beta": 0.2 } ],
  "interaction": [ { "categories": [0, 0], "axes": [
      { "direction": [1, 0], "thresholds": [2, 6], "gammas": [0.5] },
      { "direction": [0.7071067811865476, 0.7071067811865476], "thresholds": [4, 6], "gammas": [0.5] },
      { "direction": [0, 1], "thresholds": [8, 10], "gammas": [0.5] },
      { "direction": [-0.7071067811865476, 0.7071067811865476], "thresholds": [4, 6], "gammas": [0.5] } ] } ],
  "shapes": [ { "category": 0, "geometry": { "type": "paths", "parts": [ { "d": "M0 0h6v1h-6z" } ] } } ]
})";

TEST(BirthDeath, HardCoreIsNeverViolated) {
  const model::ShapeProcessModel m = io::parse_model(kSquares, "squares.json");
  const Box3 domain(Vec3(0, 0, 0), Vec3(60, 60, 0));
  SamplerOptions options;
  options.seed = 11;
  options.iterations = 30000;
  const SampleResult result = sample_shape_process(m, domain, options);
  ASSERT_GT(result.scene.elements.size(), 10u);
  const geometry::PairMeasurer measurer(result.scene, m.measurement_options(true));
  for (std::size_t i = 0; i < result.scene.elements.size(); ++i) {
    for (std::size_t j = i + 1; j < result.scene.elements.size(); ++j) {
      const geometry::Measurement pair = measurer.measure(result.scene.elements[i], result.scene.elements[j]);
      EXPECT_GE(pair.distance, m.interactions[0].axes[static_cast<std::size_t>(pair.axis)].thresholds[0]) << i << " " << j;
    }
  }
}

TEST(BirthDeath, SameSeedSameOutput) {
  const model::ShapeProcessModel m = io::parse_model(kSquares, "squares.json");
  const Box3 domain(Vec3(0, 0, 0), Vec3(40, 40, 0));
  SamplerOptions options;
  options.seed = 5;
  options.iterations = 5000;
  const SampleResult a = sample_shape_process(m, domain, options);
  const SampleResult b = sample_shape_process(m, domain, options);
  ASSERT_EQ(a.scene.elements.size(), b.scene.elements.size());
  for (std::size_t i = 0; i < a.scene.elements.size(); ++i) EXPECT_EQ(a.scene.elements[i].position, b.scene.elements[i].position);
  options.seed = 6;
  const SampleResult c = sample_shape_process(m, domain, options);
  EXPECT_TRUE(c.scene.elements.size() != a.scene.elements.size() ||
              c.scene.elements.front().position != a.scene.elements.front().position);
}

}  // namespace
}  // namespace shapeproc::sample
