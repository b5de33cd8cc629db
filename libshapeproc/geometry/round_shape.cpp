#include "libshapeproc/geometry/round_shape.hpp"

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/path.hpp"

namespace shapeproc::geometry {

namespace {

// The largest angle between consecutive points of a closed polyline seen from the origin, or a
// full turn when the polyline does not go round the origin once.
double widest_gap(const std::vector<Vec2>& points) {
  double widest = 0.0, turned = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2& a = points[i];
    const Vec2& b = points[(i + 1) % points.size()];
    const double angle = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    widest = std::max(widest, std::abs(angle));
    turned += angle;
  }
  constexpr double kTurn = 2.0 * core::kPi;
  return std::abs(std::abs(turned) - kTurn) < 1e-6 ? widest : kTurn;
}

}  // namespace

std::optional<double> round_radius(const Shape& shape) {
  if (std::holds_alternative<PointShape>(shape.geometry)) return 0.0;
  const auto* planar = std::get_if<PlanarShape>(&shape.geometry);
  if (planar == nullptr) return std::nullopt;
  double largest = 0.0;
  for (const Drawable2& part : planar->parts)
    for (const Path2& path : part.paths)
      for (const Segment2& s : path.segments)
        largest = std::max({largest, s.start.norm(), s.end.norm()});
  if (!(largest > 0.0)) return std::nullopt;
  bool any = false;
  for (const Drawable2& part : planar->parts) {
    for (const Path2& path : part.paths) {
      if (!path.closed || path.segments.empty()) return std::nullopt;
      const std::vector<Vec2> points = flatten(path, 0.1 * kRoundTolerance * largest);
      if (points.size() < 3) return std::nullopt;
      double low = points.front().norm(), high = low;
      for (const Vec2& p : points) {
        low = std::min(low, p.norm());
        high = std::max(high, p.norm());
      }
      if (high - low > kRoundTolerance * largest || widest_gap(points) > kRoundGap)
        return std::nullopt;
      any = true;
    }
  }
  if (!any) return std::nullopt;
  return (1.0 + kRoundTolerance) * largest;
}

}  // namespace shapeproc::geometry
