// Canonical directions and axis bins for the direction-dependent interaction
// (docs/mathematics.md, "Pair measurements"). A direction and its opposite share one axis bin,
// because the interaction is symmetric in its two arguments.
//
// 2D: D evenly spaced directions e_k at angles 2πk/D (D even; D = 1 means isotropic); a direction
// goes to the nearest e_k and to axis k mod D/2. Angles are measured in the scene's frame (SVG's
// y axis points down, so 90° points down the page).
// 3D: the 12 HEALPix base pixels (Nside = 1); a direction goes to its base pixel, and antipodal
// pixels share an axis (6 axes). D = 1 means isotropic.
#pragma once

#include <optional>
#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// The default number of canonical directions: 8 in 2D, the 12 HEALPix base pixels in 3D.
inline int default_directions(int dimension) { return dimension == 3 ? 12 : 8; }
// `directions` when positive, else the default for the dimension.
inline int directions_or_default(int directions, int dimension) {
  return directions > 0 ? directions : default_directions(dimension);
}

class DirectionBins {
 public:
  // At most this many directions in 2D: an axis per half degree, far finer than any exemplar's
  // pairs can fill (each axis needs pairs of its own).
  static constexpr int kMaxDirections = 720;
  // Throws core::ArgumentError for D < 1, odd D > 1 or D > kMaxDirections in 2D, or D other than
  // 1 and 12 in 3D.
  DirectionBins(int dimension, int directions);

  int dimension() const { return dimension_; }
  int directions() const { return directions_; }
  int axis_count() const { return static_cast<int>(axes_.size()); }
  // Axis bin of a non-zero direction (2D uses x and y).
  int axis_of(const Vec3& direction) const;
  // 2D: the axis bin of every direction within `half_width` radians of `direction` (a non-zero
  // vector), when they all share one; nullopt when the arc meets a bin's edge, and in 3D.
  std::optional<int> arc_axis(const Vec3& direction, double half_width) const;
  // Representative unit direction of an axis (e_k with the smallest k of the pair).
  const Vec3& axis_direction(int axis) const { return axes_.at(static_cast<std::size_t>(axis)); }

 private:
  int dimension_;
  int directions_;
  std::vector<Vec3> axes_;
};

// HEALPix base pixel (0-3 north, 4-7 equatorial, 8-11 south) of a non-zero direction.
int healpix_base_pixel(const Vec3& direction);
// Unit vector to the centre of a HEALPix base pixel.
Vec3 healpix_base_pixel_centre(int pixel);

}  // namespace shapeproc::geometry
