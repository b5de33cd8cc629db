#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "libshapeproc/core/assert.hpp"
#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/core/random.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::core {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

TEST(Check, OneMessageFormatNamingFunctionValueAndBound) {
  EXPECT_EQ(message_of([] { check_positive("fit", "the width", -2.5); }),
            "fit: the width must be positive, got -2.5");
  EXPECT_EQ(message_of([] { check_non_negative("sample", "the shift radius", -1); }),
            "sample: the shift radius must be >= 0, got -1");
  EXPECT_EQ(message_of([] { check_in_range("sample", "p", 1.0, 0.0, 1.0, true); }),
            "sample: p must be in [0, 1), got 1");
  EXPECT_EQ(message_of([] { check(false, "domain", "no room"); }), "domain: no room");
  EXPECT_EQ(message_of([] { check_positive("f", "x", 0.1); }), "");
  EXPECT_EQ(message_of([] { check_in_range("f", "x", 1.0, 0.0, 1.0); }), "");
}

TEST(Check, RejectsNotANumberAndInfinity) {
  for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    EXPECT_THROW(check_positive("f", "x", bad), ArgumentError) << bad;
    EXPECT_THROW(check_non_negative("f", "x", bad), ArgumentError) << bad;
    EXPECT_THROW(check_in_range("f", "x", bad, 0.0, 1.0), ArgumentError) << bad;
  }
  // ArgumentError is an invalid_argument, so callers that catch the standard type keep working.
  EXPECT_THROW(check(false, "f", "m"), std::invalid_argument);
}

TEST(Check, DescribeReadsBackAsTheSameNumber) {
  for (double v : {0.1, 1.0 / 3.0, 1e-300, 12345.678, -0.0})
    EXPECT_EQ(std::strtod(describe(v).c_str(), nullptr), v);
  EXPECT_EQ(describe(0.1), "0.1");
}

TEST(Assert, ThrowsAnInternalErrorNamingFileLineAndCondition) {
  const int n = 3;
  const std::string what =
      message_of([&] { SHAPEPROC_ASSERT(n == 4, "n is " + std::to_string(n)); });
  EXPECT_NE(what.find("internal error at "), std::string::npos) << what;
  EXPECT_NE(what.find("core_test.cpp:"), std::string::npos) << what;
  EXPECT_NE(what.find("n == 4 (n is 3)"), std::string::npos) << what;
  EXPECT_NO_THROW(SHAPEPROC_ASSERT(n == 3, ""));
  EXPECT_THROW(SHAPEPROC_ASSERT(false, ""), InternalError);
}

// Options named as {name} read as the name itself in what(), and as the caller names them in
// shown(); braces around anything else are left as they are.
TEST(OptionNames, ReadAsTheLibraryNamesThemOrAsTheCallerDoes) {
  const auto flag = [](std::string_view name) { return "--" + std::string(name); };
  EXPECT_EQ(name_options("{window}: expected 4 numbers, {x} {Y} {} {a_b", flag),
            "--window: expected 4 numbers, --x {Y} {} {a_b");
  const UsageError usage("{size} and {boundary}=torus");
  EXPECT_STREQ(usage.what(), "size and boundary=torus");
  EXPECT_EQ(usage.shown(flag), "--size and --boundary=torus");
  const InputError input("p.csv", 2, "outside {window}");
  EXPECT_STREQ(input.what(), "p.csv:2: outside window");
  EXPECT_EQ(input.shown(flag), "p.csv:2: outside --window");
}

TEST(InputError, ReadsFileLineMessage) {
  EXPECT_STREQ(InputError("a.svg", 3, "bad path").what(), "a.svg:3: bad path");
  EXPECT_STREQ(InputError("a.svg", 0, "empty").what(), "a.svg: empty");
}

// Names and values from input files printed safely: escape sequences and other control
// characters become '?', and long text is cut at a UTF-8 character boundary with a count. The
// XML escape turns markup into text.
TEST(Printable, ControlCharactersAndLengthAreBounded) {
  EXPECT_EQ(printable("dots"), "dots");
  EXPECT_EQ(printable("\x1b[31mred\x1b[0m\x7f"), "?[31mred?[0m?");
  const std::string big(5'000'000, 'x');
  EXPECT_EQ(printable(big, 10), "xxxxxxxxxx... (4999990 more bytes)");
  // "é" is two bytes: a cut inside it moves back to its start.
  EXPECT_EQ(printable("ab\xc3\xa9"
                      "cd",
                      3),
            "ab... (4 more bytes)");
  EXPECT_EQ(printable("ab\xc3\xa9"
                      "cd",
                      4),
            "ab\xc3\xa9"
            "... (2 more bytes)");
  // Bytes that are not UTF-8 (Latin-1 "\xfe", a lone continuation byte) print as '?'.
  EXPECT_EQ(printable("v\xfe"
                      "1.0 \x80x \xe2\x82\xac"),
            "v?1.0 ?x \xe2\x82\xac");
  EXPECT_EQ(xml_escape("<a href=\"x\">&</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;");
}

TEST(Random, SameSeedSameStreamOtherSeedOtherStream) {
  Random a(42), b(42), c(43);
  int differ = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    differ += x != c.uniform();
    EXPECT_GE(x, 0.0);
    EXPECT_LT(x, 1.0);
  }
  EXPECT_GT(differ, 95);
}

TEST(Random, IndicesAreUniform) {
  // 60,000 draws in 6 bins: chi-square with 5 degrees of freedom, P(> 20.5) = 0.001.
  Random random(7);
  std::vector<int> bins(6, 0);
  const int draws = 60000;
  for (int i = 0; i < draws; ++i) ++bins[random.index(6)];
  double chi2 = 0.0;
  for (int b : bins) chi2 += (b - draws / 6.0) * (b - draws / 6.0) / (draws / 6.0);
  EXPECT_LT(chi2, 20.5);
}

TEST(Random, UniformMeanAndVariance) {
  Random random(11);
  const int n = 100000;
  double sum = 0.0, squares = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = random.uniform(-1.0, 3.0);
    sum += x;
    squares += x * x;
  }
  const double mean = sum / n, variance = squares / n - mean * mean;
  // U(-1, 3): mean 1, variance 16/12; standard error of the mean sqrt(4/3 / n).
  EXPECT_NEAR(mean, 1.0, 4 * std::sqrt(4.0 / 3.0 / n));
  EXPECT_NEAR(variance, 4.0 / 3.0, 0.02);
}

TEST(AtomicFile, LeavesNothingHalfWrittenWhenTheWriterThrows) {
  const testing::TempDir dir;
  const auto target = dir.file("sub/out.txt");
  write_file_atomically(target, [](std::ostream& out) { out << "first"; });
  EXPECT_EQ(testing::read_file(target), "first");
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& out) {
                                       out << "second, half";
                                       throw std::runtime_error("stop");
                                     }),
               std::runtime_error);
  EXPECT_EQ(testing::read_file(target), "first");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("sub")))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 1);
  EXPECT_THROW(write_file_atomically(dir.path(), [](std::ostream&) {}), UsageError);
}

}  // namespace
}  // namespace shapeproc::core
