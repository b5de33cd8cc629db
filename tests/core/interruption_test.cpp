#include "libshapeproc/core/interruption.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <filesystem>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/resource_budget.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::core {
namespace {

// A signal outside a cancellable section ends the process at once, with the temporary file being
// written removed; a second file that was not marked stays.
TEST(InterruptionDeathTest, SignalRemovesTheTemporaryFileBeingWritten) {
  const testing::TempDir dir;
  const auto marked = dir.write("out.svg.tmp-1", "half");
  const auto other = dir.write("input.svg", "kept");
  EXPECT_EXIT(
      {
        install_interrupt_handlers();
        const TemporaryFileMark mark(marked.string());
        std::raise(SIGTERM);
      },
      ::testing::ExitedWithCode(128 + SIGTERM), "interrupted; nothing was written");
  EXPECT_FALSE(std::filesystem::exists(marked));
  EXPECT_TRUE(std::filesystem::exists(other));
}

// Inside a section the first signal only sets the flag; the second ends the process.
TEST(InterruptionDeathTest, FirstSignalInASectionOnlySetsTheFlag) {
  EXPECT_EXIT(
      {
        install_interrupt_handlers();
        const CancellableSection section;
        std::raise(SIGINT);
        if (!section.flag()->load()) std::_Exit(3);
        std::raise(SIGINT);
        std::_Exit(4);  // not reached
      },
      ::testing::ExitedWithCode(128 + SIGINT), "interrupted");
}

TEST(ResourceBudget, RefusesWithTheEstimateItsBasisAndTheLimit) {
  ResourceBudget budget;
  budget.max_elements = 1000;
  budget.max_memory = 1 << 20;
  check_budget({999, 1000, "x"}, budget, "the output", "--size");
  try {
    check_budget({2e6, 10, "density times area"}, budget, "the output", "size");
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(),
                 "the output would hold about 2e+06 elements (density times area), more than "
                 "max_elements 1000; lower size or raise max_elements");
  }
  // The command line names its flags (core::name_options).
  try {
    check_budget({2e6, 10, "density times area"}, budget, "the output", "--size");
    FAIL();
  } catch (const UsageError& e) {
    const std::string shown =
        e.shown([](std::string_view name) { return "--" + std::string(name); });
    EXPECT_NE(shown.find("more than --max_elements 1000; lower --size or raise --max_elements"),
              std::string::npos)
        << shown;
  }
  EXPECT_THROW(check_budget({10, 2e6, "x"}, budget, "the fit", "--quadrature"), UsageError);
  EXPECT_THROW(check_budget({std::nan(""), 1, "x"}, budget, "the fit", "--quadrature"), UsageError);
  EXPECT_DOUBLE_EQ(parse_bytes("8G", "--max-memory"), 8.0 * (1ull << 30));
  EXPECT_DOUBLE_EQ(parse_bytes("512m", "--max-memory"), 512.0 * (1 << 20));
  EXPECT_DOUBLE_EQ(parse_bytes("2e9", "--max-memory"), 2e9);
  EXPECT_THROW(parse_bytes("-1G", "--max-memory"), UsageError);
  EXPECT_THROW(parse_bytes("G", "--max-memory"), UsageError);
  EXPECT_EQ(format_bytes(1536.0 * (1 << 20)), "1.5 GiB");
}

}  // namespace
}  // namespace shapeproc::core
