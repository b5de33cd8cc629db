#include "libshapeproc/sample/overlap_guard.hpp"

#include <algorithm>

namespace shapeproc::sample {

namespace {

// A proxy strays from the drawn outline by at most its tolerance times the shape's diagonal,
// plus the flattening of curves at a quarter of it (geometry::ProxyOptions); the guard's margin
// is twice that, for the filled regions' signed distance.
constexpr double kStrayFactor = 2.0 * 1.25;

}  // namespace

OverlapGuard::OverlapGuard(const model::Interaction& interaction,
                           const geometry::Scene& shape_space,
                           const geometry::MeasurementOptions& options)
    : interaction_(interaction) {
  if (options.distance != geometry::DistanceKind::shape ||
      !(options.proxy.tolerance > geometry::kOutlineTolerance) || shape_space.shapes.empty())
    return;
  geometry::MeasurementOptions fine = options;
  fine.proxy.tolerance = geometry::kOutlineTolerance;
  outlines_ = std::make_unique<const geometry::PairMeasurer>(shape_space, fine);
  const double tolerance = options.proxy.tolerance + geometry::kOutlineTolerance;
  for (std::size_t s = 0; s < shape_space.shapes.size(); ++s) {
    const double diagonal = outlines_->dimension() == 2
                                ? outlines_->proxies2()[s].box.diagonal().norm()
                                : outlines_->proxies3()[s].box.diagonal().norm();
    error_.push_back(kStrayFactor * tolerance * diagonal);
  }
}

OverlapGuard::~OverlapGuard() = default;

bool OverlapGuard::overlaps(const geometry::Element& xi, const geometry::Element& other,
                            const geometry::Vec3& offset, double proxy_distance) const {
  if (!outlines_) return false;
  const double margin =
      error_[static_cast<std::size_t>(xi.shape)] + error_[static_cast<std::size_t>(other.shape)];
  // The proxies' distance is only known to lie in its interval between breakpoints: the guard
  // measures again unless the interval starts at or beyond the margin.
  const std::vector<double>& marks = interaction_.breakpoints(xi.category, other.category);
  const auto above = std::upper_bound(marks.begin(), marks.end(), proxy_distance);
  const double low = above == marks.begin() ? proxy_distance : *(above - 1);
  if (low >= margin) return false;
  return outlines_->distance(xi.shape, other.shape, offset, margin) < 0.0;
}

}  // namespace shapeproc::sample
