// The README's library example, as written there: read, fit, sample, write.
#include <gtest/gtest.h>

#include <cmath>

#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/run_chains.hpp"
#include "tests/test_support.hpp"

namespace {

TEST(ReadmeExample, FitsSamplesAndWritesAnOutput) {
  const shapeproc::testing::TempDir dir;
  const std::string input = shapeproc::testing::data_path("svg/dots-random.svg");
  const std::string output = dir.file("output.svg").string();
  // From here on as in the README (with its file names).
  using namespace shapeproc;
  const geometry::Scene exemplar = io::read_scene(input, {});
  const model::ShapeProcessModel model = fit::fit_exemplar(exemplar, {}).result.model;
  const geometry::Domain domain =
      geometry::Domain::from_sizes({600, 600}, geometry::Boundary::torus);
  const sample::ShapeProcessSampler sampler = fit::output_sampler(model, domain);
  for (const synthesis::SynthesisResult& r : synthesis::run_chains(sampler, {}))
    io::write_scene(r.scene, output, {});
  // What it made: a model fitted by maximum likelihood, and an output of about the exemplar's
  // density (600 x 600 against its window; Poisson-like spread, 5 standard deviations).
  ASSERT_TRUE(model.fit && model.fit->likelihood);
  const geometry::Scene written = io::read_scene(output, {});
  const double expected =
      static_cast<double>(exemplar.elements.size()) * 360000.0 / exemplar.window_measure();
  EXPECT_NEAR(static_cast<double>(written.elements.size()), expected, 5 * std::sqrt(expected));
}

}  // namespace
