#include "libshapeproc/geometry/directions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/error.hpp"

namespace shapeproc::geometry {

namespace {

Vec3 from_z_phi(double z, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return Vec3(s * std::cos(phi), s * std::sin(phi), z);
}
}  // namespace

int healpix_base_pixel(const Vec3& direction) {
  const Vec3 u = direction.normalized();
  const double z = u.z();
  double phi = std::atan2(u.y(), u.x());
  if (phi < 0) phi += 2 * core::kPi;
  double tt = phi / (core::kPi / 2);  // in [0, 4)
  if (tt >= 4.0) tt -= 4.0;
  if (std::abs(z) <= 2.0 / 3.0) {
    const int jp = static_cast<int>(0.5 + tt - 0.75 * z);  // ascending edge index
    const int jm = static_cast<int>(0.5 + tt + 0.75 * z);  // descending edge index
    if (jp == jm) return (jp % 4) | 4;
    return jp < jm ? jp % 4 : (jm % 4) + 8;
  }
  const int ntt = std::min(3, static_cast<int>(tt));
  return z > 0 ? ntt : ntt + 8;
}

Vec3 healpix_base_pixel_centre(int pixel) {
  if (pixel < 4) return from_z_phi(2.0 / 3.0, core::kPi / 4 + pixel * core::kPi / 2);
  if (pixel < 8) return from_z_phi(0.0, (pixel - 4) * core::kPi / 2);
  return from_z_phi(-2.0 / 3.0, core::kPi / 4 + (pixel - 8) * core::kPi / 2);
}

DirectionBins::DirectionBins(int dimension, int directions)
    : dimension_(dimension), directions_(directions) {
  if (directions < 1)
    throw core::ArgumentError("directions", "need at least 1, got " + std::to_string(directions));
  if (directions > kMaxDirections)
    throw core::ArgumentError("directions", "at most " + std::to_string(kMaxDirections) +
                                                " (an axis per half degree), got " +
                                                std::to_string(directions));
  if (directions == 1) {
    axes_.push_back(Vec3::UnitX());
    return;
  }
  if (dimension == 2) {
    if (directions % 2 != 0) {
      throw core::ArgumentError(
          "directions",
          "an even number (or 1 for isotropic) is needed in 2D, got " + std::to_string(directions));
    }
    for (int k = 0; k < directions / 2; ++k) {
      const double angle = 2 * core::kPi * k / directions;
      axes_.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    }
  } else {
    if (directions != 12) {
      throw core::ArgumentError("directions", "3D uses the 12 HEALPix base pixels (12) or 1, got " +
                                                  std::to_string(directions));
    }
    for (int pixel : {0, 1, 2, 3, 4, 5}) axes_.push_back(healpix_base_pixel_centre(pixel));
  }
}

namespace {
// The 2D axis of sector k (sector k is centred on the angle k · 2π / directions).
int sector_axis(long k, int directions) {
  const int half = directions / 2;
  return static_cast<int>(((k % half) + half) % half);
}
}  // namespace

int DirectionBins::axis_of(const Vec3& direction) const {
  if (directions_ == 1) return 0;
  if (dimension_ == 2) {
    const double step = 2 * core::kPi / directions_;
    return sector_axis(std::lround(std::atan2(direction.y(), direction.x()) / step), directions_);
  }
  const int pixel = healpix_base_pixel(direction);
  if (pixel < 4) return pixel;
  if (pixel < 8) return 4 + (pixel - 4) % 2;
  return (pixel - 8 + 2) % 4;  // south pixel 8 + (f + 2) % 4 is antipodal to north pixel f
}

std::optional<int> DirectionBins::arc_axis(const Vec3& direction, double half_width) const {
  if (dimension_ != 2) return std::nullopt;
  if (directions_ == 1) return 0;
  // In units of a sector, the arc is u ± w; it stays in sector round(u) while it does not reach
  // that sector's edges at round(u) ± 1/2 (the sectors at ±π are one: both map to one axis).
  const double step = 2 * core::kPi / directions_;
  const double u = std::atan2(direction.y(), direction.x()) / step;
  const long k = std::lround(u);
  if (!(std::abs(u - static_cast<double>(k)) + half_width / step < 0.5)) return std::nullopt;
  return sector_axis(k, directions_);
}

}  // namespace shapeproc::geometry
