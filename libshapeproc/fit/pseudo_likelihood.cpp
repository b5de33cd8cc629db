#include "libshapeproc/fit/pseudo_likelihood.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <nlopt.hpp>
#include <stdexcept>

namespace shapeproc::fit {

namespace {
constexpr double kMinusInfinity = -std::numeric_limits<double>::infinity();
constexpr double kBound = 30.0;
}  // namespace

double log_pseudo_likelihood(const PseudoLikelihoodDesign& design, const std::vector<double>& theta,
                             std::vector<double>* gradient, std::vector<double>* hessian) {
  const std::size_t p = static_cast<std::size_t>(design.parameter_count);
  double value = 0.0;
  for (std::size_t k = 0; k < p; ++k) {
    if (design.data_sum[k] != 0.0) value += design.data_sum[k] * theta[k];
  }
  if (gradient) gradient->assign(design.data_sum.begin(), design.data_sum.end());
  if (hessian) hessian->assign(p * p, 0.0);
  for (const QuadraturePoint& q : design.points) {
    double eta = theta[static_cast<std::size_t>(q.category)];
    for (const auto& [index, count] : q.counts)
      eta += theta[static_cast<std::size_t>(index)] * count;
    if (eta == kMinusInfinity) continue;
    const double mass = q.weight * std::exp(eta);
    value -= mass;
    if (gradient) {
      (*gradient)[static_cast<std::size_t>(q.category)] -= mass;
      for (const auto& [index, count] : q.counts)
        (*gradient)[static_cast<std::size_t>(index)] -= mass * count;
    }
    if (hessian) {
      // t = e_category + Σ count e_index
      std::vector<std::pair<int, double>> t{{q.category, 1.0}};
      for (const auto& [index, count] : q.counts) t.emplace_back(index, static_cast<double>(count));
      for (const auto& [i, ti] : t)
        for (const auto& [j, tj] : t)
          (*hessian)[static_cast<std::size_t>(i) * p + static_cast<std::size_t>(j)] -=
              mass * ti * tj;
    }
  }
  return value;
}

MpleResult maximise_pseudo_likelihood(const PseudoLikelihoodDesign& design,
                                      const std::vector<double>& start) {
  const std::size_t p = static_cast<std::size_t>(design.parameter_count);
  MpleResult result;
  result.theta = start;
  result.standard_errors.assign(p, std::numeric_limits<double>::quiet_NaN());
  result.status.assign(p, model::ParameterStatus::free);

  // Exposure: how much quadrature weight each parameter's statistic touches.
  std::vector<double> exposure(p, 0.0);
  for (const QuadraturePoint& q : design.points) {
    exposure[static_cast<std::size_t>(q.category)] += q.weight;
    for (const auto& [index, count] : q.counts)
      exposure[static_cast<std::size_t>(index)] += q.weight * count;
  }
  std::vector<int> free;
  for (std::size_t k = 0; k < p; ++k) {
    if (design.data_sum[k] > 0.0) {
      free.push_back(static_cast<int>(k));
    } else if (exposure[k] > 0.0) {
      result.status[k] = model::ParameterStatus::boundary;
      result.theta[k] = kMinusInfinity;
    } else {
      result.status[k] = model::ParameterStatus::unidentifiable;
      result.theta[k] = 0.0;
    }
  }

  auto full = [&](const std::vector<double>& x) {
    std::vector<double> theta = result.theta;
    for (std::size_t k = 0; k < free.size(); ++k) theta[static_cast<std::size_t>(free[k])] = x[k];
    return theta;
  };
  std::vector<double> x(free.size());
  for (std::size_t k = 0; k < free.size(); ++k)
    x[k] = result.theta[static_cast<std::size_t>(free[k])];

  if (!free.empty()) {
    // Minimise −LPL with L-BFGS and the analytic gradient.
    struct Context {
      const PseudoLikelihoodDesign* design;
      const std::vector<int>* free;
      std::function<std::vector<double>(const std::vector<double>&)> full;
      int evaluations = 0;
    } context{&design, &free, full, 0};
    // Search box: |θ − start| ≤ 30 (γ between e^−30 and e^30 times the start), so that an
    // exemplar whose statistics are separated cannot send the search to infinity.
    std::vector<double> lower(free.size()), upper(free.size());
    for (std::size_t k = 0; k < free.size(); ++k) {
      lower[k] = x[k] - kBound;
      upper[k] = x[k] + kBound;
    }
    nlopt::opt optimiser(nlopt::LD_LBFGS, static_cast<unsigned>(free.size()));
    optimiser.set_lower_bounds(lower);
    optimiser.set_upper_bounds(upper);
    optimiser.set_min_objective(
        [](const std::vector<double>& v, std::vector<double>& grad, void* data) {
          auto* c = static_cast<Context*>(data);
          ++c->evaluations;
          std::vector<double> g;
          const double value =
              log_pseudo_likelihood(*c->design, c->full(v), grad.empty() ? nullptr : &g);
          for (std::size_t k = 0; k < grad.size(); ++k)
            grad[k] = -g[static_cast<std::size_t>((*c->free)[k])];
          return -value;
        },
        &context);
    optimiser.set_ftol_rel(1e-12);
    optimiser.set_xtol_rel(1e-10);
    optimiser.set_maxeval(2000);
    double minimum = 0.0;
    try {
      optimiser.optimize(x, minimum);
    } catch (const std::runtime_error&) {
      // NLopt stopped early (roundoff limited or a generic failure): x holds its best point so
      // far, and the Newton steps below finish the job on this concave function.
    }
    result.evaluations = context.evaluations;
    if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) {
      for (std::size_t k = 0; k < free.size(); ++k)
        x[k] = result.theta[static_cast<std::size_t>(free[k])];
    }

    // Newton polish with backtracking on the concave LPL.
    const Eigen::Index n = static_cast<Eigen::Index>(free.size());
    for (int step = 0; step < 50; ++step) {
      std::vector<double> gradient, hessian;
      const double value = log_pseudo_likelihood(design, full(x), &gradient, &hessian);
      Eigen::VectorXd g(n);
      Eigen::MatrixXd h(n, n);
      for (Eigen::Index i = 0; i < n; ++i) {
        g[i] = gradient[static_cast<std::size_t>(free[static_cast<std::size_t>(i)])];
        for (Eigen::Index j = 0; j < n; ++j) {
          h(i, j) = hessian[static_cast<std::size_t>(free[static_cast<std::size_t>(i)]) * p +
                            static_cast<std::size_t>(free[static_cast<std::size_t>(j)])];
        }
      }
      const Eigen::LDLT<Eigen::MatrixXd> solver(-h);
      if (solver.info() != Eigen::Success) break;
      const Eigen::VectorXd direction = solver.solve(g);
      if (!direction.allFinite()) break;
      double scale = 1.0;
      std::vector<double> trial(x.size());
      bool improved = false;
      for (int halving = 0; halving < 40; ++halving) {
        for (std::size_t k = 0; k < x.size(); ++k) {
          trial[k] = std::clamp(x[k] + scale * direction[static_cast<Eigen::Index>(k)], lower[k],
                                upper[k]);
        }
        const double trial_value = log_pseudo_likelihood(design, full(trial));
        if (std::isfinite(trial_value) && trial_value >= value - 1e-12 * std::abs(value)) {
          improved = true;
          break;
        }
        scale *= 0.5;
      }
      if (!improved) break;
      x = trial;
      ++result.newton_steps;
      if (direction.cwiseAbs().maxCoeff() * scale < 1e-12) break;
    }
  }

  // Parameters stuck on the search box have no finite maximum.
  for (std::size_t k = 0; k < free.size(); ++k) {
    const double start_value = start[static_cast<std::size_t>(free[k])];
    if (std::abs(x[k] - start_value) >= kBound - 1e-6)
      result.status[static_cast<std::size_t>(free[k])] = model::ParameterStatus::unbounded;
  }
  result.theta = full(x);
  std::vector<double> gradient, hessian;
  result.log_pseudo_likelihood = log_pseudo_likelihood(design, result.theta, &gradient, &hessian);
  if (!free.empty()) {
    const Eigen::Index n = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd information(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        information(i, j) =
            -hessian[static_cast<std::size_t>(free[static_cast<std::size_t>(i)]) * p +
                     static_cast<std::size_t>(free[static_cast<std::size_t>(j)])];
    const Eigen::LDLT<Eigen::MatrixXd> solver(information);
    if (solver.info() == Eigen::Success) {
      const Eigen::MatrixXd covariance = solver.solve(Eigen::MatrixXd::Identity(n, n));
      for (Eigen::Index i = 0; i < n; ++i) {
        const double variance = covariance(i, i);
        if (variance > 0 && std::isfinite(variance)) {
          result.standard_errors[static_cast<std::size_t>(free[static_cast<std::size_t>(i)])] =
              std::sqrt(variance);
        }
      }
    }
  }
  return result;
}

}  // namespace shapeproc::fit
