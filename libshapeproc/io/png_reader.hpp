// Reading PNG pictures (domain masks, intensity maps) as grey levels. Cairo is included by
// png_reader.cpp only.
#pragma once

#include <filesystem>

#include "libshapeproc/geometry/raster.hpp"

namespace shapeproc::io {

// Reads a PNG as luminance times alpha (transparent counts as black). Throws core::InputError
// naming the file when it cannot be read or is not a PNG.
geometry::Raster read_grayscale_png(const std::filesystem::path& path);

}  // namespace shapeproc::io
