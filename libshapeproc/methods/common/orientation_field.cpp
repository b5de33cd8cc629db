#include "libshapeproc/methods/common/orientation_field.hpp"

#include <cmath>
#include <string>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::methods {

OrientationField OrientationField::constant(double degrees) {
  OrientationField field;
  field.constant_set_ = true;
  field.degrees_ = degrees;
  // On screen y points down: a counter-clockwise turn on screen is a clockwise one in (x, y).
  field.radians_ = -degrees * core::kPi / 180.0;
  return field;
}

OrientationField OrientationField::map(std::shared_ptr<const geometry::Raster> raster,
                                       const geometry::Box3& box) {
  OrientationField field;
  field.raster_ = std::move(raster);
  field.box_ = box;
  return field;
}

double OrientationField::angle_at(const geometry::Vec3& position) const {
  if (constant_set_) return radians_;
  if (!raster_) return 0.0;
  const double g = raster_->sample(box_, geometry::Vec2(position.x(), position.y()));
  return -2.0 * core::kPi * g;
}

geometry::Vec3 turn_about_z(const geometry::Vec3& offset, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return {c * offset.x() - s * offset.y(), s * offset.x() + c * offset.y(), offset.z()};
}

geometry::Vec3 OrientationField::turn(const geometry::Vec3& offset, const geometry::Vec3& position,
                                      bool inverse) const {
  if (empty()) return offset;
  const double a = angle_at(position);
  return turn_about_z(offset, inverse ? -a : a);
}

std::string OrientationField::describe() const {
  if (constant_set_) return core::format_number(degrees_) + " degrees";
  return raster_ ? "map" : "none";
}

}  // namespace shapeproc::methods
