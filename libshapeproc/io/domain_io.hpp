// A synthesis domain from the user's files: the box's sizes, its boundary, and in 2D an optional
// shape mask (an SVG's filled shapes, or a grayscale PNG) and intensity map (a grayscale PNG),
// both stretched over the box.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::io {

struct DomainFiles {
  std::vector<double> size;  // W,H or W,H,D
  std::string boundary;      // "torus", "open", or empty: torus for a plain box, open with a mask
  std::string mask;          // .svg (filled shapes) or .png (white = inside); may be empty
  std::string intensity;     // .png (white = 1); may be empty
};

// Reads the mask and map and builds the domain. Throws core::UsageError for sizes of the wrong
// count or sign, a torus with a mask, or maps on a 3D domain; core::InputError naming the file for
// an unreadable or empty mask.
geometry::Domain read_domain(const DomainFiles& files, int dimension);

// The mask of an SVG domain: its filled shapes, rasterised over their own window, 2048 pixels
// along the longer side; or a PNG mask as it is.
geometry::Raster read_domain_mask(const std::string& path);

}  // namespace shapeproc::io
