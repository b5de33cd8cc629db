// Every kind of bad SVG gets a clear InputError naming the file, and the line where it is known.
#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/svg_reader.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

struct BadSvg {
  const char* name;
  const char* text;
  const char* message;  // expected part of the error
  int line;             // expected line, 0 when none
};

const char* const kHead = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n";

class SvgBadInput : public ::testing::TestWithParam<BadSvg> {};

TEST_P(SvgBadInput, ThrowsInputErrorWithFileAndLine) {
  const BadSvg& bad = GetParam();
  try {
    parse_svg(bad.text, "bad.svg", {});
    FAIL() << "no error for " << bad.name;
  } catch (const core::InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), "bad.svg");
    EXPECT_EQ(e.line(), bad.line) << what;
    EXPECT_NE(what.find(bad.message), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SvgBadInput,
    ::testing::Values(
        BadSvg{"empty", "  \n", "empty", 0},
        BadSvg{"malformed", "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path d=\"M0 0\">\n</svg>",
               "malformed XML", 3},
        BadSvg{"not_svg", "<html/>", "not <svg>", 1},
        BadSvg{"unknown_command",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n\n<path d=\"M0 0 "
               "X1 1\"/></svg>",
               "cannot parse path data", 3},
        BadSvg{"nan_in_path",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n<path d=\"M0 0 L "
               "nan 1\"/></svg>",
               "cannot parse path data", 2},
        BadSvg{"infinite_in_path",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n<path d=\"M0 0 L "
               "1e999 1\"/></svg>",
               "cannot parse path data", 2},
        BadSvg{"nan_radius",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n<circle "
               "r=\"NaN\"/></svg>",
               "finite length", 2},
        BadSvg{"negative_radius",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n<circle "
               "r=\"-1\"/></svg>",
               "must not be negative", 2},
        BadSvg{"bad_transform",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n<rect "
               "width=\"1\" height=\"1\" transform=\"rotate(\"/></svg>",
               "transform", 2},
        BadSvg{"bad_points",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n<polygon "
               "points=\"0,0 1\"/></svg>",
               "odd number", 2},
        BadSvg{"unknown_use",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n<use "
               "href=\"#nothing\"/></svg>",
               "unknown id", 2},
        BadSvg{"no_elements",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\"><defs><rect "
               "width=\"1\" height=\"1\"/></defs></svg>",
               "no elements", 0},
        BadSvg{"zero_window",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 0 10\"><rect width=\"1\" "
               "height=\"1\"/></svg>",
               "zero size", 1},
        BadSvg{"zero_window_rect",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 9 10\">\n<rect "
               "id=\"window\" width=\"0\" height=\"10\"/><rect width=\"1\" height=\"1\"/></svg>",
               "zero size", 2},
        BadSvg{"bad_view_box",
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10\"><rect width=\"1\" "
               "height=\"1\"/></svg>",
               "viewBox", 1},
        BadSvg{"no_window",
               "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"1\" height=\"1\"/></svg>",
               "no window", 1}),
    [](const ::testing::TestParamInfo<BadSvg>& param_info) {
      return std::string(param_info.param.name);
    });

TEST(SvgBadInputFile, MissingAndDirectory) {
  const testing::TempDir dir;
  EXPECT_THROW(read_svg(dir.file("missing.svg"), {}), core::InputError);
  EXPECT_THROW(read_svg(dir.path(), {}), core::InputError);
  (void)kHead;
}

}  // namespace
}  // namespace shapeproc::io
