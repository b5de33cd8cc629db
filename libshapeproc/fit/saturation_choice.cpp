#include "libshapeproc/fit/saturation_choice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libshapeproc/core/format.hpp"
#include "libshapeproc/fit/quantile.hpp"

namespace shapeproc::fit {

std::vector<int> attractive_bands(const model::ShapeProcessModel& model,
                                  const model::Interaction& interaction, double z) {
  std::vector<int> out;
  for (int p = interaction.category_count(); p < interaction.parameter_count(); ++p) {
    const model::Interaction::Location where = interaction.locate(p);
    const model::PairInteraction& pair = model.interactions[static_cast<std::size_t>(where.pair)];
    if (interaction.layer(pair.first) != interaction.layer(pair.second)) continue;
    const model::AxisParameters& axis = pair.axes[static_cast<std::size_t>(where.axis)];
    const std::size_t k = static_cast<std::size_t>(where.band);
    const double log_gamma = std::log(axis.gammas[k]);
    const double se = k < axis.gamma_standard_errors.size() ? axis.gamma_standard_errors[k] : NAN;
    const model::ParameterStatus status =
        k < axis.status.size() ? axis.status[k] : model::ParameterStatus::fixed;
    // The standard error is of γ: on log γ it is se / γ.
    const bool significant = status == model::ParameterStatus::unbounded ||
                             (status == model::ParameterStatus::free && std::isfinite(se) &&
                              log_gamma > z * se / axis.gammas[k]);
    if (log_gamma > 0 && significant) out.push_back(p);
  }
  return out;
}

std::vector<std::vector<int>> saturation_candidates(const std::vector<geometry::PairRecord>& pairs,
                                                    const geometry::Scene& exemplar,
                                                    const model::Interaction& interaction,
                                                    const std::vector<int>& bands,
                                                    const std::vector<double>& quantiles) {
  // Own counts per element in each band.
  std::vector<std::vector<int>> own(bands.size(), std::vector<int>(exemplar.elements.size(), 0));
  for (const geometry::PairRecord& p : pairs) {
    const geometry::Element& a = exemplar.elements[static_cast<std::size_t>(p.i)];
    const geometry::Element& b = exemplar.elements[static_cast<std::size_t>(p.j)];
    const int band =
        interaction.band(a.category, b.category, p.measurement.axis, p.measurement.distance);
    if (band < 0) continue;
    const int parameter = interaction.parameter(a.category, b.category, p.measurement.axis, band);
    const auto at = std::find(bands.begin(), bands.end(), parameter);
    if (at == bands.end()) continue;
    std::vector<int>& counts = own[static_cast<std::size_t>(at - bands.begin())];
    ++counts[static_cast<std::size_t>(p.i)];
    ++counts[static_cast<std::size_t>(p.j)];
  }
  std::vector<std::vector<int>> out;
  for (double q : quantiles) {
    std::vector<int> candidate;
    for (const std::vector<int>& counts : own) {
      std::vector<double> positive;
      for (int c : counts)
        if (c > 0) positive.push_back(c);
      std::sort(positive.begin(), positive.end());
      candidate.push_back(
          positive.empty() ? 1 : std::max(1, static_cast<int>(std::lround(quantile(positive, q)))));
    }
    if (std::find(out.begin(), out.end(), candidate) == out.end()) out.push_back(candidate);
  }
  out.emplace_back(bands.size(), kPairwise);
  return out;
}

void set_saturations(model::ShapeProcessModel& model, const model::Interaction& interaction,
                     const std::vector<int>& bands, const std::vector<int>& saturations) {
  for (std::size_t b = 0; b < bands.size(); ++b) {
    const model::Interaction::Location where = interaction.locate(bands[b]);
    model::AxisParameters& axis = model.interactions[static_cast<std::size_t>(where.pair)]
                                      .axes[static_cast<std::size_t>(where.axis)];
    axis.saturations.resize(axis.gammas.size(), 0);
    axis.saturations[static_cast<std::size_t>(where.band)] = saturations[b];
  }
}

SaturationChoice choose_saturation(
    const model::ShapeProcessModel& unsaturated, const model::Interaction& interaction,
    const std::vector<int>& bands, const std::vector<std::vector<int>>& candidates, double gain,
    const std::function<MpleResult(const model::ShapeProcessModel&)>& fit) {
  SaturationChoice choice;
  std::vector<MpleResult> fits;
  for (const std::vector<int>& candidate : candidates) {
    model::ShapeProcessModel model = unsaturated;
    set_saturations(model, interaction, bands, candidate);
    fits.push_back(fit(model));
    choice.log_pseudo_likelihoods.push_back(fits.back().log_pseudo_likelihood);
  }
  const std::vector<double>& lpl = choice.log_pseudo_likelihoods;
  // The pairwise candidate is last; the best finite one must beat it by the gain.
  std::size_t best = 0;
  for (std::size_t c = 1; c + 1 < candidates.size(); ++c)
    if (lpl[c] > lpl[best]) best = c;
  const double pairwise = lpl.back();
  choice.saturated = candidates.size() > 1 && lpl[best] >= pairwise + gain;
  std::ostringstream note;
  note << "saturation of " << bands.size() << " attractive band(s), profile pseudo-likelihood: ";
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    note << (c ? ", " : "") << "s = ";
    if (candidates[c].front() == kPairwise) {
      note << "none";
    } else {
      for (std::size_t b = 0; b < candidates[c].size(); ++b)
        note << (b ? "/" : "") << candidates[c][b];
    }
    note << " " << core::format_general(lpl[c], 6);
  }
  note << (choice.saturated ? "; saturated"
                            : "; kept pairwise (no gain of " + core::format_general(gain, 3) + ")");
  choice.note = note.str();
  if (choice.saturated) {
    choice.saturations = candidates[best];
    choice.mple = std::move(fits[best]);
  }
  return choice;
}

}  // namespace shapeproc::fit
