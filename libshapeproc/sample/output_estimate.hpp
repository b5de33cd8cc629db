// What a shape-process output will need, estimated before any sampling so that a request that
// would exhaust memory or run for hours is refused up front (core/resource_budget.hpp).
#pragma once

#include <optional>

#include "libshapeproc/core/resource_budget.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::sample {

// Memory one element of a chain takes, all structures included (measured: about 1.5 KiB per
// element on a 7,000-element output of dots-random; rounded up).
inline constexpr double kBytesPerElement = 2048;

// Elements: `exemplar_density` (elements per unit measure, from the model's fit record) times the
// domain's measure; without it, Σ_c β_c times the measure, the Poisson count (an upper bound for
// an inhibitive model). Bytes: that many elements per chain, for `chains_at_once` chains.
core::ResourceEstimate estimate_output(double exemplar_density, const geometry::Domain& domain,
                                       int dimension, int chains_at_once);
core::ResourceEstimate estimate_output(const model::ShapeProcessModel& model,
                                       const geometry::Domain& domain,
                                       std::optional<double> exemplar_density, int chains_at_once);

}  // namespace shapeproc::sample
