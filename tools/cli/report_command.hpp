// What `report` writes, shared by `compare`: the exemplar and outputs read, evaluated and
// judged, DIR/index.html and DIR/metrics.json.
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "tools/cli/flags.hpp"
#include "tools/cli/stats_command.hpp"

namespace shapeproc::cli {

struct ReportRequest {
  std::string exemplar, directory, model;  // model: optional
  std::vector<std::string> outputs;
  std::vector<std::string> labels;  // per output (empty: the file names)
  MetricFlags metrics;
  ReaderFlags reader;
  std::string command;                                  // the command line, for the page
  std::vector<std::pair<std::string, double>> timings;  // stage, seconds, shown first
};

// Writes the report; prints each output's one-line verdict, then where the page is.
int write_report(const ReportRequest& request, std::ostream& out);

}  // namespace shapeproc::cli
