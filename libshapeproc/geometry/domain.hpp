// The domain a synthesis method fills, a fit integrates over and a metric measures in: a box (a
// rectangle in 2D, with z = [0, 0]), its boundary (a torus, where offsets take the minimum image,
// or open), and in 2D an optional shape mask and intensity map stretched over the box.
// Every method, the fit's edge treatment and the metrics take their geometry from here.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "libshapeproc/geometry/raster.hpp"
#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

struct Proxy2;

enum class Boundary { torus, open };

// `offset` replaced by its nearest image on the torus of sizes `period` (axes with period 0 are
// open): the one place the minimum-image rule is written.
inline Vec3 minimum_image(Vec3 offset, const Vec3& period) {
  for (int axis = 0; axis < 3; ++axis) {
    // Offsets within half a period, most of them, are their own image (without a call to round).
    if (period[axis] > 0 && !(std::abs(offset[axis]) < 0.5 * period[axis]))
      offset[axis] -= period[axis] * std::round(offset[axis] / period[axis]);
  }
  return offset;
}

// How statistics treat the elements near an open window's edge (docs/mathematics.md, "Edge
// treatment"): `none`: every element counts, its neighbourhood cut by the edge; `border`: only
// elements at least the interaction range inside the window count, their neighbours anywhere in it;
// `automatic` (metrics): border when enough elements are that far inside, else none. A torus
// needs no treatment.
enum class EdgeTreatment { automatic, none, border };
const char* to_string(EdgeTreatment edge);

// "torus" or "open"; parse_boundary throws core::ArgumentError on anything else.
const char* to_string(Boundary boundary);
Boundary parse_boundary(const std::string& text);

class Domain {
 public:
  // A box of `dimension` (2 or 3) with positive sizes along its axes; a torus cannot take a mask.
  // Throws core::ArgumentError otherwise.
  Domain(const Box3& box, int dimension, Boundary boundary);
  // [0, W] x [0, H] in 2D, [0, W] x [0, H] x [0, D] in 3D (`sizes` holds 2 or 3 entries).
  static Domain from_sizes(const std::vector<double>& sizes, Boundary boundary);

  const Box3& box() const { return box_; }
  int dimension() const { return dimension_; }
  Boundary boundary() const { return boundary_; }
  bool periodic() const { return boundary_ == Boundary::torus; }
  Vec3 sizes() const { return box_.sizes(); }
  // Area (2D) or volume (3D) of the box.
  double measure() const;
  // The torus's period along each axis (the box's sizes), zero on an open domain and along unused
  // axes.
  const Vec3& period() const { return period_; }

  // The offset `offset` (from one position to another) replaced by its nearest image on a torus;
  // unchanged on an open domain.
  Vec3 minimum_image(const Vec3& offset) const { return geometry::minimum_image(offset, period_); }
  // A position moved into the box along the torus's axes (unchanged when open).
  Vec3 wrap(Vec3 position) const;
  // Whether a reference position lies in the box (closed).
  bool contains(const Vec3& position) const;

  // 2D mask: inside where the grey level is >= 0.5. Setting one makes the domain open-only.
  void set_mask(std::shared_ptr<const Raster> mask);
  void set_intensity(std::shared_ptr<const Raster> intensity);
  const Raster* mask() const { return mask_.get(); }
  const Raster* intensity() const { return intensity_.get(); }
  bool has_local_factor() const { return mask_ || intensity_; }

  // Whether a 2D proxy placed at `position` lies inside the mask (its reference position and its
  // outline, sampled at half-pixel spacing); true without a mask.
  bool contains(const Proxy2& proxy, const Vec2& position) const;
  // The intensity map's value at `position` (1 without a map).
  double intensity_at(const Vec2& position) const;

 private:
  Box3 box_;
  int dimension_;
  Boundary boundary_;
  Vec3 period_ = Vec3::Zero();
  std::shared_ptr<const Raster> mask_, intensity_;
};

}  // namespace shapeproc::geometry
