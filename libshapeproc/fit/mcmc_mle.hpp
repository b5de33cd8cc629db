// Maximum likelihood by Markov chain Monte Carlo (Penttinen 1984; Geyer & Thompson 1992). The
// shape process is an exponential family in θ = (log β, log γ) with sufficient statistics t(x):
// elements per category and pairs per interaction band (sample/configuration.hpp). Its
// maximum-likelihood estimate solves E_θ[t(X)] = t(z), z the exemplar, so samples of the fitted
// model reproduce the exemplar's counts by construction. Newton steps
//     θ ← θ + Cov_θ[t]⁻¹ (t(z) − E_θ[t]),
// with E_θ[t] and Cov_θ[t] estimated from chains of the project's sampler on the exemplar's
// window, damped so that no component moves by more than `max_step`; the fit stops when every
// free component of t(z) − E_θ[t] is within `tolerance` Monte Carlo standard errors.
// Bands without an observed pair stay at γ = 0 (status boundary); a model without interaction
// parameters has the closed form β_c = n_c / |W|.
//
// This is the estimator's core; its use by `fit --estimator mle` and its validation on the
// shipped exemplars are issue 17's remaining work.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

struct MleOptions {
  int chains = 4;
  int threads = 0;  // 0: one per core
  std::uint64_t seed = 1;
  long long burn_in = 20000;      // steps of each chain before observations count
  long long steps = 100000;       // steps of each chain after the burn-in
  long long observe_every = 100;  // steps between observations of t(x)
  int max_iterations = 30;
  double tolerance = 2.0;  // |t(z) − E_θ[t]| in Monte Carlo standard errors, every component
  double max_step = 1.0;   // largest change of one component of θ per iteration
  // Called after each iteration with its number and the largest |z| of the gaps. May be empty.
  std::function<void(int iteration, double worst_z)> progress;
};

// Monte Carlo moments of t(X) under a model on a domain.
struct StatisticsMoments {
  std::vector<double> mean;
  std::vector<double> standard_error;  // of the mean, from batch means over the chains
  std::vector<double> covariance;      // row-major, parameters x parameters
  int observations = 0;
};

StatisticsMoments statistics_moments(const model::ShapeProcessModel& model,
                                     const geometry::Domain& domain, const MleOptions& options);

struct MleResult {
  std::vector<double> theta;            // by θ index; −∞ for bands on the boundary
  std::vector<double> standard_errors;  // of θ, from the inverse Monte Carlo Fisher information
  std::vector<model::ParameterStatus> status;
  std::vector<double> observed;        // t(z)
  std::vector<double> expected;        // E_θ̂[t] at the last iteration
  std::vector<double> expected_error;  // its Monte Carlo standard error
  int iterations = 0;
  bool converged = false;
};

// The MLE of `model`'s parameters (its thresholds and shapes fixed; its β and γ the start) for
// the observed statistics t(z) on `window`. Throws core::ArgumentError when `observed` has the
// wrong size or a category has no element.
MleResult maximise_likelihood(const model::ShapeProcessModel& model, const geometry::Domain& window,
                              const std::vector<double>& observed, const MleOptions& options);

// The model with θ written into it (β = exp θ_c, γ = exp θ_p), statuses and standard errors.
model::ShapeProcessModel with_estimates(model::ShapeProcessModel model, const MleResult& mle);

}  // namespace shapeproc::fit
