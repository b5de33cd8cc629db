#include "libshapeproc/geometry/triangle_distance.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>

namespace shapeproc::geometry {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point point(const Vec3& v) { return Point(v.x(), v.y(), v.z()); }

bool degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
  return CGAL::collinear(point(a), point(b), point(c));
}

// Distance between two possibly degenerate triangles, going through segments when needed.
double segment_or_point_distance(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                 const Kernel::Triangle_3* other, const Vec3& b0, const Vec3& b1,
                                 const Vec3& b2) {
  // `a` is degenerate: it is covered by its longest edge.
  Vec3 p = a0, q = a1;
  if ((a2 - a0).squaredNorm() > (q - p).squaredNorm()) q = a2;
  if ((a2 - a1).squaredNorm() > (q - p).squaredNorm()) {
    p = a1;
    q = a2;
  }
  if (other) {
    if (p == q) return std::sqrt(CGAL::to_double(CGAL::squared_distance(point(p), *other)));
    // Segment to triangle (CGAL 5.5 has no direct form): 0 if they meet, otherwise the minimum is
    // attained at an end point of the segment or between the segment and an edge.
    const Kernel::Segment_3 segment(point(p), point(q));
    if (CGAL::do_intersect(segment, *other)) return 0.0;
    double best = std::min(CGAL::to_double(CGAL::squared_distance(point(p), *other)),
                           CGAL::to_double(CGAL::squared_distance(point(q), *other)));
    for (int k = 0; k < 3; ++k) {
      const Kernel::Segment_3 edge(other->vertex(k), other->vertex(k + 1));
      best = std::min(best, CGAL::to_double(CGAL::squared_distance(segment, edge)));
    }
    return std::sqrt(best);
  }
  // Both degenerate: segment to segment.
  Vec3 r = b0, s = b1;
  if ((b2 - b0).squaredNorm() > (s - r).squaredNorm()) s = b2;
  if ((b2 - b1).squaredNorm() > (s - r).squaredNorm()) {
    r = b1;
    s = b2;
  }
  if (p == q && r == s) return (p - r).norm();
  if (p == q)
    return std::sqrt(
        CGAL::to_double(CGAL::squared_distance(point(p), Kernel::Segment_3(point(r), point(s)))));
  if (r == s)
    return std::sqrt(
        CGAL::to_double(CGAL::squared_distance(point(r), Kernel::Segment_3(point(p), point(q)))));
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(Kernel::Segment_3(point(p), point(q)),
                                                          Kernel::Segment_3(point(r), point(s)))));
}

}  // namespace

double triangle_triangle_distance(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                                  const Vec3& b1, const Vec3& b2) {
  const bool a_flat = degenerate(a0, a1, a2), b_flat = degenerate(b0, b1, b2);
  if (!a_flat && !b_flat) {
    const Kernel::Triangle_3 ta(point(a0), point(a1), point(a2)),
        tb(point(b0), point(b1), point(b2));
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(ta, tb)));
  }
  if (a_flat && !b_flat) {
    const Kernel::Triangle_3 tb(point(b0), point(b1), point(b2));
    return segment_or_point_distance(a0, a1, a2, &tb, b0, b1, b2);
  }
  if (!a_flat && b_flat) {
    const Kernel::Triangle_3 ta(point(a0), point(a1), point(a2));
    return segment_or_point_distance(b0, b1, b2, &ta, a0, a1, a2);
  }
  return segment_or_point_distance(a0, a1, a2, nullptr, b0, b1, b2);
}

double point_triangle_distance(const Vec3& p, const Vec3& a0, const Vec3& a1, const Vec3& a2) {
  return triangle_triangle_distance(p, p, p, a0, a1, a2);
}

}  // namespace shapeproc::geometry
