#include "libshapeproc/io/number_rows.hpp"

#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

std::vector<std::vector<double>> read_number_rows(const std::filesystem::path& path, int columns,
                                                  int max_columns) {
  if (max_columns < columns) max_columns = columns;
  const std::string text = read_text_file(path);
  std::vector<std::vector<double>> rows;
  int line_number = 0;
  for (const std::string& line : split(text, '\n')) {
    ++line_number;
    std::string_view content = line;
    if (const auto hash = content.find('#'); hash != std::string_view::npos)
      content = content.substr(0, hash);
    content = trim(content);
    if (content.empty()) continue;
    const auto numbers = parse_number_list(content);
    if (!numbers)
      throw core::InputError(path.string(), line_number,
                             "expected numbers, got '" + std::string(content) + "'");
    const auto n = static_cast<int>(numbers->size());
    if (n < columns || n > max_columns)
      throw core::InputError(
          path.string(), line_number,
          "expected " + std::to_string(columns) +
              (max_columns > columns ? " to " + std::to_string(max_columns) : "") +
              " numbers, got " + std::to_string(n));
    rows.push_back(*numbers);
  }
  if (rows.empty()) throw core::InputError(path.string(), 0, "the file holds no rows");
  return rows;
}

}  // namespace shapeproc::io
