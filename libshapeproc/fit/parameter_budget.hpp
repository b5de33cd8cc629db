// As many parameters as the data carry (docs/fit.md, "Parameter budget"). The paper's thresholds
// (quantiles 0, 0.1, 0.2 of every pair's distances, along each axis) give a pair of categories
// axes × bands strengths γ however few elements back them, and reach a fifth of all distances
// however large the exemplar. Both make models that a small sample cannot pin down and that
// condense on a larger domain. The budget bounds both, per pair of categories:
//   - the range ends at most max_range_spacings mean spacings of the pair's denser category
//     (|W| / n)^(1/dim): interactions are a neighbourhood's, not the window's;
//   - the pair has at most ⌊m / pairs_per_parameter⌋ strengths γ, m its exemplar pairs within
//     that range (pairs of rare categories are few). A pair whose axes would need more is pooled
//     over its axes (one isotropic axis); one whose bands would still need more keeps fewer
//     bands, the split at contact (overlap against separation) first; one with no budget
//     interacts through its hard core alone.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

struct ParameterBudget {
  // Exemplar pairs within the range behind each γ.
  int pairs_per_parameter = kFitDefaults.pairs_per_parameter;
  // The longest range, in mean spacings.
  double max_range_spacings = kFitDefaults.max_range_spacings;
};

// What the budget gives one pair: thresholds per axis (one entry: isotropic) and why.
struct PairThresholds {
  std::vector<std::vector<double>> axes;
  std::string choice;  // empty when every axis and band was kept
};

// The largest range of a pair whose denser category has `elements` in a window of measure
// `window` (area or volume) in `dimension` dimensions.
double range_cap(const ParameterBudget& budget, double window, int dimension, double elements);

// Cuts thresholds at `cap`: thresholds beyond it come down to it, and bands left empty go.
void cap_range(std::vector<double>& thresholds, double cap);

// Keeps at most `bands` bands of `thresholds` (δ_0 and a range kept; with a threshold at 0 the
// split at contact kept first); 0 bands leaves the hard core alone.
void keep_bands(std::vector<double>& thresholds, int bands);

// Applies the budget of `parameters` γ to a pair's per-axis thresholds, given the isotropic
// thresholds (from the pair's distances pooled over its axes) to fall back on; `why` says where
// the budget comes from, for the choice's text ("12 pairs within its range").
PairThresholds apply_budget(std::vector<std::vector<double>> per_axis,
                            std::vector<double> isotropic, int parameters, const std::string& why);

// After the pseudo-likelihood: a pair none of whose strengths differs from 1 by more than
// `z` standard errors (on log γ; every one estimated freely, with a standard error of at most
// FitDefaults::neutral_max_log_se) interacts through its hard core alone: its bands carried no
// evidence of attraction or repulsion, and dropping them shortens the range every chain must
// search. Returns a note per pair pruned (also its `choice`).
std::vector<std::string> prune_neutral_pairs(model::ShapeProcessModel& model,
                                             double z = kFitDefaults.neutral_z);

}  // namespace shapeproc::fit
