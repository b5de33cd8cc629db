#include "libshapeproc/geometry/segment_distance.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::geometry {

double point_segment_squared_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return (p - a).squaredNorm();
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return (a + t * ab - p).squaredNorm();
}

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  return std::sqrt(point_segment_squared_distance(p, a, b));
}

namespace {
double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }
}  // namespace

double segment_segment_squared_distance(const Vec2& a, const Vec2& b, const Vec2& c,
                                        const Vec2& d) {
  // Proper or touching intersection: the end points of each segment lie on opposite sides (or on)
  // the other's line, and the segments are not collinear-and-apart.
  const double d1 = cross(d - c, a - c);
  const double d2 = cross(d - c, b - c);
  const double d3 = cross(b - a, c - a);
  const double d4 = cross(b - a, d - a);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return 0.0;
  }
  return std::min(
      std::min(point_segment_squared_distance(a, c, d), point_segment_squared_distance(b, c, d)),
      std::min(point_segment_squared_distance(c, a, b), point_segment_squared_distance(d, a, b)));
}

double segment_segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return std::sqrt(segment_segment_squared_distance(a, b, c, d));
}

}  // namespace shapeproc::geometry
