// Text chunks (PNG tEXt, ISO/IEC 15948 §11.3.4.3) in PNG bytes: how a picture carries the seed and
// the command that made it.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace shapeproc::render {

using PngText = std::vector<std::pair<std::string, std::string>>;  // (keyword, text), Latin-1

// `png` (a whole PNG file) with a tEXt chunk per entry inserted after its IHDR chunk. Keywords
// must be 1-79 printable characters. Throws core::ArgumentError for a bad keyword or bytes that
// do not start with a PNG signature and IHDR.
std::string add_png_text(const std::string& png, const PngText& text);

// The tEXt chunks of a PNG file's bytes, in order (empty when it has none or is not a PNG).
PngText read_png_text(const std::string& png);

}  // namespace shapeproc::render
