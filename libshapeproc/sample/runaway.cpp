#include "libshapeproc/sample/runaway.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::sample {

long long runaway_count(double expected) {
  const double limit = std::max(kRunawayFactor * expected, expected + kRunawayMargin);
  return static_cast<long long>(std::ceil(std::min(limit, 9e18)));
}

std::string strongest_attraction(const model::ShapeProcessModel& model) {
  double strongest = 1.0;
  std::ostringstream text;
  for (const model::PairInteraction& pair : model.interactions) {
    for (std::size_t i = 0; i < pair.axes.size(); ++i) {
      const model::AxisParameters& axis = pair.axes[i];
      for (std::size_t k = 0; k < axis.gammas.size(); ++k) {
        if (!(axis.gammas[k] > strongest)) continue;
        strongest = axis.gammas[k];
        text.str("");
        text << "γ " << axis.gammas[k] << " between '"
             << model.categories[static_cast<std::size_t>(pair.first)].name << "' and '"
             << model.categories[static_cast<std::size_t>(pair.second)].name << "' at distances "
             << axis.thresholds[k] << " to " << axis.thresholds[k + 1];
        if (pair.axes.size() > 1) text << " (axis " << i << ")";
      }
    }
  }
  return text.str();
}

void throw_runaway(const model::ShapeProcessModel& model, long long count, long long limit) {
  std::ostringstream text;
  text << "the chain ran away: " << count << " elements, past " << limit
       << " (the most this output should hold by its expected density); the model condenses "
          "on this domain";
  const std::string cause = strongest_attraction(model);
  if (cause.empty()) {
    text << ": its intensities β are too high for its hard cores; lower them";
  } else {
    text << ", driven by its attraction, strongest " << cause
         << ": refit it, or weaken that γ towards 1";
  }
  throw core::ArgumentError("sample", text.str());
}

}  // namespace shapeproc::sample
