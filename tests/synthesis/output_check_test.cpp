#include "libshapeproc/synthesis/output_check.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::synthesis {
namespace {

// Short of the exemplar's count by more than chance: below 0.9 of it and more than 3 √wanted
// below it. 120 of 136 is neither by chance (3 √136 = 35); 251 of 405 is; 7 of 16 is below 0.9
// but within 3 √16 = 12; nothing is short of an empty exemplar.
TEST(OutputCheck, AnOutputFallsShortOnlyBeyondChance) {
  EXPECT_FALSE(falls_short(120, 136));
  EXPECT_TRUE(falls_short(100, 136));
  EXPECT_TRUE(falls_short(251, 405));
  EXPECT_FALSE(falls_short(7, 16));
  EXPECT_TRUE(falls_short(3, 16));
  EXPECT_FALSE(falls_short(0, 0));
  EXPECT_FALSE(falls_short(370, 405));  // 0.91 of it
}

SynthesisResult output_of(int elements, double side) {
  SynthesisResult result;
  result.scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(side, side, 0));
  for (int k = 0; k < elements; ++k)
    result.scene.elements.push_back({0, 0, geometry::Vec3(k, 0, 0)});
  return result;
}

// A density of 0.01 on 20 x 20 wants 4 elements: an empty output at the automatic stop is
// emptied (refused, naming its chain), one after a step count asked for is not; neither 0 nor 3
// of 4 is short by more than chance, 3 of 100 is; an unknown density (0) checks nothing.
TEST(OutputCheck, EmptiedChainsAreRefusedAndShortOnesFlagged) {
  const OutputCheck empty = check_output(output_of(0, 20), 0.01, true);
  EXPECT_DOUBLE_EQ(empty.wanted, 4.0);
  EXPECT_TRUE(empty.emptied);
  EXPECT_FALSE(empty.short_of_density);  // 4 short of 4: within 3 √4
  EXPECT_TRUE(check_output(output_of(3, 20), 0.25, true).short_of_density);  // 3 of 100
  EXPECT_FALSE(check_output(output_of(0, 20), 0.01, false).emptied);
  const OutputCheck three = check_output(output_of(3, 20), 0.01, true);
  EXPECT_FALSE(three.emptied);
  EXPECT_FALSE(three.short_of_density);
  EXPECT_DOUBLE_EQ(three.ratio(), 0.75);
  EXPECT_FALSE(check_output(output_of(0, 20), 0.0, true).emptied);
  std::vector<SynthesisResult> results = {output_of(3, 20), output_of(0, 20)};
  results[1].record.chain = 1;
  EXPECT_NO_THROW(refuse_emptied(results, 0.01, false));
  try {
    refuse_emptied(results, 0.01, true);
    ADD_FAILURE() << "an emptied chain was not refused";
  } catch (const core::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("chain 1 ended empty"), std::string::npos) << e.what();
  }
}

// A clustered output varies by its clusters: 368 of 432 wanted is short for a Poisson count
// (64 below, more than 3 √432 = 62), not for one whose 32 hidden centres hold 11.5 elements each
// (3 √(432 × 12.5) = 220).
TEST(OutputCheck, AClusteredOutputIsJudgedAtItsClustersDispersion) {
  SynthesisResult result = output_of(368, 20);
  EXPECT_TRUE(check_output(result, 432.0 / 400.0, true).short_of_density);
  result.hidden_elements = 32;
  EXPECT_FALSE(check_output(result, 432.0 / 400.0, true).short_of_density);
  EXPECT_TRUE(falls_short(100, 432, 12.5));
}

}  // namespace
}  // namespace shapeproc::synthesis
