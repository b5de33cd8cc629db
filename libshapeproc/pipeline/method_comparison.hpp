// Every synthesis method on one exemplar, in one call: each method run as `synthesize --method M`
// runs it with its defaults and the same seed, its output written to the directory, and the page
// that shows them side by side with their verdicts, times and metrics
// (report/comparison_report.hpp; the shape-process paper's Fig. 5 on the user's own drawing).
// What `shapeproc compare` does. A method that fails is left off the page with its reason; the
// others still run.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/evaluation/scene_evaluation.hpp"
#include "libshapeproc/io/reader_options.hpp"
#include "libshapeproc/report/comparison_report.hpp"

namespace shapeproc::pipeline {

// The methods by name: tile (the exemplar repeated: the baseline), shape-process, ma-em, ijiri,
// davison; centroid and hausdorff (the shape process measured with that distance, the paper's
// Fig. 11); hybrid-ma-em, hybrid-davison, hybrid-ijiri (that method's output, then the
// shape-process sampler).
const std::vector<std::string>& comparable_methods();
const std::vector<std::string>& default_compared_methods();  // tile to davison

// "tile,ma-em": the list checked. Throws core::UsageError naming {methods} for an empty list, an
// unknown method or one given twice.
std::vector<std::string> parse_compared_methods(const std::string& list);

struct MethodComparisonRequest {
  std::string exemplar;  // its file
  io::ReaderOptions reader;
  std::string size;  // "W,H" (2D) or "W,H,D" (3D), lengths or multiples of the window: "3W,3H"
  std::uint64_t seed = 1;  // every method's
  std::vector<std::string> methods = default_compared_methods();
  std::string directory;  // created if missing; METHOD.svg (.csv, .obj), model.json, the page
  evaluation::MetricOptions metrics;
  std::string command;  // the command line, for the page and the outputs' records
  // Called before each method runs (1-based index of `count`) and after it has.
  std::function<void(std::size_t index, std::size_t count, const std::string& method)> starting;
  struct MethodRun;
  std::function<void(const MethodRun&)> finished;
  const std::atomic<bool>* cancel = nullptr;  // set it to stop (core::Cancelled is thrown)
};

struct MethodComparisonRequest::MethodRun {
  std::string method, output;  // the output's file; empty when the method failed
  std::string failure;         // one line, with the library's {option} marks; empty when it ran
  double seconds = 0.0;        // fit included
  std::size_t elements = 0;
  // What the method said as it ran, a line each: the fitted model's summary or what the method
  // learnt, warnings, and the output's count against the exemplar's density.
  std::vector<std::string> lines;
};
using MethodRun = MethodComparisonRequest::MethodRun;

struct MethodComparison {
  std::vector<MethodRun> runs;  // in the order asked
  report::ComparisonReport report;
};

// Throws core::InputError for an unreadable exemplar, core::UsageError for a bad size, a
// directory that names a file, or when no method could synthesise (with the first one's reason).
MethodComparison compare_methods(const MethodComparisonRequest& request);

}  // namespace shapeproc::pipeline
