// Empirical quantiles: linear interpolation between order statistics (Hyndman & Fan type 7),
// the one definition the thresholds use.
#pragma once

#include <functional>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::fit {

// Q(q) of sorted values, q in [0, 1]: with h = (n − 1) q, x_⌊h⌋ + (h − ⌊h⌋)(x_⌊h⌋+1 − x_⌊h⌋).
// Q(0) is the minimum, Q(1) the maximum. `sorted` must be non-empty and ascending.
double quantile(const std::vector<double>& sorted, double q);

// Per category of `scene`, the median of `value` over its elements (the upper one of an even
// count; 0 for a category without elements).
std::vector<double> category_medians(const geometry::Scene& scene,
                                     const std::function<double(const geometry::Element&)>& value);

}  // namespace shapeproc::fit
