#include "libshapeproc/model/fit_record.hpp"

#include <cmath>

namespace shapeproc::model {

namespace {

constexpr std::pair<FitPath, const char*> kPathNames[] = {
    {FitPath::pseudo_likelihood, "pseudo-likelihood"},
    {FitPath::likelihood_own_window, "likelihood, own window"},
    {FitPath::likelihood_stationary, "likelihood, stationary window"},
    {FitPath::likelihood_stationary_restarted,
     "likelihood, stationary window, restarted from the own window's estimate"},
    {FitPath::likelihood_own_after_stationary,
     "likelihood, own window, after the stationary window did not converge"},
};

}  // namespace

std::string fit_path_name(FitPath path) {
  for (const auto& [p, name] : kPathNames)
    if (p == path) return name;
  return "pseudo-likelihood";
}

std::optional<FitPath> parse_fit_path(const std::string& name) {
  for (const auto& [p, n] : kPathNames)
    if (name == n) return p;
  return std::nullopt;
}

std::optional<double> FitRecord::exemplar_density() const {
  if (!edits.empty() || window_min.empty() || window_min.size() != window_max.size())
    return std::nullopt;
  double measure = 1.0;
  for (std::size_t k = 0; k < window_min.size(); ++k) measure *= window_max[k] - window_min[k];
  if (!(measure > 0.0) || !std::isfinite(measure)) return std::nullopt;
  return static_cast<double>(elements) / measure;
}

}  // namespace shapeproc::model
