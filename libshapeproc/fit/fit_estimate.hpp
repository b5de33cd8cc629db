// What a fit will need, estimated before any work so that a request that would exhaust memory is
// refused up front (core/resource_budget.hpp): the quadrature's points, the model's parameters,
// and the matrices of the Newton steps.
#pragma once

#include "libshapeproc/core/resource_budget.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::fit {

struct FitEstimate {
  core::ResourceEstimate resources;  // elements: the exemplar's; bytes: the fit's peak
  double quadrature_points = 0;      // upper bound: cells of a square window times shapes
  double parameters = 0;             // β per category, γ per category pair, axis and band
};

FitEstimate estimate_fit(const geometry::Scene& exemplar, const FitOptions& options);

}  // namespace shapeproc::fit
