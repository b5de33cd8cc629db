#include "libshapeproc/fit/quantile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shapeproc::fit {

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) throw std::invalid_argument("quantile of no values");
  if (!(q >= 0 && q <= 1)) throw std::invalid_argument("quantile order must be in [0, 1]");
  const double h = (static_cast<double>(sorted.size()) - 1.0) * q;
  const std::size_t low = static_cast<std::size_t>(std::floor(h));
  if (low + 1 >= sorted.size()) return sorted.back();
  return sorted[low] + (h - static_cast<double>(low)) * (sorted[low + 1] - sorted[low]);
}

}  // namespace shapeproc::fit
