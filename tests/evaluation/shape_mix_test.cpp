// The shape mix: an output with the exemplar's mix of shapes passes the χ² test exactly; one of a
// single kind does not.
#include "libshapeproc/evaluation/shape_mix.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/io/scene_io.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::evaluation {
namespace {

TEST(ShapeMix, TheExemplarsOwnMixAndADriftedOne) {
  const geometry::Scene exemplar =
      io::read_scene(testing::data_path("svg/dots-random.svg").string(), {});
  const ShapeMix same = shape_mix(exemplar, exemplar);
  ASSERT_GE(same.degrees, 1);
  EXPECT_EQ(same.exemplar, same.output);
  EXPECT_NEAR(same.chi_square, 0.0, 1e-12);
  EXPECT_NEAR(same.p_value, 1.0, 1e-12);
  EXPECT_EQ(same.unmatched, 0);
  // Ten copies of one element's shape: the mix has drifted to a single class.
  geometry::Scene drifted = exemplar;
  drifted.elements.assign(30, exemplar.elements.front());
  const ShapeMix one = shape_mix(exemplar, drifted);
  EXPECT_LT(one.p_value, 1e-3);
  int total = 0;
  for (int n : one.output) total += n;
  EXPECT_EQ(total, 30);
}

}  // namespace
}  // namespace shapeproc::evaluation
