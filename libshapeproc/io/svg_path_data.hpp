// The SVG path data ("d" attribute) of a shape's outlines: absolute M, L, C and Z, numbers as
// core::format_number writes them, so that reading the text back gives the same outlines.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/path.hpp"

namespace shapeproc::io {

std::string svg_path_data(const geometry::Path2& path);
// The paths' data, one after the other, separated by a space.
std::string svg_path_data(const std::vector<geometry::Path2>& paths);

}  // namespace shapeproc::io
