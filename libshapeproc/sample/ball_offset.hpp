// An offset uniform in the ball (disc in 2D) of a radius, by rejection from its bounding cube:
// the shifts, the compressing burn-in's pushes and the births near neighbours draw their moves
// with it.
#pragma once

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::sample {

inline geometry::Vec3 offset_in_ball(core::Random& random, double radius, int dimension) {
  geometry::Vec3 offset = geometry::Vec3::Zero();
  do {
    for (int axis = 0; axis < dimension; ++axis)
      offset[axis] = radius * (2.0 * random.uniform() - 1.0);
  } while (offset.squaredNorm() > radius * radius);
  return offset;
}

}  // namespace shapeproc::sample
