#include "libshapeproc/io/domain_io.hpp"

#include <gtest/gtest.h>

namespace shapeproc::io {
namespace {

const geometry::Box3 kWindow(geometry::Vec3(10, 20, 0), geometry::Vec3(50, 80, 0));  // 40 x 60

TEST(ParseSize, TakesLengthsAndMultiplesOfTheExemplarsWindow) {
  EXPECT_EQ(parse_size("300,200", nullptr), (std::vector<double>{300, 200}));
  EXPECT_EQ(parse_size("3W,3H", &kWindow), (std::vector<double>{120, 180}));
  EXPECT_EQ(parse_size("w, 2.5h", &kWindow), (std::vector<double>{40, 150}));
  EXPECT_EQ(parse_size("100,2H", &kWindow), (std::vector<double>{100, 120}));
  const geometry::Box3 box(geometry::Vec3::Zero(), geometry::Vec3(1, 2, 4));
  EXPECT_EQ(parse_size("2W,2H,0.5D", &box), (std::vector<double>{2, 4, 2}));
}

TEST(ParseSize, RefusesWhatIsNoSize) {
  EXPECT_FALSE(parse_size("3W,3H", nullptr));     // multiples need the exemplar
  EXPECT_FALSE(parse_size("3H,3W", &kWindow));    // the letters in their axes' order
  EXPECT_FALSE(parse_size("300", &kWindow));      // one size
  EXPECT_FALSE(parse_size("1,2,3,4", &kWindow));  // four
  EXPECT_FALSE(parse_size("0W,3H", &kWindow));
  EXPECT_FALSE(parse_size("-1,3", &kWindow));
  EXPECT_FALSE(parse_size("1e308W,3H", &kWindow));  // not finite once multiplied
  EXPECT_FALSE(parse_size("3WW,3H", &kWindow));
  EXPECT_FALSE(parse_size("3X,3H", &kWindow));
  EXPECT_FALSE(parse_size("3,", &kWindow));
  const geometry::Box3 flat(geometry::Vec3::Zero(), geometry::Vec3(1, 1, 0));
  EXPECT_FALSE(parse_size("W,H,D", &flat));  // no depth to multiply
}

}  // namespace
}  // namespace shapeproc::io
