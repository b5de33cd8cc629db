// Shared by `shapeproc stats`, `report` and `compare`: the metric options on the command line,
// turned into the library's (evaluation::MetricOptions).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "libshapeproc/evaluation/scene_evaluation.hpp"
#include "tools/cli/common.hpp"

namespace shapeproc::cli {

struct MetricFlags {
  std::string boundary = "auto";
  std::string edge = "auto";
  double range = 0.0;
  double neighbourhood = 0.0;
  int directions = 0;
  std::string direction = "gravitation";
  double proxy_tolerance = evaluation::MetricOptions{}.proxy_tolerance;

  void add_to(CLI::App& command);
  // The library's options. Throws core::UsageError for values out of their domain.
  evaluation::MetricOptions options() const;
};

}  // namespace shapeproc::cli
