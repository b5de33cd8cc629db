// The verdicts of a report as one Markdown table (DIR/verdicts.md): a row per output, its time
// when the report has one under its label, and a column per check, each cell the measured figure
// with ✓ or ✗. Galleries paste these together (scripts/compare-gallery.sh).
#pragma once

#include <filesystem>

#include "libshapeproc/report/html_report.hpp"

namespace shapeproc::report {

// Writes `file` atomically; outputs without verdicts are left out. Nothing is written when no
// output has verdicts.
void write_verdict_markdown(const Report& report, const std::filesystem::path& file);

}  // namespace shapeproc::report
