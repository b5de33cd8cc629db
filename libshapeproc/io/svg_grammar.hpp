// The SVG attribute grammars (path data, transform lists, colours), parsed with svgpp.
// Kept behind this small interface so that only one file compiles svgpp's Boost.Spirit grammars.
#pragma once

#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "libshapeproc/geometry/path.hpp"

namespace shapeproc::io::svg {

// Thrown when an attribute value does not follow its grammar.
class GrammarError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Path data (`d`) in normal form: absolute lines and cubics only. Quadratics and shorthands become
// cubics, arcs become cubic arcs (SVG 1.1 F.6), `Z` adds the closing line when it has length.
// Subpaths without any segment (a lone `M`) are dropped. Throws GrammarError on bad syntax or
// non-finite numbers, and when the data would make more than `max_segments` segments.
std::vector<geometry::Path2> parse_path_data(
    std::string_view data, std::size_t max_segments = std::numeric_limits<std::size_t>::max());

// A `transform` attribute as one affine map. Throws GrammarError.
geometry::Affine2 parse_transform(std::string_view text);

// A colour as "#rrggbb" (named colours, #rgb, rgb(...) all accepted); nullopt if `text` is not
// a colour (e.g. "none", "url(#g)").
std::optional<std::string> normalise_color(std::string_view text);

}  // namespace shapeproc::io::svg
