#include "tools/cli/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace shapeproc::cli {

void VerbosityFlags::add_to(CLI::App& command) {
  command.add_flag("-q,--quiet", quiet, "no progress on standard error");
  command.add_flag("--verbose", verbose, "also print each stage on standard error");
}

bool VerbosityFlags::show_progress() const { return !quiet && isatty(fileno(stderr)) != 0; }

void VerbosityFlags::stage(const std::string& line) const {
  if (verbose && !quiet) std::fprintf(stderr, "%s\n", line.c_str());
}

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(long long done, long long total) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (total > 0) {
    const long long percent = 100 * done / total;
    if (percent == last_percent_) return;
    last_percent_ = percent;
    const int filled = static_cast<int>(percent / 4);
    std::fprintf(stderr, "\r%s [%s%s] %3lld%%", label_.c_str(),
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(25 - filled), ' ').c_str(), percent);
  } else {
    if (drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    std::fprintf(stderr, "\r%s: %lld steps (until the element count is stationary)", label_.c_str(),
                 done);
  }
  last_draw_ = now;
  drawn_ = true;
  std::fflush(stderr);
}

void ProgressBar::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (enabled_ && drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
  enabled_ = false;
}

}  // namespace shapeproc::cli
