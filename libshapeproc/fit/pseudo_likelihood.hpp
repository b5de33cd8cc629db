// The log pseudo-likelihood of a pairwise-interaction process with quadrature
// (docs/mathematics.md, "Maximum pseudo-likelihood"; Baddeley & Turner 2000):
//   LPL(θ) = Σ_n θ·t(z_n) − Σ_j w_j exp(θ·t(q_j)),
// concave in θ, with gradient Σ_n t(z_n) − Σ_j w_j λ_j t_j and Hessian −Σ_j w_j λ_j t_j t_jᵀ.
#pragma once

#include <utility>
#include <vector>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

struct QuadraturePoint {
  double weight = 0.0;
  int category = 0;                         // θ[category] = log β_category
  std::vector<std::pair<int, int>> counts;  // (θ index, count) of the interaction part
};

struct PseudoLikelihoodDesign {
  int parameter_count = 0;
  std::vector<double> data_sum;         // Σ_n t(z_n), betas included (data points per category)
  std::vector<QuadraturePoint> points;  // quadrature points with λ > 0 (hard-core ones removed)
};

struct MpleResult {
  std::vector<double> theta;            // −∞ for parameters on the boundary
  std::vector<double> standard_errors;  // of θ (log scale); NaN where not estimated
  std::vector<model::ParameterStatus> status;
  double log_pseudo_likelihood = 0.0;
  int evaluations = 0;  // NLopt evaluations
  int newton_steps = 0;
};

// LPL at θ, with its gradient and Hessian when asked for (over all parameters; entries of θ
// that are −∞ make their points vanish).
double log_pseudo_likelihood(const PseudoLikelihoodDesign& design, const std::vector<double>& theta,
                             std::vector<double>* gradient = nullptr,
                             std::vector<double>* hessian = nullptr);

// Maximises the LPL: parameters with no data but some exposure are on the boundary (θ = −∞,
// γ = 0), parameters with neither are unidentifiable (θ = 0, γ = 1); the others are found by
// NLopt's L-BFGS on the analytic gradient, then polished by Newton steps. Standard errors from
// the inverse of minus the Hessian over the free parameters.
MpleResult maximise_pseudo_likelihood(const PseudoLikelihoodDesign& design,
                                      const std::vector<double>& start);

}  // namespace shapeproc::fit
