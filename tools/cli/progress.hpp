// Progress on standard error for long runs: a bar when the length is known, a step count when it
// is not; drawn only on a terminal and not with --quiet. --verbose adds stage lines.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <mutex>
#include <string>

namespace shapeproc::cli {

// --quiet and --verbose, as every long-running subcommand takes them.
struct VerbosityFlags {
  bool quiet = false;
  bool verbose = false;
  void add_to(CLI::App& command);
  // Whether progress is drawn: standard error is a terminal and --quiet was not given.
  bool show_progress() const;
  // A stage line on standard error with --verbose ("fit: quadrature ...").
  void stage(const std::string& line) const;
};

class ProgressBar {
 public:
  ProgressBar(std::string label, bool enabled);
  ~ProgressBar();  // ends the line if anything was drawn
  // Steps done out of `total` (0: unknown). Thread-safe; redraws at most every 1% or 0.1 s.
  void update(long long done, long long total);
  void finish();

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  long long last_percent_ = -1;
  std::chrono::steady_clock::time_point last_draw_;
  std::mutex mutex_;
};

}  // namespace shapeproc::cli
