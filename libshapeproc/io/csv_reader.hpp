// Reading point patterns from CSV.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/io/reader_options.hpp"

namespace shapeproc::io {

// Reads a point pattern: a header naming the columns `x`, `y`, optionally `z` and `category`
// (any order; other columns such as `shape` are ignored), then one point element per row. With a
// `radius` column (2D only), each row is a filled disc of that radius centred on (x, y), as an
// SVG <circle> reads: trees with their trunks' sizes need no SVG.
// options.window is required and must have the dimension of the points; every point must lie in
// it. Category values are category names (one category "default" without the column). All
// elements share one point shape (discs: one shape per distinct
// radius). Throws InputError with the line on any bad row.
geometry::Scene read_csv_points(const std::filesystem::path& file, const ReaderOptions& options);
geometry::Scene parse_csv_points(std::string_view text, const std::string& file_name,
                                 const ReaderOptions& options);

// Splits one CSV line into fields ("a,\"b,c\"" gives a and b,c). Returns false on a bad quote.
bool split_csv_line(std::string_view line, std::vector<std::string>& fields);

// Quotes a field when it needs it.
std::string csv_field(const std::string& text);

}  // namespace shapeproc::io
