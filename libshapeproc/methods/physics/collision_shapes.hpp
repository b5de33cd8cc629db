// The drawn shapes as a rigid-body engine sees them, for the interleaved physics solver
// (interleaved_physics.hpp): convex pieces in the shape's local coordinates.
// - 2D: the triangles of the shape's mass (its proxy's filled regions, on their fill rule, and
//   the strips around its curves), from a constrained Delaunay triangulation (CGAL) of their
//   outlines, each triangle kept when its centroid lies in the mass. Slivers thinner than
//   `thinnest` are left out, since an engine cannot build a polygon from them.
// - 3D: the vertices of the proxy mesh, whose convex hull the engine collides (a concave mesh
//   collides as its hull: a documented simplification).
// Points have no pieces and do not collide.
#pragma once

#include <array>
#include <vector>

#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::methods {

struct CollisionShape {
  std::vector<std::array<geometry::Vec2, 3>> triangles;  // 2D, counter-clockwise
  std::vector<geometry::Vec3> hull_points;               // 3D
  double radius = 0.0;  // largest distance of the shape's points from its origin

  bool empty() const { return triangles.empty() && hull_points.empty(); }
};

// `thinnest`: the smallest triangle height kept (2D), in the shape's units.
CollisionShape collision_shape(const geometry::Shape& shape, double thinnest);

}  // namespace shapeproc::methods
