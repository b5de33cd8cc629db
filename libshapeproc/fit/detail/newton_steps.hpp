// Internal to the maximum-likelihood fit (fit/mcmc_mle.hpp): the damped Newton steps of the
// Monte Carlo MLE over its free components of θ, from a simulation's moments and reweighted to
// nearby θ between simulations (Geyer & Thompson 1992).
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

#include "libshapeproc/fit/mcmc_mle.hpp"
#include "libshapeproc/fit/monte_carlo_moments.hpp"

namespace shapeproc::fit::detail {

inline constexpr int kReweightedSteps = 10;        // Newton steps on one sample at most
inline constexpr double kMinEffectiveShare = 0.5;  // reweighting stops below this effective size
inline constexpr double kNoInformation = 1e-9;  // variance of a statistic the sample never varies
inline constexpr double kMaxOvershoot = 10;     // stationary window: the largest step division

// What one Newton step needs at a point: the penalised gap and information over the free θ.
struct Gap {
  Eigen::VectorXd gap;
  Eigen::MatrixXd information;
  double worst_z = 0.0;
  double overshoot = 1.0;  // steps are divided by this (stationary window: see Newton::gap)
};

class Newton {
 public:
  // `observed` and `options` must outlive the object; `free` lists the free θ indices, the first
  // `categories` θ are log β and those from `parameters` on are shape classes.
  Newton(const std::vector<double>& observed, std::vector<std::size_t> free, std::size_t categories,
         std::size_t parameters, const MleOptions& options);

  std::size_t size() const { return free_.size(); }

  // The gap t(z) − E_θ[t] − ∇ penalty and the information Cov_θ[t] + ∇² penalty at θ. On a
  // stationary window the steps take Cov_θ[t_W] for the derivative Cov_θ(t_W, t) of E_θ[t_W]
  // (a quasi-Newton step: symmetric, and far less noisy than the cross-covariance, which on
  // dots-random took 25 simulations to converge against 12).
  Gap gap(const StatisticsMoments& m, const std::vector<double>& theta) const;

  // Whether the attraction prior acts on θ_k (log γ > 0 of a band).
  bool penalised(std::size_t k, const std::vector<double>& theta) const;
  // The expected pairs the prior takes from the band: log γ / σ² at the optimum.
  double pairs_moved(std::size_t k, const std::vector<double>& theta) const;

  // One damped Newton step from θ. A statistic the sample never varies (a shape class or band
  // the chains did not reach) carries no information: it moves by `max_step` towards its
  // observed value, and the Newton system is solved over the others.
  std::vector<double> step(const Gap& g, std::vector<double> theta) const;

  // Newton steps on the sample drawn at θ₀, reweighted to each new θ, until the steps become
  // small or the reweighted sample's effective size falls below kMinEffectiveShare.
  std::vector<double> reweighted_steps(const StatisticsMoments& sample, const Gap& at_start,
                                       const std::vector<double>& theta0) const;

  // Halves the largest step (after a step that made the gap much worse).
  void shorten_steps() { step_scale_ *= 0.5; }
  double max_step() const { return options_.max_step * step_scale_; }

  // Standard errors of θ̂ from the inverse of the (penalised) information; for a stationary
  // window's estimating equation E_θ[t_W] = t_W(z), the sandwich J⁻¹ Cov(t_W) J⁻ᵀ with the
  // derivative J = Cov(t_W, t) (+ the penalty's) of the sample `m`.
  void standard_errors(const Gap& g, const StatisticsMoments& m, std::vector<double>& out) const;

 private:
  // On a stationary window, the division of the steps (Gap::overshoot).
  double overshoot(const StatisticsMoments& m) const;

  const std::vector<double>& observed_;
  std::vector<std::size_t> free_;
  std::size_t categories_;
  std::size_t parameters_;  // θ indices from here on are shape classes
  const MleOptions& options_;
  bool windowed_;
  double step_scale_ = 1.0;
};

}  // namespace shapeproc::fit::detail
