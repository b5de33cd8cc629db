#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/pipeline/method_comparison.hpp"
#include "libshapeproc/pipeline/synthesis_run.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::pipeline {
namespace {

std::string data(const std::string& file) { return std::string(SHAPEPROC_DATA_DIR) + "/" + file; }

geometry::Domain torus(double w, double h) {
  return geometry::Domain::from_sizes({w, h}, geometry::Boundary::torus);
}

TEST(SynthesisRun, TheShapeProcessIsFittedAndSampledInOneCallTheSameForTheSameSeed) {
  const geometry::Scene exemplar = io::read_scene(data("svg/dots-random.svg"), {});
  SynthesisRequest request;
  request.sample.chains.seed = 4;
  int fitted = 0, ready = 0;
  request.fitted = [&](fit::ExemplarFit& fit) {
    ++fitted;
    EXPECT_FALSE(fit.result.model.categories.empty());
  };
  request.sample.ready = [&](const synthesis::Synthesizer& s, const SynthesisRun&) {
    ++ready;
    EXPECT_EQ(s.method(), "shape-process");
  };
  const SynthesisRun first =
      synthesize(exemplar, geometry::Boundary::open, torus(400, 400), request);
  EXPECT_EQ(fitted, 1);
  EXPECT_EQ(ready, 1);
  ASSERT_TRUE(first.model.has_value());
  ASSERT_EQ(first.results.size(), 1u);
  // 30 elements on 200 x 200: 120 expected on 400 x 400; a hard-core pattern varies little.
  const double count = static_cast<double>(first.results[0].scene.elements.size());
  EXPECT_NEAR(count / 120.0, 1.0, 0.25);
  EXPECT_GT(first.exemplar_density, 0.0);
  const SynthesisRun again =
      synthesize(exemplar, geometry::Boundary::open, torus(400, 400), request);
  ASSERT_EQ(again.results[0].scene.elements.size(), first.results[0].scene.elements.size());
  for (std::size_t i = 0; i < again.results[0].scene.elements.size(); ++i)
    EXPECT_EQ(again.results[0].scene.elements[i].position,
              first.results[0].scene.elements[i].position);
}

TEST(SynthesisRun, AnOutputBeyondTheBudgetIsRefusedBeforeAnyFit) {
  const geometry::Scene exemplar = io::read_scene(data("svg/dots-random.svg"), {});
  SynthesisRequest request;
  request.sample.budget.max_elements = 50;  // 120 expected
  bool fitted = false;
  request.fitted = [&](fit::ExemplarFit&) { fitted = true; };
  try {
    synthesize(exemplar, geometry::Boundary::open, torus(400, 400), request);
    FAIL() << "no refusal";
  } catch (const core::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("size"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fitted);
}

TEST(MethodComparison, EachMethodWritesItsOutputAndOneThatFailsIsLeftOffWithItsReason) {
  const testing::TempDir dir;
  MethodComparisonRequest request;
  request.exemplar = data("svg/crescents-grid.svg");
  request.size = "2W,2H";
  request.seed = 3;
  request.methods = parse_compared_methods("tile,davison");
  request.directory = (dir.path() / "page").string();
  std::vector<std::string> started;
  request.starting = [&](std::size_t i, std::size_t n, const std::string& m) {
    started.push_back(std::to_string(i) + "/" + std::to_string(n) + " " + m);
  };
  const MethodComparison done = compare_methods(request);
  EXPECT_EQ(started, (std::vector<std::string>{"1/2 tile", "2/2 davison"}));
  ASSERT_EQ(done.runs.size(), 2u);
  for (const MethodRun& run : done.runs) {
    EXPECT_TRUE(run.failure.empty()) << run.method << ": " << run.failure;
    EXPECT_TRUE(std::filesystem::exists(run.output)) << run.method;
    EXPECT_GT(run.elements, 0u);
  }
  EXPECT_TRUE(std::filesystem::exists(done.report.index));
  ASSERT_EQ(done.report.outputs.size(), 2u);

  // ijiri grows 2D exemplars only: on a mesh it fails, and the page holds the others.
  MethodComparisonRequest solids = request;
  solids.exemplar = data("mesh/pebbles.obj");
  solids.size = "2W,2H,D";
  solids.methods = parse_compared_methods("tile,ijiri");
  solids.directory = (dir.path() / "solids").string();
  solids.starting = nullptr;
  const MethodComparison some = compare_methods(solids);
  ASSERT_EQ(some.runs.size(), 2u);
  EXPECT_TRUE(some.runs[0].failure.empty());
  EXPECT_NE(some.runs[1].failure.find("2D"), std::string::npos) << some.runs[1].failure;
  EXPECT_TRUE(some.runs[1].output.empty());
  EXPECT_EQ(some.report.outputs.size(), 1u);
}

TEST(MethodComparison, AMethodListIsCheckedWithTheOptionNamed) {
  EXPECT_EQ(parse_compared_methods("ma-em,hybrid-ijiri"),
            (std::vector<std::string>{"ma-em", "hybrid-ijiri"}));
  for (const char* bad : {"", "magic", "tile,tile"}) {
    try {
      parse_compared_methods(bad);
      FAIL() << bad;
    } catch (const core::UsageError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("methods: ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace shapeproc::pipeline
