// Small text files of numbers, one record per line ("x y", "i j"): blank lines and everything
// after '#' are ignored, numbers are separated by blanks or commas.
#pragma once

#include <filesystem>
#include <vector>

namespace shapeproc::io {

// The rows of `path`, each with `columns` numbers (or between `columns` and `max_columns`).
// Throws core::InputError naming the file and line for a row of the wrong length, something not
// a number, or a file without rows.
std::vector<std::vector<double>> read_number_rows(const std::filesystem::path& path, int columns,
                                                  int max_columns = 0);

}  // namespace shapeproc::io
