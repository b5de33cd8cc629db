// The record every output carries: its lookups, its domain and its one-line summary.
#include "libshapeproc/synthesis/synthesis_record.hpp"

#include <gtest/gtest.h>

namespace shapeproc::synthesis {
namespace {

TEST(SynthesisRecord, LooksUpOptionsAndInputsAndTakesTheDomain) {
  SynthesisRecord r;
  r.inputs = {{"exemplar", "a.svg"}, {"model", "m.json"}};
  r.options = {{"fit.quantiles", "0,0.1"}, {"start", "empty"}};
  EXPECT_EQ(r.input("model"), "m.json");
  EXPECT_EQ(r.option("start"), "empty");
  EXPECT_EQ(r.option("missing"), "");
  EXPECT_EQ(r.input("start"), "");
  r.set_domain(geometry::Domain::from_sizes({300, 200}, geometry::Boundary::open));
  EXPECT_EQ(r.boundary, geometry::Boundary::open);
  EXPECT_EQ(r.size, (std::vector<double>{300, 200}));
}

TEST(SynthesisRecord, SummaryNamesCommandMethodSeedStepsAndBoundary) {
  SynthesisRecord r;
  r.command = "synthesize";
  r.method = "shape-process";
  r.seed = 7;
  r.steps = 1234;
  const std::string s = r.summary();
  for (const char* part : {"synthesize", "shape-process", "seed 7", "1234 steps", "torus"})
    EXPECT_NE(s.find(part), std::string::npos) << part << " not in: " << s;
}

}  // namespace
}  // namespace shapeproc::synthesis
