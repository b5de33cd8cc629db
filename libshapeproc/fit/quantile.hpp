// Empirical quantiles: linear interpolation between order statistics (Hyndman & Fan type 7),
// the one definition the thresholds use.
#pragma once

#include <vector>

namespace shapeproc::fit {

// Q(q) of sorted values, q in [0, 1]: with h = (n − 1) q, x_⌊h⌋ + (h − ⌊h⌋)(x_⌊h⌋+1 − x_⌊h⌋).
// Q(0) is the minimum, Q(1) the maximum. `sorted` must be non-empty and ascending.
double quantile(const std::vector<double>& sorted, double q);

}  // namespace shapeproc::fit
