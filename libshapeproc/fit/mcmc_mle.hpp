// Maximum likelihood by Markov chain Monte Carlo (Penttinen 1984; Geyer & Thompson 1992). The
// shape process is an exponential family in θ = (log β, log γ) with sufficient statistics t(x):
// elements per category and pairs per interaction band (sample/configuration.hpp). Its
// maximum-likelihood estimate solves E_θ[t(X)] = t(z), z the exemplar, so samples of the fitted
// model reproduce the exemplar's counts by construction. Newton steps
//     θ ← θ + Cov_θ[t]⁻¹ (t(z) − E_θ[t]),
// with E_θ[t] and Cov_θ[t] estimated from chains of the project's sampler on the exemplar's
// window (monte_carlo_moments.hpp), damped so that no component moves by more than `max_step`.
// Between simulations the Newton steps continue on the last sample reweighted to the new θ while
// its effective size stays above half (Geyer & Thompson 1992), so a simulation serves several
// steps. The first simulations are short (a quarter of the steps) until the gaps are within the
// tolerance at their precision; the fit stops when no free component of t(z) − E_θ[t] differs
// significantly from 0 in a full-length simulation (MleOptions::significance) whose sample is
// worth at least 20 independent observations of each statistic (effective_sample_size.hpp; a
// smaller one is drawn again at the same θ with proportionally more chains). The estimate is
// then the maximum of the likelihood that this last sample approximates by reweighting (its
// expectations reweighted to it), unless the reweighting leaves too small an effective sample.
// Bands without an observed pair stay at γ = 0 (status boundary); a model without interaction
// parameters has the closed form β_c = n_c / |W|.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/fit/monte_carlo_moments.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

// A gap between an expected count and its target of at most this (a tenth of an element or
// pair) counts as matched, whatever its Monte Carlo error: a packed lattice's chains lose an
// element once in a long while, so that more chains shrink the error faster than the gap, which
// only an infinite parameter closes. `fidelity` judges its checks by the same rule.
inline constexpr double kNegligibleGap = 0.1;

// What one iteration of the fit reports.
struct MleProgress {
  int iteration = 0;
  double worst_z = 0.0;  // the largest |z| of the gaps
  // The smallest effective sample size of a free statistic (effective_sample_size.hpp).
  double effective_size = 0.0;
  int chains = 0;        // the simulation's chains
  double seconds = 0.0;  // since this fit began
};

// The model an open window (edge treatment none) is fitted as (docs/fit.md, "Stationary window").
enum class WindowModel {
  // The drawing cut at its edges: the chains sample the open window, and E_θ[t(X)] = t(z).
  own,
  // A piece of a larger drawing: the chains sample the window's own torus and the estimate
  // solves E_θ[t_W(X)] = t(z) for the statistics t_W of the window's pairs, those that do not
  // meet across the torus's seam (fit::stationary_domain).
  stationary,
  // stationary, except for a packed exemplar (its chains compress from empty): own. The default, as
  // for
  // the command line's --edge auto.
  automatic,
};

struct MleOptions {
  ChainsSetting sampling;  // the chains of each iteration
  int max_iterations = 30;
  // The fit has converged when no component of t(z) − E_θ[t] differs from 0 at this level,
  // judged on its Monte Carlo standard error, two-sided and Bonferroni-corrected over the free
  // components (5%: |z| ≤ 1.96 for one component, ≤ 3.2 for 33): a rule on the largest of
  // many |z| that a fit exactly at the MLE passes with probability 1 − significance.
  double significance = 0.05;
  double max_step = 1.0;  // largest change of one component of θ per Newton step
  // Standard deviation σ of the half-normal prior on attraction: log γ > 0 costs
  // (log γ)² / (2σ²) in the log-likelihood, so that a band with a handful of pairs cannot fit
  // strong attraction; 0 = no penalty. Inhibition (log γ < 0) is not penalised.
  double attraction_prior_sd = 1.5;
  double max_seconds = 600.0;  // the fit stops (not converged) after the iteration that passes it
  // The fit gives up (not converged, MleResult::abandoned) at this many diverged steps (steps
  // undone by the step control: the gap ten times the best iterate's), 0 = never. A start from
  // which the steps keep throwing the chains between a sparse and a condensed state (a model
  // near a phase transition) is then left for a better one (fit_maximum_likelihood.cpp).
  int abandon_after_diverged = 0;
  // The fit gives up at its first simulation when that holds more than this many times the
  // exemplar's elements of some category (a start in the condensed state of a model near a phase
  // transition), 0 = never.
  double abandon_condensed_start = 0.0;
  // Which model of an open window without border correction is fitted (WindowModel).
  WindowModel window = WindowModel::automatic;
  // Called after each iteration (MleProgress). May be empty.
  std::function<void(const MleProgress&)> progress;
};

struct MleResult {
  // By θ index; −∞ for bands on the boundary. Without convergence: the iterate whose
  // expectations came closest to the exemplar's statistics (smallest largest |z|).
  std::vector<double> theta;
  std::vector<double> standard_errors;  // of θ, from the inverse Monte Carlo Fisher information
  std::vector<model::ParameterStatus> status;
  std::vector<double> observed;        // t(z)
  std::vector<double> expected;        // E_θ̂[t] at the last iteration
  std::vector<double> expected_error;  // its Monte Carlo standard error
  double tolerance = 0.0;              // the largest |z| accepted (convergence_tolerance)
  // θ indices where the attraction prior holds the band's expected pairs half a pair or more
  // below the exemplar's count.
  std::vector<bool> penalised;
  // The largest R-hat over the free statistics at the returned estimate (monte_carlo_moments.hpp):
  // convergence also needs the setting's chains to agree (at most kMaxRHat), not those of a
  // sample grown to more (its disagreement is in its effective size).
  double worst_r_hat = 1.0;
  // The chains of the returned estimate's sample: the setting's, or more where a sample was worth
  // too few independent observations.
  int chains = 0;
  double seconds = 0.0;
  int iterations = 0;
  bool converged = false;
  // Why the fit gave up (MleOptions::abandon_after_diverged, abandon_condensed_start); empty
  // when it did not.
  std::string abandoned;
  // The chains grow a crystal (ChainsSetting::crystal) and hold it, each worth few
  // observations: the search stopped, not converged, at its first iterate within the tolerance
  // whose expected counts are all within 5% of the exemplar's, which more chains would only test
  // at many times the cost.
  bool held_crystal = false;
};

// The MLE of `model`'s parameters (its thresholds and shapes fixed; its β and γ the start) for
// the observed statistics t(z) on `window`. Throws core::ArgumentError when `observed` has the
// wrong size or a category has no element.
// The |z| up to which the largest of `components` gaps counts as Monte Carlo noise at level
// `significance`: the two-sided normal quantile at significance / components.
double convergence_tolerance(double significance, std::size_t components);

MleResult maximise_likelihood(const model::ShapeProcessModel& model, const geometry::Domain& window,
                              const std::vector<double>& observed, const MleOptions& options);

// The model with θ written into it (β = exp θ_c, γ = exp θ_p), statuses and standard errors.
model::ShapeProcessModel with_estimates(model::ShapeProcessModel model, const MleResult& mle);

}  // namespace shapeproc::fit
