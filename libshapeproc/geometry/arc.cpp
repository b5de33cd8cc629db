#include "libshapeproc/geometry/arc.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::geometry {

namespace {

// Appends the arc of the ellipse (centre, radii, rotation) between parameter angles theta1 and
// theta1 + delta as cubic pieces of at most 90 degrees, ending exactly at `end`.
void append_arc_pieces(Path2& path, const Vec2& centre, double rx, double ry, double phi,
                       double theta1, double delta, const Vec2& start, const Vec2& end) {
  const int pieces =
      std::max(1, static_cast<int>(std::ceil(std::abs(delta) / (core::kPi / 2) - 1e-9)));
  const double step = delta / pieces;
  // Control-point distance for a circular arc of angle `step` on the unit circle.
  const double k = 4.0 / 3.0 * std::tan(step / 4.0);
  const double c = std::cos(phi), s = std::sin(phi);
  auto on_ellipse = [&](double t) {
    return Vec2(centre.x() + rx * std::cos(t) * c - ry * std::sin(t) * s,
                centre.y() + rx * std::cos(t) * s + ry * std::sin(t) * c);
  };
  auto tangent = [&](double t) {  // derivative with respect to t
    return Vec2(-rx * std::sin(t) * c - ry * std::cos(t) * s,
                -rx * std::sin(t) * s + ry * std::cos(t) * c);
  };
  Vec2 p0 = start;
  for (int i = 0; i < pieces; ++i) {
    const double t0 = theta1 + i * step;
    const double t1 = t0 + step;
    const Vec2 p3 = (i + 1 == pieces) ? end : on_ellipse(t1);
    path.segments.push_back(Segment2::bezier(p0, p0 + k * tangent(t0), p3 - k * tangent(t1), p3));
    p0 = p3;
  }
}

double angle_between(const Vec2& u, const Vec2& v) {
  return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

}  // namespace

void append_elliptical_arc(Path2& path, const Vec2& from, double rx, double ry,
                           double rotation_degrees, bool large_arc, bool sweep, const Vec2& to) {
  if (from == to) return;
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0.0 || ry == 0.0) {
    path.segments.push_back(Segment2::line(from, to));
    return;
  }
  const double phi = std::fmod(rotation_degrees, 360.0) * core::kPi / 180.0;
  const double c = std::cos(phi), s = std::sin(phi);
  // F.6.5.1: the midpoint difference in the ellipse's frame.
  const Vec2 half = 0.5 * (from - to);
  const Vec2 p(c * half.x() + s * half.y(), -s * half.x() + c * half.y());
  // F.6.6.2: scale radii up when the end point is out of reach.
  const double lambda = (p.x() * p.x()) / (rx * rx) + (p.y() * p.y()) / (ry * ry);
  if (lambda > 1.0) {
    const double root = std::sqrt(lambda);
    rx *= root;
    ry *= root;
  }
  // F.6.5.2: centre in the ellipse's frame.
  const double rx2 = rx * rx, ry2 = ry * ry;
  const double num = rx2 * ry2 - rx2 * p.y() * p.y() - ry2 * p.x() * p.x();
  const double den = rx2 * p.y() * p.y() + ry2 * p.x() * p.x();
  // End points a diameter apart (a circle drawn as two half arcs) leave num/den at rounding
  // level, whose square root would move the centre by 1e-8 of the radius, differently for each
  // copy of the drawing: such arcs are taken as exact half ellipses.
  const double ratio = num / den;
  double coef = ratio > 1e-12 ? std::sqrt(ratio) : 0.0;
  if (large_arc == sweep) coef = -coef;
  // Radii or end points that are not finite numbers (NaN radii, overflowing transforms) give no
  // ellipse: the segment is drawn as a line, as for zero radii, and the reader's check of
  // non-finite coordinates names the element.
  if (!std::isfinite(coef) || !std::isfinite(rx) || !std::isfinite(ry) || !std::isfinite(phi)) {
    path.segments.push_back(Segment2::line(from, to));
    return;
  }
  const Vec2 cp(coef * rx * p.y() / ry, -coef * ry * p.x() / rx);
  // F.6.5.3: centre in user space.
  const Vec2 mid = 0.5 * (from + to);
  const Vec2 centre(c * cp.x() - s * cp.y() + mid.x(), s * cp.x() + c * cp.y() + mid.y());
  // F.6.5.5-6: start angle and sweep.
  const Vec2 u((p.x() - cp.x()) / rx, (p.y() - cp.y()) / ry);
  const Vec2 v((-p.x() - cp.x()) / rx, (-p.y() - cp.y()) / ry);
  const double theta1 = angle_between(Vec2(1.0, 0.0), u);
  double delta = angle_between(u, v);
  if (!sweep && delta > 0) delta -= 2 * core::kPi;
  if (sweep && delta < 0) delta += 2 * core::kPi;
  append_arc_pieces(path, centre, rx, ry, phi, theta1, delta, from, to);
}

Path2 ellipse_path(const Vec2& centre, double rx, double ry) {
  Path2 path;
  const Vec2 start(centre.x() + rx, centre.y());
  append_arc_pieces(path, centre, rx, ry, 0.0, 0.0, 2 * core::kPi, start, start);
  path.closed = true;
  return path;
}

}  // namespace shapeproc::geometry
