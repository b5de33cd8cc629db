// Running the command line in-process for the tests: its exit code and what it printed.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tests/test_support.hpp"
#include "tools/cli/cli.hpp"

namespace shapeproc::cli {

struct Result {
  int code;
  std::string out;
  std::string err;
};

inline Result run_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "shapeproc");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = run(static_cast<int>(argv.size()), argv.data(), out, err);
  return {code, out.str(), err.str()};
}

inline std::string data(const std::string& relative) {
  return testing::data_path(relative).string();
}

inline void expect_one_line_error(const Result& r, int code, const std::string& part) {
  EXPECT_EQ(r.code, code) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // exactly one line
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

}  // namespace shapeproc::cli
