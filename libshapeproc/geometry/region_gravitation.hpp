// Gravitation between 2D regions as a double boundary integral (exact for polygonal proxies).
//
// With φ(x, y) = 1/|y − x|, the kernel is (y − x)/|y − x|^3 = ∇_x φ, and in 2D
// div_y((y − x)/|y − x|) = 1/|y − x|. Two applications of the divergence theorem turn the force
// between uniform regions A and B into
//   F(A, B) = ∮_∂A ∮_∂B n_A(x) [(y − x)·n_B(y)] / |y − x| ds_y ds_x,
// whose integrand is bounded (|(y − x)·n_B| ≤ |y − x|), so touching, interlocking and even
// overlapping regions are handled without any singularity. For a straight edge j of ∂B,
// (y − x)·n_j is constant in y and ∫_edge ds_y / |y − x| has a closed form (a difference of
// asinh), so only the outer integral along each edge of ∂A needs Gauss–Legendre quadrature, with
// more points for edge pairs that are close relative to their lengths. Regions far apart
// (centroid distance above 5 times the sum of their radii) use the second-order far-field
// expansion (far_field_force in gravitation.hpp), whose relative error is below (1/5)^3.
#pragma once

#include <array>
#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// The boundary of a region's mass: edges with outward unit normals. A point element is a unit
// point mass (no edges).
struct MassBoundary2 {
  std::vector<Vec2> start, end, normal;
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
  Eigen::Matrix2d moments = Eigen::Matrix2d::Zero();  // ∫ (x − c)(x − c)^T dA
  double radius = 0.0;  // of the edges around the centroid
  bool point = false;

  // Adds an edge with its outward normal (the side away from the mass), updating area and
  // centroid; call finish() after the last edge.
  void add_edge(const Vec2& a, const Vec2& b, const Vec2& outward_normal);
  void finish();
};

// F(A, B) with B moved by `offset`.
Vec2 gravitation_force(const MassBoundary2& a, const MassBoundary2& b, const Vec2& offset);

// The 3D analogue for solids bounded by closed triangle meshes: in 3D div_y((y − x)/|y − x|) is
// 2/|y − x|, so F(A, B) = ½ ∮_∂A ∮_∂B n_A(x) [(y − x)·n_B(y)] / |y − x| dS_y dS_x, again with a
// bounded integrand. Both surface integrals use symmetric triangle rules (1 point for triangle
// pairs far apart relative to their sizes, 3 points, or 3 points on each quarter when near).
struct MassSurface3 {
  std::vector<std::array<Vec3, 3>> triangles;  // oriented outwards
  std::vector<Vec3> normal;                    // unit outward normals
  std::vector<double> area;
  double volume = 0.0;
  Vec3 centroid = Vec3::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();  // ∫ (x − c)(x − c)^T dV
  double radius = 0.0;

  // From a closed mesh; flips the orientation when the signed volume is negative.
  static MassSurface3 from_closed_mesh(const std::vector<Vec3>& vertices,
                                       const std::vector<std::array<int, 3>>& triangles);
};

Vec3 gravitation_force(const MassSurface3& a, const MassSurface3& b, const Vec3& offset);

}  // namespace shapeproc::geometry
