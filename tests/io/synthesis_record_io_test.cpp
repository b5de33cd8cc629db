#include "libshapeproc/io/synthesis_record_io.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

synthesis::SynthesisRecord example_record() {
  synthesis::SynthesisRecord r;
  r.method = "shape-process";
  r.command = "synthesize";
  r.arguments = {"shapeproc", "synthesize", "in.svg", "--seed", "3"};
  r.seed = 3;
  r.chain = 2;
  r.chains = 4;
  r.chain_seed = 0xFFFFFFFFFFFFFFF0ULL;  // needs all 64 bits
  r.boundary = geometry::Boundary::open;
  r.size = {440, 220.5};
  r.domain_file = "star.svg";
  r.inputs = {{"exemplar", "in.svg"}};
  r.options = {{"shift_probability", "0.25"}, {"fit.quantiles", "0,0.1,0.2"}};
  r.iterations = "20000";
  r.steps = 20000;
  r.stationary = false;
  r.seconds = 1.5;
  return r;
}

TEST(SynthesisRecordIo, RoundTripsThroughEveryOutputFormat) {
  const testing::TempDir dir;
  const synthesis::SynthesisRecord r = example_record();
  geometry::Scene scene;
  scene.dimension = 2;
  scene.window = geometry::Box3(geometry::Vec3::Zero(), geometry::Vec3(440, 220.5, 0));
  scene.categories.push_back({"default"});
  scene.shapes.push_back(geometry::Shape{});
  for (const char* name : {"out.svg", "out.csv"}) {
    write_scene(scene, dir.file(name), synthesis_provenance(r));
    const auto back = read_synthesis_record(dir.file(name));
    ASSERT_TRUE(back.has_value()) << name;
    EXPECT_EQ(back->method, r.method);
    EXPECT_EQ(back->command, r.command);
    EXPECT_EQ(back->arguments, r.arguments);
    EXPECT_EQ(back->seed, r.seed);
    EXPECT_EQ(back->chain, r.chain);
    EXPECT_EQ(back->chains, r.chains);
    EXPECT_EQ(back->chain_seed, r.chain_seed);
    EXPECT_EQ(back->boundary, r.boundary);
    EXPECT_EQ(back->size, r.size);
    EXPECT_EQ(back->domain_file, r.domain_file);
    EXPECT_EQ(back->inputs, r.inputs);
    EXPECT_EQ(back->options, r.options);
    EXPECT_EQ(back->iterations, r.iterations);
    EXPECT_EQ(back->steps, r.steps);
    EXPECT_EQ(back->stationary, r.stationary);
    EXPECT_EQ(back->seconds, 0.0) << "the time is not written: same seed, same bytes";
  }
}

TEST(SynthesisRecordIo, OtherProvenanceIsNoRecordAndABrokenRecordIsAnError) {
  EXPECT_FALSE(
      parse_synthesis_record(R"({"tool":"shapeproc","command":"convert"})", "x.svg").has_value());
  EXPECT_FALSE(parse_synthesis_record("not json", "x.svg").has_value());
  try {
    parse_synthesis_record(R"({"synthesis":{"method":"shape-process","seed":"one"}})", "x.svg");
    FAIL() << "expected an InputError";
  } catch (const core::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("x.svg: malformed synthesis record", 0), 0u) << e.what();
  }
}

TEST(SynthesisRecord, SummaryForReports) {
  synthesis::SynthesisRecord r = example_record();
  EXPECT_EQ(
      r.summary(),
      "shapeproc synthesize, shape-process, seed 3, chain 2, 20000 steps, open, domain star.svg");
  r.iterations = "stationary";
  r.chains = 1;
  r.domain_file.clear();
  EXPECT_EQ(r.summary(),
            "shapeproc synthesize, shape-process, seed 3, 20000 steps (until stationary), open");
}

}  // namespace
}  // namespace shapeproc::io
