// The synthesizer factory: every method by name, each the same as the method built by hand, and
// what it refuses.
#include "libshapeproc/methods/synthesizer_factory.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/methods/tiled_exemplar.hpp"
#include "tests/methods/method_scenes.hpp"

namespace shapeproc::methods {
namespace {

using geometry::Boundary;

TEST(SynthesizerFactory, NamesRoundTripAndUnknownNamesAreRefused) {
  for (const Method m : {Method::shape_process, Method::ma_em, Method::davison, Method::ijiri,
                         Method::hybrid, Method::tile})
    EXPECT_EQ(method_from_name(method_name(m)), m);
  EXPECT_EQ(method_name(Method::ma_em), "ma-em");
  EXPECT_FALSE(method_from_name("region-growing").has_value());
  EXPECT_FALSE(method_from_name("").has_value());
}

// Each method made by name gives, chain for chain, what the method built directly gives.
TEST(SynthesizerFactory, MakesTheMethodsAsTheirOwnConstructorsDo) {
  const geometry::Scene exemplar = testing::rectangle_lattice(4, 20.0, 8.0, 4.0);
  const geometry::Domain domain = geometry::Domain::from_sizes({120, 120}, Boundary::torus);
  MethodOptions options;
  options.em.iterations = 3;

  const auto em =
      make_synthesizer(Method::ma_em, exemplar, Boundary::torus, domain, options, nullptr);
  const NeighbourhoodEm em_direct(exemplar, Boundary::torus, domain, options.em);
  EXPECT_EQ(em->method(), em_direct.method());
  EXPECT_EQ(testing::run(*em, 3).scene.elements.size(),
            testing::run(em_direct, 3).scene.elements.size());
  const auto em_lines = describe_synthesizer(*em, exemplar, options);
  ASSERT_EQ(em_lines.size(), 1u);
  EXPECT_EQ(em_lines[0].rfind("neighbourhood EM: 16 exemplar elements", 0), 0u) << em_lines[0];

  const auto growth =
      make_synthesizer(Method::davison, exemplar, Boundary::torus, domain, options, nullptr);
  const RegionGrowing growth_direct(exemplar, Boundary::torus, domain, options.growth);
  const auto a = testing::run(*growth, 5).scene, b = testing::run(growth_direct, 5).scene;
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t i = 0; i < a.elements.size(); ++i)
    EXPECT_EQ(a.elements[i].position, b.elements[i].position);
  EXPECT_EQ(describe_synthesizer(*growth, exemplar, options).size(), 1u);

  const auto tile =
      make_synthesizer(Method::tile, exemplar, Boundary::torus, domain, options, nullptr);
  EXPECT_EQ(testing::run(*tile, 1).scene.elements.size(), 36u);  // 6 × 6 lattice sites
}

TEST(SynthesizerFactory, TheShapeProcessAndTheHybridSampleTheModel) {
  const geometry::Scene exemplar = testing::rectangle_lattice(4, 20.0, 8.0, 4.0);
  const model::ShapeProcessModel model = fit::fit_shape_process(exemplar, {}).model;
  const geometry::Domain domain = geometry::Domain::from_sizes({100, 100}, Boundary::torus);
  MethodOptions options;
  options.sampler.iterations = 2000;
  options.em.iterations = 2;
  const auto sampler =
      make_synthesizer(Method::shape_process, exemplar, Boundary::torus, domain, options, &model);
  EXPECT_EQ(sampler->method(), "shape-process");
  EXPECT_EQ(testing::run(*sampler, 2).record.steps, 2000);
  EXPECT_TRUE(describe_synthesizer(*sampler, exemplar, options).empty());
  const auto hybrid =
      make_synthesizer(Method::hybrid, exemplar, Boundary::torus, domain, options, &model);
  EXPECT_EQ(hybrid->method(), "hybrid");
}

TEST(SynthesizerFactory, RefusesWhatAMethodCannotDo) {
  const geometry::Scene exemplar = testing::rectangle_lattice(3, 20.0, 8.0, 4.0);
  const geometry::Domain domain = geometry::Domain::from_sizes({100, 100}, Boundary::torus);
  MethodOptions options;
  // The shape process and the hybrid need a model.
  EXPECT_THROW(
      make_synthesizer(Method::shape_process, exemplar, Boundary::torus, domain, options, nullptr),
      core::ArgumentError);
  EXPECT_THROW(
      make_synthesizer(Method::hybrid, exemplar, Boundary::torus, domain, options, nullptr),
      core::ArgumentError);
  // A hybrid starts from a neighbourhood method only.
  const model::ShapeProcessModel model = fit::fit_shape_process(exemplar, {}).model;
  options.start_from = Method::tile;
  EXPECT_THROW(make_synthesizer(Method::hybrid, exemplar, Boundary::torus, domain, options, &model),
               core::ArgumentError);
  // Seed-and-grow is 2D only; a palette must match the exemplar's dimension.
  geometry::Scene solid = exemplar;
  solid.dimension = 3;
  EXPECT_THROW(make_synthesizer(Method::ijiri, solid, Boundary::torus, domain, {}, nullptr),
               core::ArgumentError);
  MethodOptions palette;
  palette.palette.push_back({solid, Boundary::open});
  EXPECT_THROW(
      make_synthesizer(Method::davison, exemplar, Boundary::torus, domain, palette, nullptr),
      core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::methods
