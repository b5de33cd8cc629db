// Exact distances between 3D triangles and points, through CGAL's kernel (the only file that
// includes CGAL: it is slow to compile).
#pragma once

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// Shortest distance between triangles (a0, a1, a2) and (b0, b1, b2); 0 when they intersect.
// Degenerate triangles (segments or points) are allowed.
double triangle_triangle_distance(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                                  const Vec3& b1, const Vec3& b2);

// Distance from p to the triangle (a0, a1, a2).
double point_triangle_distance(const Vec3& p, const Vec3& a0, const Vec3& a1, const Vec3& a2);

}  // namespace shapeproc::geometry
