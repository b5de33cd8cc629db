#include "libshapeproc/fit/density_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/fit/effective_sample_size.hpp"
#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace shapeproc::fit {

namespace {

constexpr double kLargestStep = kFitDefaults.calibration_largest_step;
constexpr double kLeastElasticity = kFitDefaults.calibration_least_elasticity;
// Observations a chain's mean needs for its own Monte Carlo error to be estimated.
constexpr std::size_t kLeastObservations = 20;

// The torus of `multiple` windows along x and y, at the window's origin. A 3D exemplar keeps its
// depth: it is a layer (pebbles on the ground), and its outputs extend it sideways; a torus of
// twice its depth would let its elements stack as no output does.
geometry::Domain calibration_domain(const geometry::Scene& exemplar, double multiple) {
  geometry::Box3 box = exemplar.window;
  box.max().head<2>() = box.min().head<2>() + multiple * exemplar.window.sizes().head<2>();
  return geometry::Domain(box, exemplar.dimension, geometry::Boundary::torus);
}

struct Chain {
  bool ran_away = false;
  std::vector<double> ratio;    // per category (an anchored category's: per base)
  std::vector<double> overall;  // per category: its count over the expected, bases or not
  std::vector<double> allowed;  // per category: the largest |ratio − 1| that agrees
};

// The chain agrees on a category within the tolerance or within two Monte Carlo standard errors
// of its mean count (from its observations' effective sample size; two Poisson standard errors
// of a single state when it has too few observations).
double allowed_error(const std::vector<std::vector<double>>& observations, std::size_t first,
                     std::size_t end, std::size_t c, double expected, double tolerance) {
  if (end - first < kLeastObservations)
    return std::max(tolerance, 2.0 / std::sqrt(std::max(1.0, expected)));
  std::vector<double> column;
  for (std::size_t i = first; i < end; ++i) column.push_back(observations[i][c]);
  const EffectiveSize size = effective_size(column, 1, 0, {{0, static_cast<int>(column.size())}});
  return std::max(tolerance, 2.0 * size.standard_error / std::max(1.0, expected));
}

// `geometry`: the proxies of the model's shapes on `domain`, built once for every chain (the
// check changes β and γ, never the shapes or thresholds). The ratio is the chain's mean count per
// category over the second half of its run, after any burn-in, to the expected count: a time
// average, far less noisy than the last state, so the chain stops once its count is stationary
// (no run-on).
Chain run_chain(const model::ShapeProcessModel& model, const geometry::Domain& domain,
                const std::shared_ptr<const sample::ChainGeometry>& geometry,
                const std::vector<double>& expected, double exemplar_density, double tolerance,
                std::uint64_t seed, int threads) {
  OutputSampling sampling;
  sampling.exemplar_density = exemplar_density;
  sampling.threads = threads;
  sample::SamplerOptions options = output_sampler_options(model, domain, sampling);
  options.geometry = geometry;
  options.run_on = false;
  // About one observation per element's worth of steps, of each layer's own elements: a layer
  // of a few large elements is observed as often as it changes.
  std::vector<double> layer_total(static_cast<std::size_t>(model.layer_count()), 0.0);
  for (std::size_t c = 0; c < expected.size(); ++c)
    layer_total[static_cast<std::size_t>(model.categories[c].layer)] += expected[c];
  const auto every = [](double total) {
    return std::max<long long>(10, static_cast<long long>(total));
  };
  double total = 0.0;
  for (double t : layer_total) {
    total += t;
    options.layer_observe_every.push_back(every(t));
  }
  options.observe_every = every(total);
  const sample::ShapeProcessSampler sampler(model, domain, options);
  core::Random random(seed);
  Chain chain;
  sample::SampleResult result;
  try {
    result = sampler.sample(random);
  } catch (const core::ArgumentError&) {
    chain.ran_away = true;  // the runaway stop: the only refusal a valid model's chain makes
    return chain;
  }
  // Each category's mean over the second half of its own chain: the whole run's (after any
  // burn-in), or a layered model's chain of its layer.
  const std::size_t n = result.observations.size();
  std::vector<double> last(expected.size(), 0.0);  // the final state's counts
  for (const std::vector<geometry::Element>* elements : {&result.scene.elements, &result.hidden})
    for (const geometry::Element& e : *elements) last[static_cast<std::size_t>(e.category)] += 1.0;
  std::vector<double> counts = last;  // a run too short to observe keeps its last state
  for (std::size_t c = 0; c < expected.size(); ++c) {
    std::size_t first = std::max<std::size_t>(
        n / 2, static_cast<std::size_t>(result.compression_steps / options.observe_every));
    std::size_t end = n;
    if (!result.layer_observations.empty()) {
      const auto layer = static_cast<std::size_t>(model.categories[c].layer);
      const std::size_t start = result.layer_observations[layer];
      end = layer + 1 < result.layer_observations.size() ? result.layer_observations[layer + 1] : n;
      first = start + (end - start) / 2;
    }
    chain.allowed.push_back(
        allowed_error(result.observations, first, end, c, expected[c], tolerance));
    if (end <= first) continue;
    double sum = 0.0;
    for (std::size_t i = first; i < end; ++i) sum += result.observations[i][c];
    counts[c] = sum / static_cast<double>(end - first);
  }
  for (std::size_t c = 0; c < expected.size(); ++c) chain.ratio.push_back(counts[c] / expected[c]);
  chain.overall = chain.ratio;
  // An anchored category's count follows its bases': its ratio is per base of those its chain
  // held (its β sets how many each base carries; the bases' own β, how many bases there are).
  for (std::size_t c = 0; c < expected.size(); ++c)
    if (const int anchor = model.categories[c].anchor; anchor >= 0) {
      const double bases =
          last[static_cast<std::size_t>(anchor)] / expected[static_cast<std::size_t>(anchor)];
      chain.ratio[c] = bases > 0 ? chain.ratio[c] / bases : 0.0;
    }
  return chain;
}

bool category_agrees(const Chain& chain, std::size_t c) {
  return std::abs(chain.ratio[c] - 1.0) <= chain.allowed[c];
}

bool overall_agrees(const Chain& chain, std::size_t c) {
  return std::abs(chain.overall[c] - 1.0) <= chain.allowed[c];
}

bool agrees(const Chain& chain) {
  for (std::size_t c = 0; c < chain.ratio.size(); ++c)
    if (!category_agrees(chain, c) || !overall_agrees(chain, c)) return false;
  return true;
}

// Whether category c's β steps: its ratio is off; or it is anchored, or the base of one, whose
// count is off overall although its own ratio and its base's agree (two errors within the
// tolerance, of one sign, compound: bases ×0.93 carrying ×0.94 per base are ×0.87 overall).
bool steps(const model::ShapeProcessModel& model, const Chain& chain, std::size_t c) {
  if (!category_agrees(chain, c)) return true;
  for (std::size_t a = 0; a < model.categories.size(); ++a) {
    const int anchor = model.categories[a].anchor;
    if (anchor >= 0 && (a == c || static_cast<std::size_t>(anchor) == c) &&
        !overall_agrees(chain, a))
      return true;
  }
  return false;
}

// A β step and the chain's ratios before it.
struct Step {
  std::vector<double> beta, ratio;
};

// An anchor pair's γ > 1 place the anchored category on its base (category_layers.hpp); they are
// not an attraction that condenses, and shrinking them would strip the bases of what they carry.
bool has_attraction(const model::ShapeProcessModel& model) {
  for (const model::PairInteraction& pair : model.interactions)
    if (!model.anchors(pair))
      for (const model::AxisParameters& axis : pair.axes)
        for (double g : axis.gammas)
          if (g > 1.0) return true;
  return false;
}

// Whether the densities are too high and β does not bring them down: every category over the
// tolerance whose β the last step lowered moved by less than kLeastElasticity of that step (in
// log), as counts that the attraction holds up do (amacrine: β × 0.26 took 2.6 times the
// exemplar's count to 1.97 times it). The attraction is then what is wrong.
bool held_by_attraction(const model::ShapeProcessModel& model, const Step& previous,
                        const Chain& chain) {
  if (previous.beta.empty() || !has_attraction(model)) return false;
  const std::vector<double>& ratio = chain.ratio;
  bool over = false;
  for (std::size_t c = 0; c < ratio.size(); ++c) {
    if (ratio[c] <= 1.0 || category_agrees(chain, c)) continue;
    over = true;
    const double step = std::log(previous.beta[c] / model.categories[c].beta);
    if (!(step > 0) || !(previous.ratio[c] > 0) || !(ratio[c] > 0)) return false;
    if (std::log(previous.ratio[c] / ratio[c]) >= kLeastElasticity * step) return false;
  }
  return over;
}

// Every log γ > 0 times `factor`: of the pairs that are not anchors, or, with `anchors_too`
// (a chain that ran away with no other attraction), of every pair.
void shrink_attraction(model::ShapeProcessModel& model, double factor, bool anchors_too = false) {
  for (model::PairInteraction& pair : model.interactions)
    if (anchors_too || !model.anchors(pair))
      for (model::AxisParameters& axis : pair.axes)
        for (double& g : axis.gammas)
          if (g > 1.0) g = std::exp(factor * std::log(g));
}

}  // namespace

model::CalibrationRecord calibrate_density(model::ShapeProcessModel& model,
                                           const geometry::Scene& exemplar,
                                           const CalibrationOptions& options) {
  const core::Stopwatch clock;
  model::CalibrationRecord record;
  record.multiple = options.multiple;
  const std::size_t categories = model.categories.size();
  record.beta_factor.assign(categories, 1.0);
  const geometry::Domain domain = calibration_domain(exemplar, options.multiple);
  const double scale = options.multiple * options.multiple;
  std::vector<double> expected(categories, 0.0);
  for (const geometry::Element& e : exemplar.elements)
    expected[static_cast<std::size_t>(e.category)] += scale;
  const double density = static_cast<double>(exemplar.elements.size()) / exemplar.window_measure();
  // A β the pseudo-likelihood could not bound follows its quadrature's data share, not the data
  // (1e-15 for trees that no location of a grassy window could take): the chains start it at
  // the category's density, as the maximum likelihood does. An anchored category's β is not
  // free of its anchor bands' γ (every element of it has one such band, so only their product is
  // fitted): it keeps its estimate.
  for (std::size_t c = 0; c < categories; ++c) {
    model::CategoryParameters& category = model.categories[c];
    if (category.beta_status != model::ParameterStatus::unbounded || category.anchor >= 0) continue;
    const double start = expected[c] / scale / exemplar.window_measure();
    record.beta_factor[c] = start / category.beta;
    category.beta = start;
  }
  const auto geometry =
      std::make_shared<const sample::ChainGeometry>(model, model::Interaction(model), domain);
  double best_worst = std::numeric_limits<double>::infinity();
  model::ShapeProcessModel best = model;
  std::vector<double> low(categories, 0.0),
      high(categories, std::numeric_limits<double>::infinity());  // β brackets
  Step previous;  // the last β step, to tell a density β moves from one the interaction holds
  for (int round = 1; round <= options.rounds; ++round) {
    if (options.progress) options.progress(round, options.rounds);
    const Chain chain =
        run_chain(model, domain, geometry, expected, density, options.tolerance,
                  options.seed + static_cast<std::uint64_t>(round - 1), options.threads);
    record.rounds = round;
    if (chain.ran_away) {
      record.ran_away = true;
      record.attraction_shrink *= 0.5;
      shrink_attraction(model, 0.5, !has_attraction(model));
      continue;
    }
    if (record.ratio_before.empty()) record.ratio_before = chain.ratio;
    if (agrees(chain)) {
      record.ratio_after = chain.ratio;
      record.converged = true;
      break;
    }
    // The closest agreement yet (its worst category's), which a check that never agrees keeps.
    double worst = 0.0;
    for (const std::vector<double>* ratios : {&chain.ratio, &chain.overall})
      for (double r : *ratios) worst = std::max(worst, std::abs(std::log(std::max(r, 1e-9))));
    if (worst < best_worst) {
      best_worst = worst;
      record.ratio_after = chain.ratio;
      best = model;
    }
    if (round == options.rounds) break;
    if (held_by_attraction(model, previous, chain)) {
      record.attraction_shrink *= 0.5;
      shrink_attraction(model, 0.5);
      std::fill(low.begin(), low.end(), 0.0);
      std::fill(high.begin(), high.end(), std::numeric_limits<double>::infinity());
      previous = {};
      continue;
    }
    previous.ratio = chain.ratio;
    previous.beta.clear();
    for (const model::CategoryParameters& c : model.categories) previous.beta.push_back(c.beta);
    for (std::size_t c = 0; c < categories; ++c) {
      // A category that agrees keeps its β: a step on its chain's noise would only add noise.
      if (!steps(model, chain, c)) continue;
      const double r = chain.ratio[c], beta = model.categories[c].beta;
      // The count grows with β: a β known too low or too high brackets the answer, and once
      // both ends are known the next β halves the bracket (in log β), as a crystal's nucleation
      // makes the count jump where a proportional step would overshoot.
      if (r < 1) low[c] = std::max(low[c], beta);
      if (r > 1) high[c] = std::min(high[c], beta);
      // None at all says only that β is far too low: the largest step, squared.
      double next = beta * (r > 0 ? std::clamp(1.0 / r, 1.0 / kLargestStep, kLargestStep)
                                  : kLargestStep * kLargestStep);
      if (low[c] > 0 && std::isfinite(high[c]) && !(next > low[c] && next < high[c]))
        next = std::sqrt(low[c] * high[c]);
      record.beta_factor[c] *= next / beta;
      model.categories[c].beta = next;
    }
  }
  if (!record.converged && std::isfinite(best_worst)) {
    for (std::size_t c = 0; c < categories; ++c)
      record.beta_factor[c] *= best.categories[c].beta / model.categories[c].beta;
    model = std::move(best);
  }
  record.seconds = clock.seconds();
  return record;
}

}  // namespace shapeproc::fit
