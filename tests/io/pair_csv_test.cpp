#include "libshapeproc/io/pair_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

std::vector<geometry::PairRecord> two_pairs() {
  geometry::PairRecord a;
  a.i = 0;
  a.j = 1;
  a.measurement.distance = 2.5;
  a.measurement.direction = geometry::Vec3(1, 0, 0);
  a.measurement.axis = 0;
  geometry::PairRecord b;
  b.i = 1;
  b.j = 2;
  b.measurement.distance = 0.1;
  b.measurement.direction = geometry::Vec3(0, -1, 0.5);
  b.measurement.axis = 3;
  return {a, b};
}

TEST(PairCsv, OneRowPerPairWithExactNumbers) {
  std::ostringstream out2, out3;
  write_pairs_csv(out2, 2, two_pairs());
  EXPECT_EQ(out2.str(), "i,j,distance,ox,oy,axis\n0,1,2.5,1,0,0\n1,2,0.1,0,-1,3\n");
  write_pairs_csv(out3, 3, two_pairs());
  EXPECT_EQ(out3.str(), "i,j,distance,ox,oy,oz,axis\n0,1,2.5,1,0,0,0\n1,2,0.1,0,-1,0.5,3\n");
}

TEST(PairCsv, AFileGetsItsProvenanceBeside) {
  const testing::TempDir dir;
  const auto file = dir.file("pairs.csv");
  write_pairs_csv(file, 2, two_pairs(), {R"({"tool":"shapeproc"})"});
  EXPECT_EQ(testing::read_file(file), "i,j,distance,ox,oy,axis\n0,1,2.5,1,0,0\n1,2,0.1,0,-1,3\n");
  EXPECT_EQ(testing::read_file(dir.file("pairs.csv.json")), "{\"tool\":\"shapeproc\"}\n");
}

}  // namespace
}  // namespace shapeproc::io
