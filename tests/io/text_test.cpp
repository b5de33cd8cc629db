#include "libshapeproc/io/text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/csv_reader.hpp"
#include "libshapeproc/io/reader_options.hpp"

namespace shapeproc::io {
namespace {

TEST(Text, FormatNumberRoundTripsExactly) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> value(-1e6, 1e6);
  for (int i = 0; i < 1000; ++i) {
    const double x = value(rng) * std::pow(10.0, static_cast<int>(rng() % 20) - 10);
    EXPECT_EQ(parse_number(core::format_number(x)).value(), x);
  }
  EXPECT_EQ(core::format_number(0.1), "0.1");
  EXPECT_EQ(core::format_number(-0.0), "0");
  EXPECT_EQ(core::format_number(2.0), "2");
}

TEST(Text, NumberListsAcceptSvgMinifiedForms) {
  EXPECT_EQ(parse_number_list("2-1.79.5.5").value(), (std::vector<double>{2, -1.79, 0.5, 0.5}));
  EXPECT_EQ(parse_number_list(" 1, 2 3e2,+4 ").value(), (std::vector<double>{1, 2, 300, 4}));
  EXPECT_FALSE(parse_number_list("1,,2"));
  EXPECT_FALSE(parse_number_list("1 x"));
  EXPECT_FALSE(parse_number_list("1e999"));
  EXPECT_FALSE(parse_number("nan"));
  EXPECT_FALSE(parse_number("inf"));
  EXPECT_FALSE(parse_number("1.5.5"));
}

TEST(Text, CsvFieldsAndQuotes) {
  std::vector<std::string> fields;
  ASSERT_TRUE(split_csv_line(R"(1, "a,b" ,"say ""hi""")", fields));
  EXPECT_EQ(fields, (std::vector<std::string>{"1", "a,b", "say \"hi\""}));
  EXPECT_FALSE(split_csv_line("\"open", fields));
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("plain"), "plain");
}

TEST(ReaderOptions, WindowOption) {
  const WindowOption w = WindowOption::parse("0,10,-5,5");
  EXPECT_EQ(w.dimension, 2);
  EXPECT_EQ(w.box.min(), geometry::Vec3(0, -5, 0));
  EXPECT_EQ(WindowOption::parse("0,1,0,1,0,2").dimension, 3);
  EXPECT_THROW(WindowOption::parse("0,10,5"), core::UsageError);
  EXPECT_THROW(WindowOption::parse("0,0,0,1"), core::UsageError);
  EXPECT_THROW(WindowOption::parse("1,0,0,1"), core::UsageError);
  EXPECT_THROW(WindowOption::parse("a,b,c,d"), core::UsageError);
}

}  // namespace
}  // namespace shapeproc::io
