#include "libshapeproc/fit/fit_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/format.hpp"
#include "libshapeproc/geometry/directions.hpp"

namespace shapeproc::fit {

FitEstimate estimate_fit(const geometry::Scene& exemplar, const FitOptions& options) {
  const int d = exemplar.dimension;
  const double along = options.quadrature > 0 ? options.quadrature : default_quadrature_cells(d);
  const double cells = std::pow(along * std::pow(2.0, options.refinement), d);
  const double shapes = options.shapes_per_location > 0
                            ? std::min<double>(options.shapes_per_location,
                                               static_cast<double>(exemplar.shapes.size()))
                            : static_cast<double>(std::max<std::size_t>(1, exemplar.shapes.size()));
  const double categories =
      static_cast<double>(std::max<std::size_t>(1, exemplar.categories.size()));
  const double axes = geometry::directions_or_default(options.measurement.directions, d);
  const double bands = static_cast<double>(std::max<std::size_t>(
      1, options.thresholds.empty() ? options.quantiles.size() : options.thresholds.size()));
  FitEstimate estimate;
  estimate.quadrature_points = cells * shapes + static_cast<double>(exemplar.elements.size());
  estimate.parameters = categories + categories * (categories + 1) / 2 * axes * bands;
  // Per quadrature point, its statistics and neighbour lists (measured: 720 bytes a point on a
  // 7,050-point exemplar, 9.0e6 points, 6.4 GB peak; 570 on 1,066 points); the Newton steps hold
  // the parameters' square matrices (information, covariance, a factor).
  const double bytes =
      768.0 * estimate.quadrature_points + 3.0 * 8.0 * estimate.parameters * estimate.parameters;
  estimate.resources.elements = static_cast<double>(exemplar.elements.size());
  estimate.resources.bytes = bytes;
  estimate.resources.basis = core::format_general(estimate.quadrature_points, 3) +
                             " quadrature points and " +
                             core::format_general(estimate.parameters, 3) + " parameters";
  return estimate;
}

}  // namespace shapeproc::fit
