// Visible ink of a stroke: the outline a stroke of its width paints around a drawable's subpaths,
// with its caps and joins (SVG `stroke-width`, `stroke-linecap`, `stroke-linejoin`,
// `stroke-miterlimit`), as filled polygons. The offset is Boost.Geometry's buffer: open subpaths
// are buffered as lines (flat, round or square caps: a square cap is a flat cap half a width
// beyond the end), closed subpaths as the difference of their outward and inward offsets, so that
// every corner of a closed outline gets its join.
#pragma once

#include <optional>

#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::geometry {

// Whether the drawable paints a stroke (a stroke colour other than none and a positive width).
bool stroked(const Drawable2& drawable);

// The stroke's ink as a filled drawable (closed line subpaths, even-odd, filled with the stroke's
// colour and opacity, no stroke), flattened within `tolerance`; nothing when the drawable is not
// stroked or its stroke paints no area.
std::optional<Drawable2> stroke_ink(const Drawable2& drawable, double tolerance);

}  // namespace shapeproc::geometry
