#include "libshapeproc/core/error.hpp"

namespace shapeproc::core {

namespace {
std::string locate(const std::string& file, int line, const std::string& message) {
  std::string where = file;
  if (line > 0) where += ":" + std::to_string(line);
  return where + ": " + message;
}
}  // namespace

InputError::InputError(std::string file, int line, const std::string& message)
    : std::runtime_error(locate(file, line, message)), file_(std::move(file)), line_(line) {}

ArgumentError::ArgumentError(const std::string& function, const std::string& message)
    : std::invalid_argument(function + ": " + message) {}

}  // namespace shapeproc::core
