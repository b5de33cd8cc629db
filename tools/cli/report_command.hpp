// What `report` prints of the report the library wrote (report::write_comparison_report), shared
// by `compare`.
#pragma once

#include <ostream>

#include "libshapeproc/report/comparison_report.hpp"

namespace shapeproc::cli {

// Each output's one-line verdict, where the page is, then each output's figures.
void print_report(const report::ComparisonReport& report, std::ostream& out);

}  // namespace shapeproc::cli
