#include "libshapeproc/sample/overlap_guard.hpp"

#include <algorithm>

namespace shapeproc::sample {

namespace {

// A proxy strays from the drawn outline by at most its tolerance times the shape's diagonal,
// plus the flattening of curves at a quarter of it (geometry::ProxyOptions): 1.25 tolerances.
// The margin adds a fifth for the rounding of the diagonal (the proxy's box, not the drawn one's).
// (Twice that, 2.5, cost 10% of two-kinds' sampling time for the same outputs.)
constexpr double kStrayFactor = 1.5;

// Whether two proxies have the same outline (to 1e-9 of their size).
bool same_outline(const geometry::Proxy2& a, const geometry::Proxy2& b) {
  if (a.segment_start.size() != b.segment_start.size()) return false;
  const double tolerance = 1e-9 * std::max(1.0, a.box.diagonal().norm());
  for (std::size_t i = 0; i < a.segment_start.size(); ++i)
    if ((a.segment_start[i] - b.segment_start[i]).lpNorm<Eigen::Infinity>() > tolerance ||
        (a.segment_end[i] - b.segment_end[i]).lpNorm<Eigen::Infinity>() > tolerance)
      return false;
  return true;
}

bool same_outline(const geometry::Proxy3& a, const geometry::Proxy3& b) {
  if (a.triangles != b.triangles || a.vertices.size() != b.vertices.size()) return false;
  const double tolerance = 1e-9 * std::max(1.0, a.box.diagonal().norm());
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    if ((a.vertices[i] - b.vertices[i]).lpNorm<Eigen::Infinity>() > tolerance) return false;
  return true;
}

std::vector<std::vector<double>> breakpoints_of(const model::Interaction& interaction) {
  std::vector<std::vector<double>> breakpoints;
  const int categories = interaction.category_count();
  for (int a = 0; a < categories; ++a)
    for (int b = 0; b < categories; ++b)
      breakpoints.push_back(interaction.interacts(a, b) ? interaction.breakpoints(a, b)
                                                        : std::vector<double>{});
  return breakpoints;
}

// Per pair of categories: whether its hard core lets it overlap (then the guard has nothing to
// keep apart).
std::vector<char> overlap_allowed(const model::Interaction& interaction) {
  std::vector<char> allowed;
  const int categories = interaction.category_count();
  for (int a = 0; a < categories; ++a)
    for (int b = 0; b < categories; ++b)
      allowed.push_back(interaction.interacts(a, b) && interaction.min_hard_core(a, b) < 0.0);
  return allowed;
}

}  // namespace

OverlapGuard::OverlapGuard(const OverlapGuard& same_shapes, const model::Interaction& interaction)
    : breakpoints_(breakpoints_of(interaction)),
      overlap_allowed_(overlap_allowed(interaction)),
      categories_(interaction.category_count()),
      outlines_(same_shapes.outlines_),
      error_(same_shapes.error_) {}

OverlapGuard::OverlapGuard(const model::Interaction& interaction,
                           const geometry::Scene& shape_space,
                           const geometry::PairMeasurer& proxies)
    : breakpoints_(breakpoints_of(interaction)),
      overlap_allowed_(overlap_allowed(interaction)),
      categories_(interaction.category_count()) {
  const geometry::MeasurementOptions& options = proxies.options();
  if (options.distance != geometry::DistanceKind::shape ||
      !(options.proxy.tolerance > geometry::kOutlineTolerance) || shape_space.shapes.empty())
    return;
  geometry::MeasurementOptions fine = options;
  fine.proxy.tolerance = geometry::kOutlineTolerance;
  fine.direction = geometry::DirectionKind::centroid;  // distances only: no gravitation tables
  outlines_ = std::make_shared<const geometry::PairMeasurer>(shape_space, fine);
  bool finer = false;
  for (std::size_t s = 0; s < shape_space.shapes.size() && !finer; ++s)
    finer = outlines_->dimension() == 2
                ? !same_outline(proxies.proxies2()[s], outlines_->proxies2()[s])
                : !same_outline(proxies.proxies3()[s], outlines_->proxies3()[s]);
  if (!finer) {
    outlines_.reset();
    return;
  }
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
  if (!outlines_ ||
      overlap_allowed_[static_cast<std::size_t>(xi.category * categories_ + other.category)])
    return false;
  const double margin =
      error_[static_cast<std::size_t>(xi.shape)] + error_[static_cast<std::size_t>(other.shape)];
  // The proxies' distance is only known to lie in its interval between breakpoints: the guard
  // measures again unless the interval starts at or beyond the margin.
  const std::vector<double>& marks =
      breakpoints_[static_cast<std::size_t>(xi.category * categories_ + other.category)];
  const auto above = std::upper_bound(marks.begin(), marks.end(), proxy_distance);
  const double low = above == marks.begin() ? proxy_distance : *(above - 1);
  if (low >= margin) return false;
  return outlines_->distance(xi.shape, other.shape, offset, margin) < 0.0;
}

}  // namespace shapeproc::sample
