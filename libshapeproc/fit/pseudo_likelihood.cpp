#include "libshapeproc/fit/pseudo_likelihood.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
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

namespace {

// The free parameters (those with data) and θ with them written in at `x`.
struct FreeParameters {
  std::vector<int> index;
  std::vector<double> base;  // θ with the fixed parameters' values
  std::vector<double> full(const std::vector<double>& x) const {
    std::vector<double> theta = base;
    for (std::size_t k = 0; k < index.size(); ++k) theta[static_cast<std::size_t>(index[k])] = x[k];
    return theta;
  }
};

// Parameters with data are free; those whose statistic the quadrature touches but the data do
// not sit on the boundary (γ = 0); the rest are unidentifiable (γ = 1).
std::vector<int> classify_parameters(const PseudoLikelihoodDesign& design, MpleResult& result) {
  const std::size_t p = static_cast<std::size_t>(design.parameter_count);
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
  return free;
}

// Minimises −LPL with L-BFGS and the analytic gradient inside the box [lower, upper]; `x` starts
// at the start values and ends at the best point found (the start again if that is not finite).
// Returns the evaluations.
int minimise_lbfgs(const PseudoLikelihoodDesign& design, const FreeParameters& free,
                   const std::vector<double>& lower, const std::vector<double>& upper,
                   std::vector<double>& x) {
  const std::vector<double> start = x;
  struct Context {
    const PseudoLikelihoodDesign* design;
    const FreeParameters* free;
    int evaluations = 0;
  } context{&design, &free, 0};
  nlopt::opt optimiser(nlopt::LD_LBFGS, static_cast<unsigned>(free.index.size()));
  optimiser.set_lower_bounds(lower);
  optimiser.set_upper_bounds(upper);
  optimiser.set_min_objective(
      [](const std::vector<double>& v, std::vector<double>& grad, void* data) {
        auto* c = static_cast<Context*>(data);
        ++c->evaluations;
        std::vector<double> g;
        const double value =
            log_pseudo_likelihood(*c->design, c->free->full(v), grad.empty() ? nullptr : &g);
        for (std::size_t k = 0; k < grad.size(); ++k)
          grad[k] = -g[static_cast<std::size_t>(c->free->index[k])];
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
    // far, and the Newton steps finish the job on this concave function.
  }
  if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) x = start;
  return context.evaluations;
}

// The free block of a p × p matrix stored by rows.
Eigen::MatrixXd free_block(const std::vector<double>& matrix, const std::vector<int>& free,
                           std::size_t p) {
  const Eigen::Index n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd out(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      out(i, j) = matrix[static_cast<std::size_t>(free[static_cast<std::size_t>(i)]) * p +
                         static_cast<std::size_t>(free[static_cast<std::size_t>(j)])];
  return out;
}

// Newton steps with backtracking on the concave LPL, inside the box. Returns the steps taken.
int newton_polish(const PseudoLikelihoodDesign& design, const FreeParameters& free,
                  const std::vector<double>& lower, const std::vector<double>& upper,
                  std::vector<double>& x) {
  const std::size_t p = static_cast<std::size_t>(design.parameter_count);
  const Eigen::Index n = static_cast<Eigen::Index>(free.index.size());
  int steps = 0;
  for (int step = 0; step < 50; ++step) {
    std::vector<double> gradient, hessian;
    const double value = log_pseudo_likelihood(design, free.full(x), &gradient, &hessian);
    Eigen::VectorXd g(n);
    for (Eigen::Index i = 0; i < n; ++i)
      g[i] = gradient[static_cast<std::size_t>(free.index[static_cast<std::size_t>(i)])];
    const Eigen::MatrixXd h = free_block(hessian, free.index, p);
    const Eigen::LDLT<Eigen::MatrixXd> solver(-h);
    if (solver.info() != Eigen::Success) break;
    const Eigen::VectorXd direction = solver.solve(g);
    if (!direction.allFinite()) break;
    double scale = 1.0;
    std::vector<double> trial(x.size());
    bool improved = false;
    for (int halving = 0; halving < 40; ++halving) {
      for (std::size_t k = 0; k < x.size(); ++k) {
        trial[k] =
            std::clamp(x[k] + scale * direction[static_cast<Eigen::Index>(k)], lower[k], upper[k]);
      }
      const double trial_value = log_pseudo_likelihood(design, free.full(trial));
      if (std::isfinite(trial_value) && trial_value >= value - 1e-12 * std::abs(value)) {
        improved = true;
        break;
      }
      scale *= 0.5;
    }
    if (!improved) break;
    x = trial;
    ++steps;
    if (direction.cwiseAbs().maxCoeff() * scale < 1e-12) break;
  }
  return steps;
}

}  // namespace

MpleResult maximise_pseudo_likelihood(const PseudoLikelihoodDesign& design,
                                      const std::vector<double>& start) {
  const std::size_t p = static_cast<std::size_t>(design.parameter_count);
  MpleResult result;
  result.theta = start;
  result.standard_errors.assign(p, std::numeric_limits<double>::quiet_NaN());
  result.status.assign(p, model::ParameterStatus::free);
  FreeParameters free;
  free.index = classify_parameters(design, result);
  free.base = result.theta;
  std::vector<double> x(free.index.size());
  for (std::size_t k = 0; k < free.index.size(); ++k)
    x[k] = result.theta[static_cast<std::size_t>(free.index[k])];
  if (!free.index.empty()) {
    // Search box: |θ − start| ≤ 30 (γ between e^−30 and e^30 times the start), so that an
    // exemplar whose statistics are separated cannot send the search to infinity.
    std::vector<double> lower(x.size()), upper(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
      lower[k] = x[k] - kBound;
      upper[k] = x[k] + kBound;
    }
    result.evaluations = minimise_lbfgs(design, free, lower, upper, x);
    result.newton_steps = newton_polish(design, free, lower, upper, x);
  }
  // Parameters stuck on the search box have no finite maximum.
  for (std::size_t k = 0; k < free.index.size(); ++k) {
    const double start_value = start[static_cast<std::size_t>(free.index[k])];
    if (std::abs(x[k] - start_value) >= kBound - 1e-6)
      result.status[static_cast<std::size_t>(free.index[k])] = model::ParameterStatus::unbounded;
  }
  result.theta = free.full(x);
  std::vector<double> gradient, hessian;
  result.log_pseudo_likelihood = log_pseudo_likelihood(design, result.theta, &gradient, &hessian);
  if (free.index.empty()) return result;
  const Eigen::Index n = static_cast<Eigen::Index>(free.index.size());
  const Eigen::LDLT<Eigen::MatrixXd> solver(-free_block(hessian, free.index, p));
  if (solver.info() != Eigen::Success) return result;
  const Eigen::MatrixXd covariance = solver.solve(Eigen::MatrixXd::Identity(n, n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const double variance = covariance(i, i);
    if (variance > 0 && std::isfinite(variance))
      result.standard_errors[static_cast<std::size_t>(free.index[static_cast<std::size_t>(i)])] =
          std::sqrt(variance);
  }
  return result;
}

}  // namespace shapeproc::fit
