#include "libshapeproc/io/text.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <system_error>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::io {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

// Reads one SVG-style number at `pos`: optional sign, digits with at most one dot, optional
// exponent. Returns the number of characters consumed (0 if none).
std::size_t scan_number(std::string_view text, std::size_t pos, double& value) {
  std::size_t i = pos;
  const std::size_t n = text.size();
  if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
  if (i < n && text[i] == '.') {
    ++i;
    while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < n && (text[j] == '+' || text[j] == '-')) ++j;
    if (j < n && std::isdigit(static_cast<unsigned char>(text[j]))) {
      while (j < n && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
      i = j;
    }
  }
  std::string_view token = text.substr(pos, i - pos);
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  if (result.ec == std::errc::result_out_of_range) {
    value = HUGE_VAL;  // reported as not finite by the callers
  } else if (result.ec != std::errc() || result.ptr != token.data() + token.size()) {
    return 0;
  }
  return i - pos;
}

}  // namespace

std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  double value = 0.0;
  const std::size_t used = scan_number(text, 0, value);
  if (used == 0 || used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::vector<double>> parse_number_list(std::string_view text) {
  std::vector<double> values;
  std::size_t i = 0;
  bool comma_allowed = false;
  while (true) {
    while (i < text.size() && is_space(text[i])) ++i;
    if (i < text.size() && text[i] == ',' && comma_allowed) {
      ++i;
      comma_allowed = false;
      while (i < text.size() && is_space(text[i])) ++i;
      if (i == text.size()) return std::nullopt;  // trailing comma
    }
    if (i == text.size()) break;
    double value = 0.0;
    const std::size_t used = scan_number(text, i, value);
    if (used == 0 || !std::isfinite(value)) return std::nullopt;
    values.push_back(value);
    i += used;
    comma_allowed = true;
  }
  return values;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

std::string to_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string> split(std::string_view text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.emplace_back(text.substr(start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return parts;
}

std::string extension_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  if (!ext.empty() && ext.front() == '.') ext.erase(0, 1);
  return to_lower(ext);
}

std::string read_text_file(const std::filesystem::path& path, std::size_t max_bytes) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw core::InputError(path.string(), 0, "no such file");
  if (std::filesystem::is_directory(path, ec)) {
    throw core::InputError(path.string(), 0, "is a directory, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw core::InputError(path.string(), 0, "cannot open the file for reading");
  // Read in blocks up to the limit, so that a device or pipe without an end (/dev/zero) is
  // refused at the limit instead of filling the memory.
  std::string text;
  std::array<char, 1 << 16> block{};
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (text.size() + got > max_bytes) {
      throw core::InputError(path.string(), 0,
                             "larger than " + std::to_string(max_bytes >> 20) +
                                 " MiB, the most an input file may hold");
    }
    text.append(block.data(), got);
  }
  if (in.bad()) throw core::InputError(path.string(), 0, "read error");
  return text;
}
}  // namespace shapeproc::io
