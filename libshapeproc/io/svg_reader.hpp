// Reading SVG exemplars: which drawables form an element, their geometry in normal form, their
// style, category and the observation window.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/io/reader_options.hpp"

namespace shapeproc::io {

// Reads an SVG file as a 2D scene.
//
// Elements follow Inkscape habits: the root `<svg>` and layer groups
// (`inkscape:groupmode="layer"`) are containers; any other `<g>` (also `<a>`, `<switch>`) is one
// element made of everything inside it (unless options.groups == GroupMode::container); any
// drawable (`path`, `rect`, `circle`, `ellipse`, `line`, `polyline`, `polygon`, `use`) outside
// such a group is one element. With options.split_subpaths, each disjoint subpath of such a
// drawable is its own element (holes stay with their outline).
//
// Geometry is baked into the root's user space: transforms applied, arcs and quadratics turned
// into cubics. Styles come from presentation attributes, `<style>` sheets (simple tag, class and id
// selectors) and `style` attributes, inherited down the tree. `display:none` subtrees and
// `<defs>`, `<symbol>`, `<clipPath>`, `<mask>`, `<pattern>`, `<marker>` contents are not drawn;
// `<text>` and `<image>` are ignored.
//
// Window: `<rect id="window">` if present (not an element), else the root's viewBox, else its
// width and height.
//
// Throws InputError (file and line) on malformed XML, bad attribute values, unknown path
// commands, non-finite numbers, no elements, or a window of zero size.
geometry::Scene read_svg(const std::filesystem::path& file, const ReaderOptions& options);

// The same from text in memory; `file_name` is used in error messages.
geometry::Scene parse_svg(std::string_view text, const std::string& file_name,
                          const ReaderOptions& options);

}  // namespace shapeproc::io
