// Convex polygons cut by half-planes (Sutherland–Hodgman), the pieces of 2D quadrature cells.
#pragma once

#include <algorithm>
#include <array>

namespace shapeproc::fit {

struct Point2 {
  double x, y;
};

// The half-plane n·p ≤ c (p relative to the cell's centre).
struct HalfPlane {
  double nx, ny, c;
};

// A convex polygon with inline storage: a square cut by k lines has at most 4 + k vertices.
// Copies move only the vertices in use.
struct Polygon {
  static constexpr int kCapacity = 48;
  std::array<Point2, kCapacity> p;
  int n = 0;

  Polygon() = default;
  Polygon(const Polygon& o) : n(o.n) { std::copy_n(o.p.begin(), n, p.begin()); }
  Polygon& operator=(const Polygon& o) {
    n = o.n;
    std::copy_n(o.p.begin(), n, p.begin());
    return *this;
  }

  // Signed area (positive counter-clockwise).
  double area() const;
};

// out = polygon ∩ h.
void clip(const Polygon& polygon, const HalfPlane& h, Polygon& out);

}  // namespace shapeproc::fit
