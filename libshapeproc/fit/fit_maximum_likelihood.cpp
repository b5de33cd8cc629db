#include "libshapeproc/fit/fit_maximum_likelihood.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/fit/exemplar_statistics.hpp"
#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/metrics/novelty.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

namespace {
// The tuning constants (fit_defaults.hpp has what each does and why).
constexpr double kStartBound = kFitDefaults.start_bound;
constexpr int kAbandonTorusAfter = kFitDefaults.abandon_torus_after;
constexpr double kCondensedStart = kFitDefaults.condensed_start;
}  // namespace

std::vector<double> observed_statistics(const geometry::Scene& exemplar,
                                        const model::ShapeProcessModel& model) {
  const model::Interaction interaction(model);
  std::vector<double> t(static_cast<std::size_t>(interaction.statistic_count()), 0.0);
  for (const geometry::Element& e : exemplar.elements) {
    t[static_cast<std::size_t>(e.category)] += 1.0;
    if (const int k = interaction.class_statistic(e.shape); k >= 0)
      t[static_cast<std::size_t>(k)] += 1.0;
  }
  for (int p = static_cast<int>(model.categories.size()); p < interaction.parameter_count(); ++p) {
    const model::Interaction::Location where = interaction.locate(p);
    const model::AxisParameters& axis = model.interactions[static_cast<std::size_t>(where.pair)]
                                            .axes[static_cast<std::size_t>(where.axis)];
    t[static_cast<std::size_t>(p)] =
        static_cast<double>(axis.observed_pairs.at(static_cast<std::size_t>(where.band)));
  }
  return t;
}

BorderCondition border_condition(const geometry::Scene& exemplar,
                                 const model::ShapeProcessModel& model) {
  BorderCondition b;
  const FitRegion region =
      fit_region(exemplar, geometry::EdgeTreatment::border, model::Interaction(model).range());
  b.region = region.box;
  for (const geometry::Element& e : exemplar.elements)
    if (!region.contains(e.position)) b.fixed.push_back(e);
  return b;
}

bool packed_exemplar(const model::ShapeProcessModel& mple) {
  for (const model::CategoryParameters& c : mple.categories)
    if (c.beta_status == model::ParameterStatus::unbounded) return true;
  for (const model::PairInteraction& pair : mple.interactions)
    for (const model::AxisParameters& axis : pair.axes)
      for (model::ParameterStatus status : axis.status)
        if (status == model::ParameterStatus::unbounded) return true;
  return false;
}

geometry::Domain stationary_domain(const geometry::Scene& exemplar) {
  return geometry::Domain(exemplar.window, exemplar.dimension, geometry::Boundary::torus);
}

bool fitted_on_stationary_window(const model::ShapeProcessModel& model) {
  return model.fit && model.fit->likelihood && model.fit->likelihood->stationary_window;
}

namespace {

// A note in the fit's record and its notes, first.
void add_first_note(FitResult& fit, const std::string& note) {
  fit.notes.insert(fit.notes.begin(), note);
  if (fit.model.fit) fit.model.fit->notes = fit.notes;
}

// "N iteration(s), S s": what a maximum-likelihood attempt took.
std::string attempt(int iterations, double seconds) {
  return std::to_string(iterations) + " iteration(s), " + core::format_general(seconds, 3) + " s";
}

// An automatic window whose torus did not converge from the pseudo-likelihood's start, or was
// abandoned there (kAbandonTorusAfter, kCondensedStart). A model
// near a phase transition can swing between a sparse and a condensed state on the torus at every
// step (rings: at the pseudo-likelihood's estimate its torus holds 65 elements against 19, and the
// steps swing between |z| 10 and 10⁹ for 30 iterations). The window as drawn converges where the
// torus does not; its estimate is then the start of a second torus fit, nearer than the
// pseudo-likelihood's (rings at seed 1: converged in 7 iterations). That fit is kept when it
// converges, else the window as drawn, each with the reason.
FitResult refit_after_torus_failure(const geometry::Scene& exemplar, const FitOptions& fit_options,
                                    FitResult mple, const MleOptions& options,
                                    const MleResult& failed) {
  MleOptions own = options;
  own.window = WindowModel::own;
  const std::vector<std::string> pseudo_likelihood_notes = mple.notes;
  FitResult drawn = refine_to_maximum_likelihood(exemplar, fit_options, std::move(mple), own);
  MleOptions torus = options;
  torus.window = WindowModel::stationary;
  FitResult start = drawn;
  start.notes = pseudo_likelihood_notes;  // the window as drawn's own notes are not the torus's
  FitResult again = refine_to_maximum_likelihood(exemplar, fit_options, std::move(start), torus);
  model::LikelihoodRecord& estimator = *again.model.fit->likelihood;
  const std::string first =
      "the fit of the window as a piece of a larger drawing (its own torus) " +
      (failed.abandoned.empty() ? std::string("did not converge ")
                                : "was abandoned, " + failed.abandoned + ", ") +
      "from the pseudo-likelihood's estimate (" + attempt(failed.iterations, failed.seconds) + ")";
  if (estimator.converged) {
    again.model.fit->path = model::FitPath::likelihood_stationary_restarted;
    add_first_note(again, first +
                              "; started again from the estimate of the window as drawn, it "
                              "converged (" +
                              std::to_string(estimator.iterations) + " iteration(s))");
    return again;
  }
  add_first_note(drawn, first + ", nor from the estimate of the window as drawn (" +
                            attempt(estimator.iterations, estimator.seconds) +
                            "), so the window was fitted as drawn (no edge treatment); its outputs "
                            "may be denser or sparser than the exemplar near its edges");
  drawn.model.fit->path = model::FitPath::likelihood_own_after_stationary;
  return drawn;
}

}  // namespace

namespace {

// θ indices whose status is `status`.
std::vector<int> indices_with(const MleResult& mle, model::ParameterStatus status) {
  std::vector<int> out;
  for (std::size_t k = 0; k < mle.status.size(); ++k)
    if (mle.status[k] == status) out.push_back(static_cast<int>(k));
  return out;
}

// The notes of the search's outcome: gave up, not converged, statistics unreachable (never
// varied: a jammed exemplar) or held (never moved off the exemplar's: unbounded).
void add_outcome_notes(const MleResult& mle, const MleOptions& options,
                       const model::ShapeProcessModel& start, const std::vector<double>& observed,
                       std::vector<std::string>& notes) {
  if (!mle.converged && !mle.abandoned.empty()) {
    notes.push_back("the maximum-likelihood fit gave up after " + std::to_string(mle.iterations) +
                    " iterations: " + mle.abandoned +
                    "; the model is the iterate closest to the exemplar, and its outputs "
                    "hold fewer elements than the exemplar's density");
  } else if (mle.held_crystal) {
    notes.push_back("the maximum-likelihood fit stopped after " + std::to_string(mle.iterations) +
                    " iterations at an iterate whose expected counts are within the tolerance and "
                    "within 5% of the exemplar's, untested: its chains grow the lattice as a "
                    "crystal and hold it, each worth few independent observations");
  } else if (!mle.converged) {
    notes.push_back("the maximum-likelihood fit did not converge in " +
                    std::to_string(mle.iterations) +
                    " iterations (caps: " + std::to_string(options.max_iterations) +
                    " iterations, " + core::format_number(options.max_seconds) +
                    " s): some expected counts still differ from the exemplar's by more than " +
                    core::format_general(mle.tolerance, 3) + " Monte Carlo standard errors");
  }
  const std::vector<std::string> names = model::statistic_names(start);
  std::string unreachable;
  for (int k : indices_with(mle, model::ParameterStatus::unreachable)) {
    const std::size_t i = static_cast<std::size_t>(k);
    unreachable += (unreachable.empty() ? "" : "; ") + names[i] + ": " +
                   core::format_general(mle.expected[i], 3) + " against " +
                   core::format_general(observed[i], 3);
  }
  if (!unreachable.empty())
    notes.push_back(
        "the chains did not vary these statistics in 4 successive simulations while their "
        "parameters were pushed towards the exemplar's counts (a jammed exemplar), so their "
        "parameters stay at the pseudo-likelihood's start, marked unreachable (the chains' mean "
        "at the returned estimate against the exemplar's count): " +
        unreachable);
  std::string held;
  for (int k : indices_with(mle, model::ParameterStatus::unbounded))
    held += (held.empty() ? "" : ", ") + names[static_cast<std::size_t>(k)];
  if (!held.empty())
    notes.push_back(
        "the chains held these statistics at the exemplar's values in every observation (the "
        "likelihood keeps growing with their parameters, which are marked unbounded and kept "
        "where the chains first held them): " +
        held);
}

// The record of the search: its window, its chains (`chains`, as run), its outcome and its
// goodness of fit.
model::LikelihoodRecord likelihood_record(const MleResult& mle, const MleOptions& options,
                                          const MleOptions& chains, bool stationary,
                                          const std::vector<double>& observed) {
  model::LikelihoodRecord e;
  e.stationary_window = stationary;
  e.burn_in_kind = chains.sampling.burn_in_kind;
  e.unbounded = indices_with(mle, model::ParameterStatus::unbounded);
  e.iterations = mle.iterations;
  e.converged = mle.converged;
  e.chains = options.sampling.chains;
  e.final_chains = mle.chains;
  e.burn_in = chains.sampling.burn_in;
  e.steps = chains.sampling.steps;
  e.observe_every = options.sampling.observe_every;
  e.seed = options.sampling.seed;
  e.attraction_prior_sd = options.attraction_prior_sd;
  for (std::size_t k = 0; k < mle.penalised.size(); ++k)
    if (mle.penalised[k]) e.penalised.push_back(static_cast<int>(k));
  e.unreachable = indices_with(mle, model::ParameterStatus::unreachable);
  e.observed = observed;
  e.expected = mle.expected;
  e.expected_standard_error = mle.expected_error;
  for (std::size_t k = 0; k < observed.size(); ++k) {
    const double se = mle.expected_error.size() > k ? mle.expected_error[k] : 0.0;
    e.z.push_back(se > 0 ? (observed[k] - mle.expected[k]) / se : 0.0);
  }
  e.tolerance = mle.tolerance;
  e.worst_r_hat = std::isfinite(mle.worst_r_hat) ? mle.worst_r_hat : -1.0;
  e.significance = options.significance;
  e.seconds = mle.seconds;
  return e;
}

// The search's chains for the window the fit chose: the stationary window's observed region and
// its abandon rules, the border condition, the compressing burn-in of a packed exemplar. `measure`
// receives the measure of the region the chains sample.
MleOptions chain_options(const geometry::Scene& exemplar, const FitOptions& fit_options,
                         const model::ShapeProcessModel& start, const MleOptions& options,
                         bool stationary, model::BurnIn burn_in, double& measure) {
  MleOptions chains = options;
  measure = geometry::measure(exemplar.window, exemplar.dimension);
  if (stationary) chains.sampling.observe_region = exemplar.window;
  if (stationary && options.window == WindowModel::automatic) {
    chains.abandon_after_diverged = kAbandonTorusAfter;
    chains.abandon_condensed_start = kCondensedStart;
  }
  if (fit_options.edge == geometry::EdgeTreatment::border) {
    const BorderCondition border = border_condition(exemplar, start);
    chains.sampling.fixed = border.fixed;
    chains.sampling.free_region = border.region;
    measure = geometry::measure(border.region, exemplar.dimension);
  }
  chains.sampling.burn_in_kind = burn_in;  // a packed exemplar's chains compress from empty
  return chains;
}

}  // namespace

FitResult refine_to_maximum_likelihood(const geometry::Scene& exemplar,
                                       const FitOptions& fit_options, FitResult mple,
                                       const MleOptions& options) {
  model::ShapeProcessModel start = mple.model;
  const bool open_window = fit_options.boundary == geometry::Boundary::open &&
                           fit_options.edge == geometry::EdgeTreatment::none;
  const bool packed = packed_exemplar(start);
  // A lattice's chains grow it as a crystal from one element, by births at the exemplar's
  // neighbour offsets (every element of a lattice is equivalent: any one is a nucleus), packed or
  // not: random births fill a lattice's sites only by chance.
  const bool crystal = !start.neighbour_offsets.empty() && metrics::is_lattice_exemplar(exemplar);
  const model::BurnIn burn_in = crystal  ? model::BurnIn::crystal
                                : packed ? model::BurnIn::compressing
                                         : model::BurnIn::plain;
  if (crystal && fit_options.near_birth_share == kAutomaticNearBirths)
    start.neighbour_offsets.share = kFitDefaults.crystal_near_birth_share;
  const bool stationary = open_window && (options.window == WindowModel::stationary ||
                                          (options.window == WindowModel::automatic && !packed));
  const geometry::Domain window =
      stationary ? stationary_domain(exemplar)
                 : geometry::Domain(exemplar.window, exemplar.dimension, fit_options.boundary);
  const std::vector<double> observed = observed_statistics(exemplar, start);
  double measure = 0.0;
  const MleOptions chains =
      chain_options(exemplar, fit_options, start, options, stationary, burn_in, measure);
  for (std::size_t c = 0; c < start.categories.size(); ++c) {
    model::CategoryParameters& category = start.categories[c];
    if (category.beta_status != model::ParameterStatus::free) category.beta = observed[c] / measure;
  }
  for (model::PairInteraction& pair : start.interactions) {
    for (model::AxisParameters& axis : pair.axes) {
      for (double& gamma : axis.gammas)
        gamma = std::exp(std::clamp(std::log(gamma), -kStartBound, kStartBound));
    }
  }
  const MleResult mle = maximise_likelihood(start, window, observed, chains);
  if (stationary && !mle.converged && options.window == WindowModel::automatic)
    return refit_after_torus_failure(exemplar, fit_options, std::move(mple), options, mle);
  FitResult result = std::move(mple);
  model::FitRecord record = result.model.fit.value_or(model::FitRecord{});
  result.model = with_estimates(start, mle);
  add_outcome_notes(mle, options, start, observed, result.notes);
  record.likelihood = likelihood_record(mle, options, chains, stationary, observed);
  record.path =
      stationary ? model::FitPath::likelihood_stationary : model::FitPath::likelihood_own_window;
  record.notes = result.notes;
  result.model.fit = std::move(record);
  return result;
}

}  // namespace shapeproc::fit
