// A synthesis domain from the user's files: the box's sizes, its boundary, and in 2D an optional
// shape mask (an SVG's filled shapes, or a grayscale PNG) and intensity map (a grayscale PNG),
// both stretched over the box.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::io {

struct DomainFiles {
  std::vector<double> size;  // W,H or W,H,D
  std::string boundary;      // "torus", "open", or empty: torus for a plain box, open with a mask
  std::string mask;          // .svg (filled shapes) or .png (white = inside); may be empty
  std::string intensity;     // .png (white = 1); may be empty
};

// Parses a size such as --size's: W,H or W,H,D, each a length in the exemplar's units or a
// multiple of the side of the exemplar's window along that axis: "3W,3H" is three windows by
// three, "W,2H" one by two, "300,2H" mixes both (the letters are W, H and D in that order,
// either case). `window` is the exemplar's window; null refuses multiples. nullopt on anything
// else, a value that is not positive and finite included.
std::optional<std::vector<double>> parse_size(std::string_view text, const geometry::Box3* window);

// Reads the mask and map and builds the domain. Throws core::UsageError for sizes of the wrong
// count or sign, a torus with a mask, or maps on a 3D domain; core::InputError naming the file for
// an unreadable or empty mask.
geometry::Domain read_domain(const DomainFiles& files, int dimension);

// The mask of an SVG domain: its filled shapes, rasterised over their own window, 2048 pixels
// along the longer side; or a PNG mask as it is.
geometry::Raster read_domain_mask(const std::string& path);

}  // namespace shapeproc::io
