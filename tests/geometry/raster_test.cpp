// A raster stretched over a box: which pixel a point reads, and nothing outside.
#include "libshapeproc/geometry/raster.hpp"

#include <gtest/gtest.h>

namespace shapeproc::geometry {
namespace {

TEST(Raster, SamplesThePixelHoldingThePointAndZeroOutside) {
  Raster r;
  r.width = 2;
  r.height = 2;
  r.values = {0.1f, 0.2f, 0.3f, 0.4f};  // rows from y = min: (0.1 0.2), (0.3 0.4)
  const Box3 box(Vec3(10, 20, 0), Vec3(30, 60, 0));
  EXPECT_FLOAT_EQ(r.sample(box, Vec2(11, 21)), 0.1f);
  EXPECT_FLOAT_EQ(r.sample(box, Vec2(29, 21)), 0.2f);
  EXPECT_FLOAT_EQ(r.sample(box, Vec2(11, 59)), 0.3f);
  EXPECT_FLOAT_EQ(r.sample(box, Vec2(20, 40)), 0.4f);  // the centre: the last row and column
  EXPECT_FLOAT_EQ(r.sample(box, Vec2(30, 40)), 0.0f);  // the far side is outside
  EXPECT_FLOAT_EQ(r.sample(box, Vec2(9.9, 40)), 0.0f);
  EXPECT_FLOAT_EQ(Raster{}.sample(box, Vec2(20, 40)), 0.0f);
}

}  // namespace
}  // namespace shapeproc::geometry
