// How a model was fitted: the exemplar it came from, the estimator's settings and outcome, the
// maximum likelihood's goodness-of-fit table, the notes the fit made and the edits made since.
// The fit writes it (fit/fit_shape_process.hpp, fit/fit_maximum_likelihood.hpp), io/model_io
// reads and writes it as the model file's "fit" object, and the sampler, `fidelity`, `report` and
// `show` read it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "libshapeproc/model/burn_in.hpp"

namespace shapeproc::model {

// The pseudo-likelihood's quadrature (fit/detail/quadrature_design.hpp).
struct QuadratureRecord {
  bool lines = false;  // line quadrature; otherwise cells
  long long cells = 0;
  int cells_along_longest_side = 0;
  int shapes_per_location = 0;
  int refinement = 0;
  long long points = 0;  // dummy and data points with λ > 0
  double data_weight = 0.0;
};

// Seconds of the pseudo-likelihood fit's stages.
struct FitSeconds {
  double proxies = 0.0, measurements = 0.0, quadrature = 0.0, optimisation = 0.0;
};

// The path the fit took (fit/fit_exemplar.hpp): which estimator gave the model, on which window.
enum class FitPath {
  // The maximum likelihood was not run (an exemplar over the fit's likelihood_elements, or not
  // asked for): the pseudo-likelihood's estimate, checked on the output's scale.
  pseudo_likelihood,
  // The maximum likelihood on the window as drawn (an edge treatment or window asked for, or a
  // packed exemplar).
  likelihood_own_window,
  // On the stationary window (the exemplar as a piece of a larger drawing), from the
  // pseudo-likelihood's estimate.
  likelihood_stationary,
  // On the stationary window, restarted from the window as drawn's estimate after the first
  // attempt did not converge or was abandoned.
  likelihood_stationary_restarted,
  // Neither stationary attempt converged: the window as drawn's estimate.
  likelihood_own_after_stationary,
};

// "pseudo-likelihood", "likelihood, own window", …: the model file's names.
std::string fit_path_name(FitPath path);
// The path of a name; none for another name.
std::optional<FitPath> parse_fit_path(const std::string& name);

// The maximum-likelihood fit by MCMC (fit/mcmc_mle.hpp): its chains and its outcome. Statistics
// are by θ index (sample/configuration.hpp, Configuration::statistics).
struct LikelihoodRecord {
  // The window fitted as a piece of a larger drawing (its own torus, fit::WindowModel), rather
  // than as drawn.
  bool stationary_window = false;
  // How the chains started from empty (burn_in.hpp); outputs of the model start the same way.
  BurnIn burn_in_kind = BurnIn::plain;
  int iterations = 0;
  bool converged = false;
  int chains = 0;        // of each simulation
  int final_chains = 0;  // of the returned estimate's (more where its sample was too small)
  long long burn_in = 0, steps = 0, observe_every = 0;
  std::uint64_t seed = 0;
  double attraction_prior_sd = 0.0;
  double significance = 0.0;
  double tolerance = 0.0;    // the largest |z| accepted
  double worst_r_hat = 1.0;  // −1 when not finite
  double seconds = 0.0;
  std::vector<int> unbounded, penalised, unreachable;  // θ indices
  // The goodness-of-fit table: t(z), E_θ̂[t], its Monte Carlo standard error, and z.
  std::vector<double> observed, expected, expected_standard_error, z;
};

// The density check on the output's scale (fit/density_calibration.hpp): chains from empty on a
// torus `multiple` times the exemplar's window along each axis, their per-category density against
// the exemplar's, and the corrections made until it agreed.
struct CalibrationRecord {
  double multiple = 2.0;
  int rounds = 0;          // chains run
  bool converged = false;  // the last chain's densities agreed within the tolerance
  bool ran_away = false;   // some chain ran away, and the attraction was shrunk
  std::vector<double> ratio_before,
      ratio_after;                  // per category: the chain's density / the exemplar's
  std::vector<double> beta_factor;  // per category: β multiplied by this
  double attraction_shrink = 1.0;   // every log γ > 0 multiplied by this
  double seconds = 0.0;
};

// An `edit` of the model: the file it was read from, the command line, the edits made.
struct ModelEdit {
  std::string from;
  std::vector<std::string> arguments, edits;
};

struct FitRecord {
  // The exemplar's window (its dimension's coordinates) and its elements (those drawn: not the
  // hidden ones the fit adds, such as clusters' centres).
  std::vector<double> window_min, window_max;
  long long elements = 0;
  std::string edge;  // the edge treatment's name
  FitPath path = FitPath::pseudo_likelihood;
  std::vector<double> quantiles, thresholds;  // the thresholds' rule: one of them is empty
  QuadratureRecord quadrature;
  long long data_points = 0;
  double log_pseudo_likelihood = 0.0;
  std::string optimiser;  // the pseudo-likelihood's optimiser
  int evaluations = 0, newton_steps = 0;
  FitSeconds seconds;
  std::string version;  // of the library that fitted
  std::vector<std::string> notes;
  // The maximum likelihood, when the fit refined to it.
  std::optional<LikelihoodRecord> likelihood;
  // The density check on the output's scale, when the fit ran it.
  std::optional<CalibrationRecord> calibration;
  // The command that fitted: the exemplar's file, its arguments and its options as name and
  // value ("reader.tile", "true"), and the times a tile was repeated for the fit (0: none).
  std::string exemplar;
  std::vector<std::string> arguments;
  std::vector<std::pair<std::string, std::string>> options;
  int tile_repeats = 0;
  std::vector<ModelEdit> edits;

  // Elements per unit area (volume) of the exemplar as fitted, when the record has its window
  // and the model has not been edited since.
  std::optional<double> exemplar_density() const;
};

}  // namespace shapeproc::model
