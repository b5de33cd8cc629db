// The Monte Carlo standard error of a mean over several Markov chains, from their effective
// sample size (Geyer 1992; the multi-chain form of Vehtari, Gelman, Simpson, Carpenter and
// Bürkner 2021). The autocorrelation ρ_t at lag t combines every chain's autocovariance with the
// chains' disagreement,
//     ρ_t = 1 − (W − mean_j γ_j(t)) / var⁺,   var⁺ = (n − 1)/n W + B/n,
// W the mean within-chain variance, B/n the variance of the chain means, γ_j(t) chain j's
// autocovariance; Geyer's initial positive sequence sums the pairs ρ_2k + ρ_2k+1 while they are
// positive (made monotone), τ = −1 + 2 Σ pairs, and the m chains of n observations count as
// m n / τ independent ones.
//
// Batch means with five batches per chain, used before, assume batches longer than the
// autocorrelation: on dashes-rows' packed lattice (autocorrelation 0.2–0.4 at half a batch) their
// errors were 1.3–2.3 times too small (benchmarks/mc_error_study.cpp), so the fit's test rejected
// at its own estimate and wandered until its iteration cap.
#pragma once

#include <utility>
#include <vector>

namespace shapeproc::fit {

struct EffectiveSize {
  double variance = 0.0;         // var⁺ of one observation
  double autocorrelation = 1.0;  // τ: observations per independent one
  double effective = 0.0;        // m n / τ
  double standard_error = 0.0;   // of the mean of all observations: √(var⁺ / effective)
};

// Of column k of `samples`, a row-major observations × p matrix whose chains are the row ranges
// [first, last) of `chains` (chains of unequal length: each keeps its own mean and variance, the
// lags run over the shortest).
EffectiveSize effective_size(const std::vector<double>& samples, int p, int k,
                             const std::vector<std::pair<int, int>>& chains);

}  // namespace shapeproc::fit
