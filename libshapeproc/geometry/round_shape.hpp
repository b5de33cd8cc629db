// Round shapes: discs, rings (annuli) and points, drawn with every outline a circle about the
// shape's reference position. The gravitation between two round shapes pulls along the line of
// their centres (each mass is symmetric about that line), and where their outer circles are
// apart a line across the gap separates them, so it pulls each towards the other: their
// relative orientation is the line from one centre to the other, exactly, with no boundary
// integral (pair_measurements.hpp). (A dot in a ring's hole is pulled towards the nearer wall,
// away from the centre: such pairs are integrated.) On their polygonal proxies the integral
// gives the same line up to the proxies' error. The outer circle also holds the mass of an
// outline drawn as a curve, whose strip reaches beyond the outline (PairMeasurer widens it).
#pragma once

#include <optional>

#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::geometry {

// Whether `shape` is round: a point, or a planar shape whose every subpath is closed, lies on a
// circle about the origin (the reference position) within kRoundTolerance of the largest
// radius, and goes round it with no gap wider than kRoundGap (a square's corners lie on a circle
// too, but a quarter turn apart). Meshes are not. Returns the radius of the shape's outer circle
// (widened by kRoundTolerance; 0 for a point), or nothing when the shape is not round.
std::optional<double> round_radius(const Shape& shape);

// Radial tolerance of a round outline, relative to its largest radius: a circle drawn as four
// cubic Béziers strays 2.7e-4 of its radius from the circle.
inline constexpr double kRoundTolerance = 1e-3;
// The widest angle (radians) between consecutive points of a round outline flattened to
// kRoundTolerance: a 12-gon's 30° and wider are polygons.
inline constexpr double kRoundGap = 0.5;

}  // namespace shapeproc::geometry
