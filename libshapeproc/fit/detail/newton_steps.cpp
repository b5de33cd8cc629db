#include "libshapeproc/fit/detail/newton_steps.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shapeproc::fit::detail {

Newton::Newton(const std::vector<double>& observed, std::vector<std::size_t> free,
               std::size_t categories, std::size_t parameters, const MleOptions& options)
    : observed_(observed),
      free_(std::move(free)),
      categories_(categories),
      parameters_(parameters),
      options_(options),
      windowed_(!options.sampling.observe_region.isEmpty()) {}

Gap Newton::gap(const StatisticsMoments& m, const std::vector<double>& theta) const {
  const std::size_t p = observed_.size();
  const Eigen::Index n = static_cast<Eigen::Index>(free_.size());
  Gap g{Eigen::VectorXd(n), Eigen::MatrixXd(n, n), 0.0};
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t k = free_[static_cast<std::size_t>(i)];
    g.gap[i] = observed_[k] - m.mean[k];
    for (Eigen::Index j = 0; j < n; ++j)
      g.information(i, j) = m.covariance[k * p + free_[static_cast<std::size_t>(j)]];
    if (penalised(k, theta)) {
      const double precision = 1.0 / (options_.attraction_prior_sd * options_.attraction_prior_sd);
      g.gap[i] -= theta[k] * precision;
      g.information(i, i) += precision;
    }
    const double se = std::max(m.standard_error[k], 1e-9);
    if (std::abs(g.gap[i]) > kNegligibleGap)
      g.worst_z = std::max(g.worst_z, std::abs(g.gap[i]) / se);
  }
  if (windowed_) g.overshoot = overshoot(m);
  return g;
}

// On a stationary window Cov(t_W) understates the derivative J = Cov(t_W, t) of E_θ[t_W] where
// the window's statistics rise with those around it (attraction), and full steps overshoot:
// two-kinds' gaps jumped from |z| 11 to 35, 57 and 10⁹ between simulations. J itself is too
// noisy for the steps (above), but the ratio of its trace to Cov(t_W)'s over the free
// statistics is an average of many and stable; steps are divided by it (at least 1, so that
// inhibition's smaller derivative never lengthens them; at most kMaxOvershoot). A trust region
// on the reweighting's effective size was tried instead: the torus's statistics vary so much
// that, far from the estimate, it allowed steps of 0.004 in θ.
double Newton::overshoot(const StatisticsMoments& m) const {
  const std::size_t p = observed_.size();
  double derivative = 0.0, covariance = 0.0;
  for (std::size_t k : free_) {
    derivative += m.information[k * p + k];
    covariance += m.covariance[k * p + k];
  }
  if (!(covariance > 0.0) || !std::isfinite(derivative)) return 1.0;
  return std::clamp(derivative / covariance, 1.0, kMaxOvershoot);
}

bool Newton::penalised(std::size_t k, const std::vector<double>& theta) const {
  return k >= categories_ && k < parameters_ && options_.attraction_prior_sd > 0 && theta[k] > 0;
}

double Newton::pairs_moved(std::size_t k, const std::vector<double>& theta) const {
  if (!penalised(k, theta)) return 0.0;
  return theta[k] / (options_.attraction_prior_sd * options_.attraction_prior_sd);
}

std::vector<double> Newton::step(const Gap& g, std::vector<double> theta) const {
  const Eigen::Index n = g.gap.size();
  std::vector<Eigen::Index> informed;
  for (Eigen::Index i = 0; i < n; ++i)
    if (g.information(i, i) > kNoInformation) informed.push_back(i);
  const Eigen::Index m = static_cast<Eigen::Index>(informed.size());
  Eigen::MatrixXd information(m, m);
  Eigen::VectorXd gap(m);
  for (Eigen::Index a = 0; a < m; ++a) {
    gap[a] = g.gap[informed[static_cast<std::size_t>(a)]];
    for (Eigen::Index b = 0; b < m; ++b)
      information(a, b) = g.information(informed[static_cast<std::size_t>(a)],
                                        informed[static_cast<std::size_t>(b)]);
  }
  Eigen::VectorXd solved =
      Eigen::LDLT<Eigen::MatrixXd>(information + 1e-9 * Eigen::MatrixXd::Identity(m, m)).solve(gap);
  if (!solved.allFinite()) solved.setZero();
  solved /= g.overshoot;
  Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
  for (Eigen::Index a = 0; a < m; ++a) step[informed[static_cast<std::size_t>(a)]] = solved[a];
  for (Eigen::Index i = 0; i < n; ++i)
    if (g.information(i, i) <= kNoInformation && g.gap[i] != 0)
      step[i] = std::copysign(max_step(), g.gap[i]);
  const double largest = step.cwiseAbs().maxCoeff();
  if (largest > max_step()) step *= max_step() / largest;
  for (Eigen::Index i = 0; i < n; ++i) theta[free_[static_cast<std::size_t>(i)]] += step[i];
  return theta;
}

std::vector<double> Newton::reweighted_steps(const StatisticsMoments& sample, const Gap& at_start,
                                             const std::vector<double>& theta0) const {
  std::vector<double> theta = step(at_start, theta0);
  for (int inner = 1; inner < kReweightedSteps; ++inner) {
    std::vector<double> delta(theta.size(), 0.0);
    for (std::size_t k : free_) delta[k] = theta[k] - theta0[k];
    double share = 1.0;
    const StatisticsMoments here = reweighted(sample, delta, share);
    if (share < kMinEffectiveShare) break;
    const std::vector<double> next = step(gap(here, theta), theta);
    double moved = 0.0;
    for (std::size_t k : free_) moved = std::max(moved, std::abs(next[k] - theta[k]));
    theta = next;
    if (moved < 1e-3) break;
  }
  return theta;
}

void Newton::standard_errors(const Gap& g, const StatisticsMoments& m,
                             std::vector<double>& out) const {
  const Eigen::Index n = g.gap.size();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd inverse =
      Eigen::LDLT<Eigen::MatrixXd>(g.information + 1e-9 * identity).solve(identity);
  if (windowed_) {
    const std::size_t p = observed_.size();
    Eigen::MatrixXd derivative = g.information;  // the penalty's part on the diagonal
    Eigen::MatrixXd spread(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) {
        const std::size_t at =
            free_[static_cast<std::size_t>(i)] * p + free_[static_cast<std::size_t>(j)];
        derivative(i, j) += m.information[at] - m.covariance[at];
        spread(i, j) = m.covariance[at];
      }
    const Eigen::MatrixXd inverse_derivative =
        Eigen::PartialPivLU<Eigen::MatrixXd>(derivative + 1e-9 * identity).solve(identity);
    inverse = inverse_derivative * spread * inverse_derivative.transpose();
  }
  for (Eigen::Index i = 0; i < n; ++i)
    out[free_[static_cast<std::size_t>(i)]] = std::sqrt(std::max(0.0, inverse(i, i)));
}

}  // namespace shapeproc::fit::detail
