#include "libshapeproc/geometry/domain.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::geometry {

const char* to_string(Boundary boundary) { return boundary == Boundary::torus ? "torus" : "open"; }

const char* to_string(EdgeTreatment edge) {
  return edge == EdgeTreatment::border ? "border"
         : edge == EdgeTreatment::none ? "none"
                                       : "automatic";
}

Boundary parse_boundary(const std::string& text) {
  if (text == "torus") return Boundary::torus;
  if (text == "open") return Boundary::open;
  throw core::ArgumentError("domain", "the boundary is 'torus' or 'open', got '" + text + "'");
}

Domain::Domain(const Box3& box, int dimension, Boundary boundary)
    : box_(box), dimension_(dimension), boundary_(boundary) {
  core::check(dimension == 2 || dimension == 3, "domain",
              "the dimension is 2 or 3, got " + std::to_string(dimension));
  for (int axis = 0; axis < dimension; ++axis) {
    core::check_positive("domain",
                         axis == 0   ? "the width"
                         : axis == 1 ? "the height"
                                     : "the depth",
                         box.sizes()[axis]);
  }
  if (boundary == Boundary::torus) period_.head(dimension) = box.sizes().head(dimension);
}

Domain Domain::from_sizes(const std::vector<double>& sizes, Boundary boundary) {
  core::check(sizes.size() == 2 || sizes.size() == 3, "domain", "give 2 (W,H) or 3 (W,H,D) sizes");
  Vec3 max = Vec3::Zero();
  for (std::size_t axis = 0; axis < sizes.size(); ++axis) max[static_cast<int>(axis)] = sizes[axis];
  return Domain(Box3(Vec3::Zero(), max), static_cast<int>(sizes.size()), boundary);
}

double Domain::measure() const {
  const Vec3 s = box_.sizes();
  return dimension_ == 3 ? s.prod() : s.x() * s.y();
}

Vec3 Domain::wrap(Vec3 position) const {
  if (boundary_ != Boundary::torus) return position;
  for (int axis = 0; axis < dimension_; ++axis) {
    const double low = box_.min()[axis], size = box_.sizes()[axis];
    position[axis] -= size * std::floor((position[axis] - low) / size);
  }
  return position;
}

bool Domain::contains(const Vec3& position) const {
  for (int axis = 0; axis < dimension_; ++axis) {
    if (!(position[axis] >= box_.min()[axis] && position[axis] <= box_.max()[axis])) return false;
  }
  return true;
}

void Domain::set_mask(std::shared_ptr<const Raster> mask) {
  core::check(!mask || dimension_ == 2, "domain", "shape masks are for 2D domains");
  core::check(!mask || boundary_ == Boundary::open, "domain",
              "a torus needs a rectangular domain: a mask needs an open boundary");
  mask_ = std::move(mask);
}

void Domain::set_intensity(std::shared_ptr<const Raster> intensity) {
  core::check(!intensity || dimension_ == 2, "domain", "intensity maps are for 2D domains");
  intensity_ = std::move(intensity);
}

bool Domain::contains(const Proxy2& proxy, const Vec2& position) const {
  if (!mask_) return true;
  const Raster& mask = *mask_;
  if (mask.sample(box_, position) < 0.5f) return false;
  const double pixel =
      0.5 * std::min(box_.sizes().x() / mask.width, box_.sizes().y() / mask.height);
  for (std::size_t k = 0; k < proxy.segment_start.size(); ++k) {
    const Vec2 a = proxy.segment_start[k] + position, b = proxy.segment_end[k] + position;
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / pixel)));
    for (int i = 0; i <= steps; ++i) {
      if (mask.sample(box_, a + (b - a) * (static_cast<double>(i) / steps)) < 0.5f) return false;
    }
  }
  return true;
}

double Domain::intensity_at(const Vec2& position) const {
  return intensity_ ? static_cast<double>(intensity_->sample(box_, position)) : 1.0;
}

}  // namespace shapeproc::geometry
