#include "libshapeproc/geometry/path.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::geometry {

Vec2 Segment2::point_at(double t) const {
  const double u = 1.0 - t;
  return u * u * u * start + 3.0 * u * u * t * control1 + 3.0 * u * t * t * control2 +
         t * t * t * end;
}

namespace {

// Roots in (0, 1) of the derivative of one coordinate of a cubic Bézier.
void derivative_roots(double p0, double p1, double p2, double p3, std::vector<double>& roots) {
  // B'(t)/3 = a t^2 + b t + c
  const double a = -p0 + 3.0 * p1 - 3.0 * p2 + p3;
  const double b = 2.0 * (p0 - 2.0 * p1 + p2);
  const double c = p1 - p0;
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (scale == 0.0) return;
  auto keep = [&](double t) {
    if (t > 0.0 && t < 1.0) roots.push_back(t);
  };
  if (std::abs(a) <= 1e-12 * scale) {
    if (b != 0.0) keep(-c / b);
    return;
  }
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return;
  const double sq = std::sqrt(disc);
  // Numerically stable pair of roots.
  const double q = -0.5 * (b + std::copysign(sq, b));
  keep(q / a);
  if (q != 0.0) keep(c / q);
}

}  // namespace

Box2 bounding_box(const Segment2& segment) {
  Box2 box(segment.start);
  box.extend(segment.end);
  if (!segment.cubic) return box;
  std::vector<double> roots;
  for (int axis = 0; axis < 2; ++axis) {
    derivative_roots(segment.start[axis], segment.control1[axis], segment.control2[axis],
                     segment.end[axis], roots);
  }
  for (double t : roots) box.extend(segment.point_at(t));
  return box;
}

Box2 bounding_box(const Path2& path) {
  Box2 box;
  for (const Segment2& segment : path.segments) box.extend(bounding_box(segment));
  return box;
}

void transform(Path2& path, const Affine2& map) {
  for (Segment2& s : path.segments) {
    s.start = map * s.start;
    s.control1 = map * s.control1;
    s.control2 = map * s.control2;
    s.end = map * s.end;
  }
}

void translate(Path2& path, const Vec2& offset) {
  for (Segment2& s : path.segments) {
    s.start += offset;
    s.control1 += offset;
    s.control2 += offset;
    s.end += offset;
  }
}

std::vector<Vec2> flatten(const Path2& path, double tolerance) {
  std::vector<Vec2> points;
  if (path.segments.empty()) return points;
  points.push_back(path.start_point());
  for (const Segment2& s : path.segments) {
    if (s.cubic) {
      // Uniform subdivision into n pieces keeps the chord error below
      // (3/4) max(|P0 - 2P1 + P2|, |P1 - 2P2 + P3|) / n^2.
      const double second = std::max((s.start - 2.0 * s.control1 + s.control2).norm(),
                                     (s.control1 - 2.0 * s.control2 + s.end).norm());
      const double needed = std::sqrt(0.75 * second / std::max(tolerance, 1e-300));
      const int n = std::clamp(static_cast<int>(std::ceil(needed)), 1, 1024);
      for (int i = 1; i < n; ++i) points.push_back(s.point_at(static_cast<double>(i) / n));
    }
    points.push_back(s.end);
  }
  if (path.closed && points.size() > 1 && points.back() == points.front()) points.pop_back();
  return points;
}

double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = polygon[i];
    const Vec2& q = polygon[(i + 1) % n];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

int winding_number(const std::vector<Vec2>& polygon, const Vec2& point) {
  int winding = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
    winding += winding_crossing(polygon[i], polygon[(i + 1) % n], point);
  return winding;
}

namespace {

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Whether two segments share more than isolated touching points: they cross properly, or they
// are collinear and overlap along a piece of positive length.
bool segments_overlap(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = orient(c, d, a);
  const double d2 = orient(c, d, b);
  const double d3 = orient(a, b, c);
  const double d4 = orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  if (d1 != 0 || d2 != 0 || d3 != 0 || d4 != 0) return false;
  // Collinear: project on the longer direction and compare the intervals.
  const Vec2 axis = (b - a).squaredNorm() >= (d - c).squaredNorm() ? Vec2(b - a) : Vec2(d - c);
  const double a0 = axis.dot(a), a1 = axis.dot(b), c0 = axis.dot(c), c1 = axis.dot(d);
  const double low = std::max(std::min(a0, a1), std::min(c0, c1));
  const double high = std::min(std::max(a0, a1), std::max(c0, c1));
  return high > low;
}

}  // namespace

bool polylines_overlap(const std::vector<Vec2>& a, bool a_closed, const std::vector<Vec2>& b,
                       bool b_closed) {
  const std::size_t na = a.size() < 2 ? 0 : (a_closed ? a.size() : a.size() - 1);
  const std::size_t nb = b.size() < 2 ? 0 : (b_closed ? b.size() : b.size() - 1);
  for (std::size_t i = 0; i < na; ++i) {
    const Vec2& p = a[i];
    const Vec2& q = a[(i + 1) % a.size()];
    const Box2 box_pq = Box2(p).extend(q);
    for (std::size_t j = 0; j < nb; ++j) {
      const Vec2& r = b[j];
      const Vec2& s = b[(j + 1) % b.size()];
      if (!box_pq.intersects(Box2(r).extend(s))) continue;
      if (segments_overlap(p, q, r, s)) return true;
    }
  }
  return false;
}

namespace {

// Whether segment cd runs beside segment ab, within `tolerance` of its line, along more than
// twice the tolerance of ab's length (a crossing or a touch at a point runs beside it for about
// the tolerance at most, unless the segments meet at a very small angle).
bool segments_run_close(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                        double tolerance) {
  const double length = (b - a).norm();
  if (!(length > 2 * tolerance)) return false;
  const Vec2 along = (b - a) / length;
  const double tc = along.dot(c - a), td = along.dot(d - a);
  const double low = std::max(0.0, std::min(tc, td)), high = std::min(length, std::max(tc, td));
  if (!(high - low > 2 * tolerance)) return false;
  const auto at = [&](double t) { return c + (t - tc) / (td - tc) * (d - c); };
  const auto off_line = [&](const Vec2& p) {
    return std::abs(along.x() * (p.y() - a.y()) - along.y() * (p.x() - a.x()));
  };
  return off_line(at(low)) <= tolerance && off_line(at(high)) <= tolerance;
}

}  // namespace

bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double tolerance) {
  return segments_overlap(a, b, c, d) || segments_run_close(a, b, c, d, tolerance) ||
         segments_run_close(c, d, a, b, tolerance);
}

}  // namespace shapeproc::geometry
