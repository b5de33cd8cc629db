// Numbers as text, one formatter per use: exact for files, fixed and general for tables.
#pragma once

#include <string>

namespace shapeproc::core {

// The shortest text that reads back as the same double ("0.1", "1e-300"; -0 as "0"): for files
// and messages.
std::string format_number(double value);
// printf's %.Nf and %.Ng, "-" for NaN and infinities: for tables people read.
std::string format_fixed(double value, int precision = 3);
std::string format_general(double value, int digits = 4);

// `text` with &, <, > and " escaped, for XML attribute values and character data (SVG, HTML):
// names taken from input files never reach a written file as markup.
std::string xml_escape(const std::string& text);

// `text` made safe to print on a terminal: control characters (terminal escape sequences among
// them) become '?', and text longer than `limit` bytes is cut at a character boundary with
// "... (N more bytes)". For names and values taken from input files.
std::string printable(const std::string& text, std::size_t limit = 300);

}  // namespace shapeproc::core
