// The report of outputs against their exemplar, assembled: the exemplar and the outputs read,
// measured and judged (evaluation/), and DIR/index.html, DIR/metrics.json and DIR/verdicts.md
// written. With a fitted model, its goodness-of-fit table, its interaction functions and the
// simulation envelopes of the nearest distances are added. What `shapeproc report` and
// `shapeproc compare` write.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "libshapeproc/evaluation/scene_evaluation.hpp"
#include "libshapeproc/io/reader_options.hpp"

namespace shapeproc::report {

struct ComparisonRequest {
  std::string exemplar, directory;
  std::string model;  // optional: the fitted model
  std::vector<std::string> outputs;
  std::vector<std::string> labels;  // per output (empty: the file names)
  evaluation::MetricOptions metrics;
  io::ReaderOptions reader;
  std::string command;                                  // the command line, for the page
  std::vector<std::pair<std::string, double>> timings;  // stage, seconds, shown first
};

// One output as the report judged it.
struct OutputSummary {
  std::string label, file;
  std::string verdicts;  // the one-line summary of its verdicts
  std::size_t elements = 0, colliding_pairs = 0;
  double w1_nearest = 0.0, w1_pairs = 0.0;  // in the exemplar's mean nearest distances
  double neighbourhood = 0.0;               // normalised neighbourhood distance, a²
};

struct ComparisonReport {
  std::string index;  // DIR/index.html
  std::vector<OutputSummary> outputs;
  // Outputs left off the page because they hold no element (a chain that ended empty).
  std::vector<std::string> empty_outputs;
};

// Throws core::UsageError when the directory names a file, core::InputError for an unreadable
// input or when every output is empty. Files are written whole or not at all.
ComparisonReport write_comparison_report(const ComparisonRequest& request);

}  // namespace shapeproc::report
