// 2D paths made of straight lines and cubic Bézier segments: the normal form every SVG drawable
// is converted to (arcs, quadratics and shorthands are rewritten as cubics on reading).
#pragma once

#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// One piece of a path from `start` to `end`. A line keeps its control points equal to its end
// points, so every segment is also a valid cubic; `cubic` records how it was drawn.
struct Segment2 {
  Vec2 start = Vec2::Zero();
  Vec2 control1 = Vec2::Zero();
  Vec2 control2 = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  bool cubic = false;

  static Segment2 line(const Vec2& a, const Vec2& b) { return {a, a, b, b, false}; }
  static Segment2 bezier(const Vec2& a, const Vec2& c1, const Vec2& c2, const Vec2& b) {
    return {a, c1, c2, b, true};
  }
  // B(t) = (1-t)^3 P0 + 3(1-t)^2 t P1 + 3(1-t) t^2 P2 + t^3 P3, t in [0, 1].
  Vec2 point_at(double t) const;
};

// A subpath: consecutive segments, each starting where the previous one ends. A closed path ends
// at its start point (the closing line of `Z` is an explicit segment when it has length).
struct Path2 {
  std::vector<Segment2> segments;
  bool closed = false;

  Vec2 start_point() const { return segments.front().start; }
};

// Exact bounding box of a segment (extrema of the cubic, not its control polygon).
Box2 bounding_box(const Segment2& segment);
Box2 bounding_box(const Path2& path);

// Applies an affine map to every point of the path (Bézier curves are affine invariant).
void transform(Path2& path, const Affine2& map);
void translate(Path2& path, const Vec2& offset);

// Polyline through the path with at most `tolerance` distance to the curve. A closed path's
// polyline does not repeat its first point at the end.
std::vector<Vec2> flatten(const Path2& path, double tolerance);

// Signed area of a closed polygon (positive when counter-clockwise in a y-up frame).
double signed_area(const std::vector<Vec2>& polygon);

// Winding number of `polygon` (implicitly closed) around `point`.
int winding_number(const std::vector<Vec2>& polygon, const Vec2& point);

// The edge (a, b)'s share of a winding number around `point`: +1 or -1 where it crosses the
// horizontal line through the point (a half-open crossing, upwards or downwards) on the point's
// right, else 0. Edges that do not reach the point's height give 0.
inline int winding_crossing(const Vec2& a, const Vec2& b, const Vec2& point) {
  const double cross =
      (b.x() - a.x()) * (point.y() - a.y()) - (point.x() - a.x()) * (b.y() - a.y());
  if (a.y() <= point.y()) return b.y() > point.y() && cross > 0.0 ? 1 : 0;
  return b.y() <= point.y() && cross < 0.0 ? -1 : 0;
}

// True when the outlines of two polylines (closed when the flags say so) cross, or run together
// along a piece of positive length; touching at isolated points does not count.
bool polylines_overlap(const std::vector<Vec2>& a, bool a_closed, const std::vector<Vec2>& b,
                       bool b_closed);

// True when segments ab and cd cross, run together along a piece of positive length, or run side
// by side within `tolerance` of each other along more than twice the tolerance: pieces of ink a
// hair apart, such as the two halves of a shape a tile's border cut and a drawing program wrote
// 0.02 px apart. Touching or crossing at a point, or corners a hair apart, do not count.
bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double tolerance);

}  // namespace shapeproc::geometry
