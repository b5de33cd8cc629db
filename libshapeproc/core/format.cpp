#include "libshapeproc/core/format.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace shapeproc::core {

std::string format_number(double value) {
  if (value == 0.0) return "0";  // also folds -0
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string format_fixed(double value, int precision) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", precision, value);
  return buffer;
}

std::string format_general(double value, int digits) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string printable(const std::string& text, std::size_t limit) {
  std::size_t end = std::min(text.size(), limit);
  // Back to the start of a UTF-8 character (continuation bytes are 10xxxxxx).
  while (end < text.size() && end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80)
    --end;
  std::string out = text.substr(0, end);
  for (std::size_t i = 0; i < out.size();) {
    const auto byte = static_cast<unsigned char>(out[i]);
    // A UTF-8 character's length from its first byte; 0 for a byte that cannot start one.
    const std::size_t length = byte < 0x80           ? 1
                               : (byte >> 5) == 0x6  ? 2
                               : (byte >> 4) == 0xE  ? 3
                               : (byte >> 3) == 0x1E ? 4
                                                     : 0;
    bool valid = length > 0 && i + length <= out.size();
    for (std::size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(out[i + k]) & 0xC0) == 0x80;
    if (!valid) {  // a stray byte of another encoding, or a cut character
      out[i++] = '?';
    } else if (byte < 0x20 || byte == 0x7F) {
      out[i++] = '?';
    } else {
      i += length;
    }
  }
  if (end < text.size()) out += "... (" + std::to_string(text.size() - end) + " more bytes)";
  return out;
}

}  // namespace shapeproc::core
