// Small files of numbers: comments, blanks and commas; wrong rows named by file and line.
#include "libshapeproc/io/number_rows.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

TEST(NumberRows, ReadsRowsSkippingCommentsAndBlankLines) {
  const testing::TempDir dir;
  const auto file = dir.write("rows.txt", "# x y\n1 2\n\n3,4  # a comment\n  5\t6\n");
  const auto rows = read_number_rows(file, 2);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (std::vector<double>{1, 2}));
  EXPECT_EQ(rows[1], (std::vector<double>{3, 4}));
  EXPECT_EQ(rows[2], (std::vector<double>{5, 6}));
  const auto file3 = dir.write("mixed.txt", "1 2\n3 4 5\n");
  EXPECT_EQ(read_number_rows(file3, 2, 3).size(), 2u);
}

TEST(NumberRows, RefusesWrongRowsNamingTheFileAndLine) {
  const testing::TempDir dir;
  const auto expect_refused = [&](const std::string& text, const std::string& where) {
    const auto file = dir.write("bad.txt", text);
    try {
      read_number_rows(file, 2);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.txt" + where), std::string::npos) << e.what();
    }
  };
  expect_refused("1 2\n3\n", ":2");
  expect_refused("1 2\n3 x\n", ":2");
  expect_refused("# nothing\n\n", "");
}

}  // namespace
}  // namespace shapeproc::io
