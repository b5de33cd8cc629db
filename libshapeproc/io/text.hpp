// Small text helpers shared by the readers and writers: exact number formatting and parsing of
// number lists such as "0 0 100 50" or "1,2 3-4.5.5".
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libshapeproc/core/format.hpp"

namespace shapeproc::io {

// Parses a whole string as one finite number; nullopt on anything else.
std::optional<double> parse_number(std::string_view text);

// Parses numbers separated by whitespace and/or commas, SVG style: "2-1.79" is 2 and -1.79,
// ".5.5" is 0.5 and 0.5. nullopt when something else is in the way or a value is not finite.
std::optional<std::vector<double>> parse_number_list(std::string_view text);

std::string_view trim(std::string_view text);
std::string to_lower(std::string_view text);
std::vector<std::string> split(std::string_view text, char separator);

// Lowercase extension without the dot ("svg").
std::string extension_of(const std::filesystem::path& path);

// The most an input file may hold (512 MiB): far above any drawing, below what would exhaust
// memory.
inline constexpr std::size_t kMaxInputBytes = std::size_t{512} << 20;

// The whole file as text; throws InputError when it cannot be read or holds more than
// `max_bytes`.
std::string read_text_file(const std::filesystem::path& path,
                           std::size_t max_bytes = kMaxInputBytes);

}  // namespace shapeproc::io
