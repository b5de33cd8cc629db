// Which attractive bands to saturate, and at what s (docs/fit.md, "Saturation"). A pairwise
// attraction that reproduces an exemplar's clusters makes a density that condenses on a larger
// domain (every element gains from every neighbour), and the density check can only weaken it
// until the clusters are gone. A saturated band (model/saturation.hpp; Geyer 1999) lets each
// element gain from at most s neighbours: the same attraction holds a cluster together without
// drawing the whole domain into one.
//
// The fit saturates the bands whose pseudo-likelihood γ is above 1 by more than two standard
// errors, within one layer, and chooses s by profile pseudo-likelihood (as spatstat's profilepl
// chooses Geyer's s): for each candidate (quantiles of the exemplar's own counts per element in
// each band, and s = ∞, which is the pairwise model), the saturated model is fitted on one
// sampled quadrature, and the best candidate is kept when its log pseudo-likelihood beats the
// pairwise one's by at least the gain kFitDefaults.saturation_gain (an Akaike penalty for the
// one more parameter).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/fit/pseudo_likelihood.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

// θ indices of the bands worth saturating: γ above 1 by more than `z` standard errors (or
// unbounded above 1), of a pair within one layer.
std::vector<int> attractive_bands(const model::ShapeProcessModel& model,
                                  const model::Interaction& interaction, double z);

// The candidate saturations, one vector (an s per band of `bands`) per candidate: the
// `quantiles` of the exemplar's own counts in each band over the elements with at least one
// neighbour there (at least 1), distinct candidates only, then s = ∞ (kPairwise) last.
inline constexpr int kPairwise = 1 << 20;
std::vector<std::vector<int>> saturation_candidates(const std::vector<geometry::PairRecord>& pairs,
                                                    const geometry::Scene& exemplar,
                                                    const model::Interaction& interaction,
                                                    const std::vector<int>& bands,
                                                    const std::vector<double>& quantiles);

// Writes `saturations` (one per band of `bands`, located in `interaction`, the model's) into
// the model's axes.
void set_saturations(model::ShapeProcessModel& model, const model::Interaction& interaction,
                     const std::vector<int>& bands, const std::vector<int>& saturations);

struct SaturationChoice {
  bool saturated = false;                      // a finite candidate won
  std::vector<int> saturations;                // the winner's, per band
  std::vector<double> log_pseudo_likelihoods;  // per candidate, in their order
  MpleResult mple;                             // the winner's fit (when saturated)
  std::string note;                            // what was compared and chosen
};

// Profiles the candidates: `fit(model)` fits a model with its saturations set and returns its
// pseudo-likelihood fit on the sampled quadrature.
SaturationChoice choose_saturation(
    const model::ShapeProcessModel& unsaturated, const model::Interaction& interaction,
    const std::vector<int>& bands, const std::vector<std::vector<int>>& candidates, double gain,
    const std::function<MpleResult(const model::ShapeProcessModel&)>& fit);

}  // namespace shapeproc::fit
