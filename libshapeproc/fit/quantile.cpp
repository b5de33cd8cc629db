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

std::vector<double> category_medians(const geometry::Scene& scene,
                                     const std::function<double(const geometry::Element&)>& value) {
  std::vector<std::vector<double>> values(scene.categories.size());
  for (const geometry::Element& e : scene.elements)
    values[static_cast<std::size_t>(e.category)].push_back(value(e));
  std::vector<double> out;
  for (std::vector<double>& v : values) {
    if (v.empty()) {
      out.push_back(0.0);
      continue;
    }
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    out.push_back(v[v.size() / 2]);
  }
  return out;
}

}  // namespace shapeproc::fit
