// Closed-form distances between 2D points and segments.
#pragma once

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// Distance from p to the segment [a, b] (a == b allowed).
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);
double point_segment_squared_distance(const Vec2& p, const Vec2& a, const Vec2& b);

// Shortest distance between segments [a, b] and [c, d]: 0 when they cross or touch, otherwise the
// smallest of the four end-point-to-segment distances (the minimum of two non-crossing segments is
// always attained at an end point). Degenerate segments (points) allowed.
double segment_segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
// The same squared (one square root fewer per call where only comparisons are needed).
double segment_segment_squared_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

}  // namespace shapeproc::geometry
