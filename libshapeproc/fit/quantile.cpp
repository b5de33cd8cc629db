#include "libshapeproc/fit/quantile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "libshapeproc/core/check.hpp"

namespace shapeproc::fit {

double quantile(const std::vector<double>& sorted, double q) {
  core::check(!sorted.empty(), "quantile", "no values");
  core::check_in_range("quantile", "the order", q, 0.0, 1.0);
  const double h = (static_cast<double>(sorted.size()) - 1.0) * q;
  const std::size_t low = static_cast<std::size_t>(std::floor(h));
  if (low + 1 >= sorted.size()) return sorted.back();
  return sorted[low] + (h - static_cast<double>(low)) * (sorted[low + 1] - sorted[low]);
}

}  // namespace shapeproc::fit
