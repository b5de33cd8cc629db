// A local orientation field over the output (Ma et al. 2011, §5, eq. 7): the angle by which the
// exemplar's frame is turned at each place of a 2D output. Neighbourhood offsets are compared in
// the local frame (p̂(s') = o(s)⁻¹ (p(s') − p(s))), predictions and copied patches are turned
// into it, and single-sample elements are drawn turned by it.
#pragma once

#include <memory>

#include "libshapeproc/geometry/raster.hpp"
#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::methods {

class OrientationField {
 public:
  OrientationField() = default;  // none: the global frame everywhere
  // The same angle everywhere, in degrees (counter-clockwise on screen: SVG's y axis points down,
  // so positive angles turn from +x towards −y).
  static OrientationField constant(double degrees);
  // A grey-level map stretched over `box`: grey g turns by 360° g.
  static OrientationField map(std::shared_ptr<const geometry::Raster> raster,
                              const geometry::Box3& box);

  bool empty() const { return !constant_set_ && !raster_; }
  // The angle at `position`, in radians in the scene's coordinates (0 without a field).
  double angle_at(const geometry::Vec3& position) const;
  // `offset` turned by the field's angle at `position` (inverse: by minus it).
  geometry::Vec3 turn(const geometry::Vec3& offset, const geometry::Vec3& position,
                      bool inverse = false) const;
  // A description for records: "none", "30 degrees" or "map".
  std::string describe() const;

 private:
  bool constant_set_ = false;
  double radians_ = 0.0, degrees_ = 0.0;
  std::shared_ptr<const geometry::Raster> raster_;
  geometry::Box3 box_;
};

// Turns a 3D offset about z by `radians`.
geometry::Vec3 turn_about_z(const geometry::Vec3& offset, double radians);

}  // namespace shapeproc::methods
