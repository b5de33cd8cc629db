#include "libshapeproc/model/fit_record.hpp"

#include <cmath>

namespace shapeproc::model {

std::optional<double> FitRecord::exemplar_density() const {
  if (!edits.empty() || window_min.empty() || window_min.size() != window_max.size())
    return std::nullopt;
  double measure = 1.0;
  for (std::size_t k = 0; k < window_min.size(); ++k) measure *= window_max[k] - window_min[k];
  if (!(measure > 0.0) || !std::isfinite(measure)) return std::nullopt;
  return static_cast<double>(elements) / measure;
}

}  // namespace shapeproc::model
