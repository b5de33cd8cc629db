#include "libshapeproc/fit/parameter_budget.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace shapeproc::fit {

namespace {

int band_count(const std::vector<std::vector<double>>& axes) {
  int bands = 0;
  for (const std::vector<double>& t : axes) bands += static_cast<int>(t.size()) - 1;
  return bands;
}

// The pair keeps its hard core alone: one isotropic axis at its axes' smallest δ_0, no γ.
void reduce_to_hard_core(model::PairInteraction& pair) {
  if (pair.axes.empty()) return;
  // One isotropic axis at the smallest hard core: no axis keeps a hard core the others lack.
  model::AxisParameters axis = pair.axes.front();
  for (const model::AxisParameters& a : pair.axes)
    axis.thresholds.front() = std::min(axis.thresholds.front(), a.thresholds.front());
  axis.thresholds.resize(1);
  axis.gammas.clear();
  axis.gamma_standard_errors.clear();
  axis.status.clear();
  axis.observed_pairs.clear();
  axis.saturations.clear();
  pair.axes = {axis};
}

}  // namespace

double range_cap(const ParameterBudget& budget, double window, int dimension, double elements) {
  return budget.max_range_spacings * std::pow(window / std::max(1.0, elements), 1.0 / dimension);
}

void cap_range(std::vector<double>& thresholds, double cap) {
  if (thresholds.empty() || !(thresholds.back() > cap) || !(cap > 0)) return;
  while (thresholds.size() > 1 && thresholds[thresholds.size() - 2] >= cap) thresholds.pop_back();
  if (thresholds.size() > 1) thresholds.back() = cap;
}

void keep_bands(std::vector<double>& thresholds, int bands) {
  const int have = static_cast<int>(thresholds.size()) - 1;
  if (have <= bands) return;
  if (bands <= 0) {
    thresholds.resize(1);
    return;
  }
  // The thresholds kept: δ_0, then the split at contact, then the range's end, then the others
  // from the nearest up, until `bands` bands.
  std::vector<double> inner(thresholds.begin() + 1, thresholds.end());
  std::vector<double> kept;
  const auto contact = std::find(inner.begin(), inner.end(), 0.0);
  if (contact != inner.end() && contact + 1 != inner.end()) {
    kept.push_back(0.0);
    inner.erase(contact);
  }
  if (static_cast<int>(kept.size()) < bands) {
    kept.push_back(inner.back());
    inner.pop_back();
  }
  for (std::size_t k = 0; static_cast<int>(kept.size()) < bands && k < inner.size(); ++k)
    kept.push_back(inner[k]);
  std::sort(kept.begin(), kept.end());
  // A pair that may overlap, reduced to its split at contact, keeps a hair beyond it.
  if (thresholds.front() < 0 && !(kept.back() > 0)) kept.back() = 1e-9 * -thresholds.front();
  thresholds.resize(1);
  thresholds.insert(thresholds.end(), kept.begin(), kept.end());
}

PairThresholds apply_budget(std::vector<std::vector<double>> per_axis,
                            std::vector<double> isotropic, int parameters, const std::string& why) {
  PairThresholds out;
  const int full = band_count(per_axis);
  if (full <= parameters) {
    out.axes = std::move(per_axis);
    return out;
  }
  const int pooled = static_cast<int>(isotropic.size()) - 1;
  keep_bands(isotropic, parameters);
  const int kept = static_cast<int>(isotropic.size()) - 1;
  out.choice = "isotropic, " + std::to_string(kept) + " of " + std::to_string(pooled) +
               " band(s): " + why + " carry " + std::to_string(parameters) + " γ at most (" +
               std::to_string(full) + " wanted along every axis)";
  if (kept == 0) out.choice = "hard core only: " + why + " carry no γ";
  out.axes.push_back(std::move(isotropic));
  return out;
}

std::vector<std::string> prune_neutral_pairs(model::ShapeProcessModel& model, double z) {
  std::vector<std::string> notes;
  for (model::PairInteraction& pair : model.interactions) {
    bool neutral = !pair.axes.empty();
    double largest = 0.0;
    for (const model::AxisParameters& axis : pair.axes) {
      for (std::size_t k = 0; k < axis.gammas.size() && neutral; ++k) {
        const double g = axis.gammas[k], se = axis.gamma_standard_errors[k];
        // On log γ; an estimate whose standard error exceeds the cap says nothing either way (a
        // packed exemplar's flat pseudo-likelihood), so its pair keeps its bands.
        neutral = axis.status[k] == model::ParameterStatus::free && g > 0 && se > 0 &&
                  se / g <= kFitDefaults.neutral_max_log_se && std::abs(std::log(g)) <= z * se / g;
        largest = std::max(largest, std::abs(std::log(g)) / (se / g));
      }
    }
    // An anchor pair's bands say where the anchored category may be: they stay.
    if (!neutral || model.anchors(pair) || pair.axes.front().gammas.empty()) continue;
    reduce_to_hard_core(pair);
    std::ostringstream text;
    text << "hard core only: no γ of the pseudo-likelihood differs from 1 by more than " << z
         << " standard errors (at most " << std::setprecision(2) << largest << ")";
    pair.choice = text.str();
    notes.push_back("pair '" + model.categories[static_cast<std::size_t>(pair.first)].name + "'-'" +
                    model.categories[static_cast<std::size_t>(pair.second)].name +
                    "': " + pair.choice);
  }
  return notes;
}

}  // namespace shapeproc::fit
