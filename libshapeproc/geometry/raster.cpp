#include "libshapeproc/geometry/raster.hpp"

namespace shapeproc::geometry {

float Raster::sample(const Box3& box, const Vec2& p) const {
  if (width <= 0 || height <= 0) return 0.0f;
  const Vec3 size = box.sizes();
  const double fx = (p.x() - box.min().x()) / size.x() * width;
  const double fy = (p.y() - box.min().y()) / size.y() * height;
  if (!(fx >= 0 && fy >= 0 && fx < width && fy < height)) return 0.0f;
  return at(static_cast<int>(fx), static_cast<int>(fy));
}

}  // namespace shapeproc::geometry
