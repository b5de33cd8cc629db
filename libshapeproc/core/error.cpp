#include "libshapeproc/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace shapeproc::core {

namespace {
std::string locate(const std::string& file, int line, const std::string& message) {
  std::string where = file;
  if (line > 0) where += ":" + std::to_string(line);
  return where + ": " + message;
}
}  // namespace

std::string name_options(std::string_view text, const OptionNamer& namer) {
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t open = text.find('{', at);
    if (open == std::string_view::npos) break;
    std::size_t end = open + 1;
    while (end < text.size() &&
           (std::islower(static_cast<unsigned char>(text[end])) || text[end] == '_'))
      ++end;
    out.append(text.substr(at, open - at));
    if (end < text.size() && text[end] == '}' && end > open + 1) {
      out += namer(text.substr(open + 1, end - open - 1));
      at = end + 1;
    } else {
      out += '{';
      at = open + 1;
    }
  }
  out.append(text.substr(std::min(at, text.size())));
  return out;
}

namespace {
std::string itself(std::string_view name) { return std::string(name); }
}  // namespace

InputError::InputError(std::string file, int line, const std::string& message)
    : std::runtime_error(locate(file, line, name_options(message, itself))),
      file_(std::move(file)),
      line_(line),
      message_(message) {}

std::string InputError::shown(const OptionNamer& namer) const {
  return locate(file_, line_, name_options(message_, namer));
}

UsageError::UsageError(const std::string& message)
    : std::runtime_error(name_options(message, itself)), message_(message) {}

std::string UsageError::shown(const OptionNamer& namer) const {
  return name_options(message_, namer);
}

ArgumentError::ArgumentError(const std::string& function, const std::string& message)
    : std::invalid_argument(function + ": " + message) {}

}  // namespace shapeproc::core
