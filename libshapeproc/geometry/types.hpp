// Basic vector and box types shared by every module.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::geometry {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
// Axis-aligned boxes; an empty box has min > max (Eigen's convention).
using Box2 = Eigen::AlignedBox2d;
using Box3 = Eigen::AlignedBox3d;
// 2D affine map (SVG's `matrix(a b c d e f)` is [a c e; b d f]).
using Affine2 = Eigen::Affine2d;

// Lifts a 2D box to 3D with z = [0, 0].
inline Box3 lift(const Box2& box) {
  if (box.isEmpty()) return Box3();
  return Box3(Vec3(box.min().x(), box.min().y(), 0.0), Vec3(box.max().x(), box.max().y(), 0.0));
}

// Area (dimension 2: x and y sides) or volume (dimension 3) of a box.
inline double measure(const Box3& box, int dimension) {
  const Vec3 sides = box.sizes();
  return dimension == 2 ? sides.x() * sides.y() : sides.x() * sides.y() * sides.z();
}

// Area (dimension 2) or volume (dimension 3) of a ball of radius r.
inline double ball_measure(double r, int dimension) {
  return dimension == 3 ? 4.0 / 3.0 * core::kPi * r * r * r : core::kPi * r * r;
}

}  // namespace shapeproc::geometry
