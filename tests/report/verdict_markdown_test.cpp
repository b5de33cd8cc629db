// The verdicts as a Markdown table: a column per check, a row per judged output.
#include "libshapeproc/report/verdict_markdown.hpp"

#include <gtest/gtest.h>

#include "tests/test_support.hpp"

namespace shapeproc::report {
namespace {

evaluation::Verdict verdict(const std::string& metric, const std::string& brief,
                            evaluation::Outcome outcome) {
  evaluation::Verdict v;
  v.metric = metric;
  v.brief = brief;
  v.outcome = outcome;
  return v;
}

TEST(VerdictMarkdown, OneRowPerJudgedOutputOneColumnPerCheck) {
  const testing::TempDir dir;
  const std::vector<evaluation::Verdict> first = {
      verdict("density", "×1.02", evaluation::Outcome::pass),
      verdict("overlaps", "3%", evaluation::Outcome::fail)};
  const std::vector<evaluation::Verdict> second = {
      verdict("order", "0.91", evaluation::Outcome::shown)};
  Report report;
  report.outputs.push_back({"a.svg", nullptr, nullptr, nullptr, nullptr, "", &first});
  report.outputs.push_back({"unjudged.svg", nullptr, nullptr, nullptr, nullptr, "", nullptr});
  report.outputs.push_back({"b.svg", nullptr, nullptr, nullptr, nullptr, "", &second});
  report.timings = {{"a.svg", 1.26}};
  write_verdict_markdown(report, dir.file("v.md"));
  EXPECT_EQ(testing::read_file(dir.file("v.md")),
            "| output | elements | s | density | overlaps | order |\n"
            "|---|---|---|---|---|---|\n"
            "| a.svg | 0 | 1.3 | ×1.02 ✓ | 3% ✗ | – |\n"
            "| b.svg | 0 | – | – | – | 0.91 |\n");
}

TEST(VerdictMarkdown, NothingIsWrittenWithoutVerdicts) {
  const testing::TempDir dir;
  Report report;
  report.outputs.push_back({"a.svg", nullptr, nullptr, nullptr, nullptr, "", nullptr});
  write_verdict_markdown(report, dir.file("v.md"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("v.md")));
}

}  // namespace
}  // namespace shapeproc::report
