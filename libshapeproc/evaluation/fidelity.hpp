// Does a fitted model reproduce its exemplar? The fidelity checks, for one exemplar:
//   1. On the exemplar's own window and edge treatment, `chains` chains of the model: the mean of
//   every
//      sufficient statistic (elements per category, pairs per band, elements per shape class)
//      against the exemplar's, in Monte Carlo standard errors of that mean
//      (fit/effective_sample_size.hpp).
//   2. `outputs` outputs of `scale` times each side on a torus, sampled to stationarity: their
//      mean density against the exemplar's with its standard error (one output of an attractive
//      model varies by far more than 10%), their colliding pairs (shape distance 0), and a
//      chi-square test of their pooled shape-class counts against the exemplar's class shares.
// scripts/fidelity.sh runs it over a folder (`shapeproc fidelity`).
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/fit/monte_carlo_moments.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::evaluation {

// The own-window chains by default: 50 of 20,000 steps of burn-in and 20,000 observed every 200.
inline fit::ChainsSetting fidelity_chains() {
  fit::ChainsSetting s;
  s.chains = 50;
  s.burn_in = 20000;
  s.steps = 20000;
  s.observe_every = 200;
  return s;
}

struct FidelityOptions {
  // The own-window chains (check_fidelity sets their fixed elements and free region from the
  // edge treatment).
  fit::ChainsSetting sampling = fidelity_chains();
  double scale = 2.0;  // the output's sides, in exemplar sides
  int outputs = 4;     // independent outputs (chains of run_chains, seeded from sampling.seed)
};

struct StatisticCheck {
  std::string name;
  double exemplar = 0.0, mean = 0.0;
  // What the mean is compared with: the exemplar's value, less the pairs the fit's attraction
  // prior holds back in a band with log γ > 0 (log γ / σ², the penalised likelihood's own
  // target: docs/fit.md, "Attraction prior").
  double target = 0.0;
  // Of the gap between the chains' mean and the exemplar's value: the chains' Monte Carlo error
  // and, for a maximum-likelihood fit, the Monte Carlo error of the fit's own expectations (its
  // estimate is only as precise as its last sample), added in quadrature.
  double standard_error = 0.0;
  double z = 0.0;      // (mean − target) / standard error (0 within fit::kNegligibleGap)
  bool count = false;  // an element count (category or class), not a pair count
};

struct FidelityReport {
  std::vector<StatisticCheck> own_window;
  double worst_count_z = 0.0, worst_pair_z = 0.0;  // largest |z| of each kind
  int penalised = 0;  // bands whose target the attraction prior lowers (all are in the worst)
  int exemplar_elements = 0;
  int outputs = 0;
  double output_elements = 0.0;  // the outputs' mean element count
  // The outputs' mean density over the exemplar's, and the standard error of that mean (0 for
  // one output).
  double density_ratio = 0.0, density_ratio_error = 0.0;
  int exemplar_collisions = 0, output_collisions = 0;  // colliding pairs (all outputs')
  // Chi-square test of the output's class counts against the exemplar's shares (NaN p-value
  // without shape classes).
  double class_chi_square = 0.0, class_p_value = 0.0;
  int class_degrees = 0;
  // Novelty of the outputs against the exemplar (metrics/novelty.hpp), means over the outputs:
  // patch copy share, its chance level, the largest copied patch; whether the exemplar is a
  // lattice (its own repeat its only faithful arrangement) and how many outputs repeat it.
  double patch_copy_share = 0.0, patch_copy_chance = 0.0, largest_copied_patch = 0.0;
  bool lattice_exemplar = false;
  int outputs_repeating = 0;
};

// `boundary` and `edge`: the exemplar's window as the fit used it (a torus for the periodic edge
// treatment; with the border treatment the chains hold the border band's elements fixed).
FidelityReport check_fidelity(const geometry::Scene& exemplar,
                              const model::ShapeProcessModel& model, geometry::Boundary boundary,
                              geometry::EdgeTreatment edge, const FidelityOptions& options);

// Upper tail P(χ²_k ≥ x).
double chi_square_upper_tail(double x, int degrees);

}  // namespace shapeproc::evaluation
