// The hybrid: region growing's output on dots-random, then the shape-process sampler at the model
// fitted to the same exemplar.
#include "libshapeproc/methods/hybrid_synthesis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/methods/davison2018/region_growing.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "tests/methods/method_scenes.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::methods {
namespace {

using geometry::Boundary;

TEST(HybridSynthesis, StartsFromTheGrowthAndKeepsTheModelsHardCore) {
  const geometry::Scene exemplar = io::read_scene(testing::data_path("svg/dots-random.svg"), {});
  const model::ShapeProcessModel model = fit::fit_shape_process(exemplar, {}).model;
  const geometry::Domain domain = geometry::Domain::from_sizes({300, 300}, Boundary::torus);
  auto growth = std::make_unique<RegionGrowing>(exemplar, Boundary::open, domain, GrowthOptions{});
  const synthesis::SynthesisResult start = testing::run(*growth, 4);
  sample::SamplerOptions options;
  options.iterations = 5000;
  const HybridSynthesis hybrid(std::move(growth), model, domain, options);

  // Every start element becomes the model shape of its size: dots-random's shapes are copied.
  const std::vector<geometry::Element> mapped = hybrid.as_model_elements(start.scene);
  ASSERT_EQ(mapped.size(), start.scene.elements.size());
  for (std::size_t i = 0; i < mapped.size(); ++i) {
    const auto& s = start.scene.shapes[static_cast<std::size_t>(start.scene.elements[i].shape)];
    const auto& m = model.shapes[static_cast<std::size_t>(mapped[i].shape)].shape;
    EXPECT_LT(geometry::size_distance(geometry::shape_size(s), geometry::shape_size(m)), 1e-6);
  }

  const synthesis::SynthesisResult out = testing::run(hybrid, 4);
  EXPECT_EQ(out.record.method, "hybrid");
  const auto& o = out.record.options;
  EXPECT_NE(
      std::find(o.begin(), o.end(),
                std::make_pair(std::string("hybrid.start_from"), std::string("region-growing"))),
      o.end());
  // The chain kept most of the start (region growing overfills dots-random about twice: the
  // model removes some), and nothing overlaps.
  EXPECT_GT(out.scene.elements.size(), start.scene.elements.size() / 3);
  metrics::StatisticsOptions stats;
  stats.measurement.periodic = true;
  EXPECT_TRUE(
      metrics::compute_statistics(out.scene, stats, core::Random(1)).collisions.pairs.empty());

  // A start of a category the model does not have gives nothing to start from.
  geometry::Scene other = start.scene;
  other.categories[0].name = "elsewhere";
  EXPECT_TRUE(hybrid.as_model_elements(other).empty());
}

TEST(HybridSynthesis, RefusesAModelWithoutShapes) {
  model::ShapeProcessModel points;
  points.categories.push_back({"points", 0.01});
  points.measurement.directions = 1;
  const geometry::Domain domain = geometry::Domain::from_sizes({100, 100}, Boundary::torus);
  auto growth = std::make_unique<RegionGrowing>(testing::rectangle_lattice(6, 10.0, 3.0, 3.0),
                                                Boundary::torus, domain, GrowthOptions{});
  EXPECT_THROW(HybridSynthesis(std::move(growth), points, domain, {}), core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::methods
