// Elliptical arcs as cubic Bézier segments (SVG 1.1 implementation notes F.6).
#pragma once

#include "libshapeproc/geometry/path.hpp"

namespace shapeproc::geometry {

// Appends the SVG arc from `from` to `to` (radii rx, ry, x-axis rotation in degrees, the two
// flags) to `path` as cubic segments of at most 90 degrees each, following F.6.2 for
// out-of-range parameters: nothing when from == to, a line when a radius is 0, absolute radii,
// radii scaled up when too small to reach `to`. The last segment ends exactly at `to`.
void append_elliptical_arc(Path2& path, const Vec2& from, double rx, double ry,
                           double rotation_degrees, bool large_arc, bool sweep, const Vec2& to);

// Closed path of a full axis-aligned ellipse, four quarter arcs starting at (cx + rx, cy) and
// going in the direction of increasing angle (as SVG draws circles and ellipses).
Path2 ellipse_path(const Vec2& centre, double rx, double ry);

}  // namespace shapeproc::geometry
