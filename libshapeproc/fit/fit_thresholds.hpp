// The first step of the fit (paper §6.1): the model's skeleton (categories, measurement settings,
// shape space) and the thresholds δ_0 < δ_1 < … of every category pair and axis, from quantiles
// of the exemplar's directional distance distributions or given explicitly.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"

namespace shapeproc::fit {

// Checks the options on entry; throws core::ArgumentError naming the bad value.
void check_fit_options(const FitOptions& options);

// The model before any estimate: categories (β = 1), measurement settings, and the exemplar's
// shapes with their categories (none for point patterns). Throws core::ArgumentError for an
// empty exemplar or a category without elements.
model::ShapeProcessModel model_skeleton(const geometry::Scene& exemplar, const FitOptions& options);

// The distinct shapes of each category's elements, in order of first appearance.
std::vector<std::vector<int>> shapes_by_category(const geometry::Scene& exemplar);

// Adds an interaction per category pair, with thresholds per axis: the quantiles of the pair's
// distances along the axis, of the pair's distances pooled over its axes when the axis has fewer
// than options.min_pairs_per_axis, or of all pairs when the pair has fewer than 2 (each fallback
// noted once per pair in `notes`). γ = 1, no standard errors yet.
void add_thresholds(model::ShapeProcessModel& model, const geometry::Scene& exemplar,
                    const std::vector<geometry::PairRecord>& pairs,
                    const geometry::DirectionBins& bins, const FitOptions& options,
                    std::vector<std::string>& notes);

}  // namespace shapeproc::fit
