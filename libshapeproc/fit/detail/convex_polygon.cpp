#include "libshapeproc/fit/detail/convex_polygon.hpp"

namespace shapeproc::fit {

double Polygon::area() const {
  if (n == 0) return 0.0;
  double twice = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const Point2& a = p[static_cast<std::size_t>(i)];
    const Point2& b = p[static_cast<std::size_t>(i + 1)];
    twice += a.x * b.y - a.y * b.x;
  }
  const Point2& a = p[static_cast<std::size_t>(n - 1)];
  twice += a.x * p[0].y - a.y * p[0].x;
  return 0.5 * twice;
}

void clip(const Polygon& polygon, const HalfPlane& h, Polygon& out) {
  out.n = 0;
  auto add = [&](const Point2& q) {
    if (out.n < Polygon::kCapacity) out.p[static_cast<std::size_t>(out.n++)] = q;
  };
  for (int i = 0; i < polygon.n; ++i) {
    const Point2& a = polygon.p[static_cast<std::size_t>(i)];
    const Point2& b = polygon.p[static_cast<std::size_t>((i + 1) % polygon.n)];
    const double fa = h.nx * a.x + h.ny * a.y - h.c;
    const double fb = h.nx * b.x + h.ny * b.y - h.c;
    if (fa <= 0) add(a);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
      const double t = fa / (fa - fb);
      add({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
}

}  // namespace shapeproc::fit
