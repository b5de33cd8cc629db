#include "libshapeproc/fit/density_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace shapeproc::fit {

namespace {

constexpr double kLargestStep = kFitDefaults.calibration_largest_step;

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
  std::vector<double> ratio;  // per category
};

// `geometry`: the proxies of the model's shapes on `domain`, built once for every chain (the
// check changes β and γ, never the shapes or thresholds). The ratio is the chain's mean count per
// category over the second half of its run, after any burn-in, to the expected count: a time
// average, far less noisy than the last state, so the chain stops once its count is stationary
// (no run-on).
Chain run_chain(const model::ShapeProcessModel& model, const geometry::Domain& domain,
                const std::shared_ptr<const sample::ChainGeometry>& geometry,
                const std::vector<double>& expected, double exemplar_density, std::uint64_t seed,
                int threads) {
  OutputSampling sampling;
  sampling.exemplar_density = exemplar_density;
  sampling.threads = threads;
  sample::SamplerOptions options = output_sampler_options(model, domain, sampling);
  options.geometry = geometry;
  options.run_on = false;
  double total = 0.0;
  for (double e : expected) total += e;
  options.observe_every = std::max<long long>(10, static_cast<long long>(total));
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
  // The observed chain's own steps (a layered model's last layer; the earlier layers' counts are
  // those it holds fixed).
  const long long steps = result.iterations - result.observed_from;
  const long long from = std::max(result.compression_steps, steps / 2);
  std::vector<double> counts(expected.size(), 0.0);
  double kept = 0.0;
  for (std::size_t i = 0; i < result.observations.size(); ++i) {
    if (static_cast<long long>(i + 1) * options.observe_every <= from) continue;
    for (std::size_t c = 0; c < expected.size(); ++c) counts[c] += result.observations[i][c];
    kept += 1.0;
  }
  if (kept == 0.0) {  // a run too short to observe: its last state
    for (const geometry::Element& e : result.scene.elements)
      counts[static_cast<std::size_t>(e.category)] += 1;
    kept = 1.0;
  }
  for (std::size_t c = 0; c < expected.size(); ++c)
    chain.ratio.push_back(counts[c] / kept / expected[c]);
  // An anchored category's count follows its bases': its ratio is per base (its β sets how many
  // each base carries; the bases' own β, how many bases there are).
  std::vector<double> per_base = chain.ratio;
  for (std::size_t c = 0; c < expected.size(); ++c)
    if (const int anchor = model.categories[c].anchor; anchor >= 0)
      per_base[c] = chain.ratio[static_cast<std::size_t>(anchor)] > 0
                        ? chain.ratio[c] / chain.ratio[static_cast<std::size_t>(anchor)]
                        : 0.0;
  chain.ratio = std::move(per_base);
  return chain;
}

bool category_agrees(double ratio, double expected, double tolerance) {
  const double allowed = std::max(tolerance, 2.0 / std::sqrt(std::max(1.0, expected)));
  return std::abs(ratio - 1.0) <= allowed;
}

bool agrees(const std::vector<double>& ratio, const std::vector<double>& expected,
            double tolerance) {
  for (std::size_t c = 0; c < ratio.size(); ++c)
    if (!category_agrees(ratio[c], expected[c], tolerance)) return false;
  return true;
}

void shrink_attraction(model::ShapeProcessModel& model, double factor) {
  for (model::PairInteraction& pair : model.interactions)
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
  // the category's density, as the maximum likelihood does.
  for (std::size_t c = 0; c < categories; ++c) {
    model::CategoryParameters& category = model.categories[c];
    if (category.beta_status != model::ParameterStatus::unbounded) continue;
    const double start = expected[c] / scale / exemplar.window_measure();
    record.beta_factor[c] = start / category.beta;
    category.beta = start;
  }
  const auto geometry =
      std::make_shared<const sample::ChainGeometry>(model, model::Interaction(model), domain);
  double best_worst = std::numeric_limits<double>::infinity();
  std::vector<double> best_beta(categories, 0.0);
  std::vector<double> low(categories, 0.0),
      high(categories, std::numeric_limits<double>::infinity());  // β brackets
  for (int round = 1; round <= options.rounds; ++round) {
    if (options.progress) options.progress(round, options.rounds);
    const Chain chain =
        run_chain(model, domain, geometry, expected, density,
                  options.seed + static_cast<std::uint64_t>(round - 1), options.threads);
    record.rounds = round;
    if (chain.ran_away) {
      record.ran_away = true;
      record.attraction_shrink *= 0.5;
      shrink_attraction(model, 0.5);
      continue;
    }
    if (record.ratio_before.empty()) record.ratio_before = chain.ratio;
    if (agrees(chain.ratio, expected, options.tolerance)) {
      record.ratio_after = chain.ratio;
      record.converged = true;
      break;
    }
    // The closest agreement yet (its worst category's), which a check that never agrees keeps.
    double worst = 0.0;
    for (double r : chain.ratio) worst = std::max(worst, std::abs(std::log(std::max(r, 1e-9))));
    if (worst < best_worst) {
      best_worst = worst;
      record.ratio_after = chain.ratio;
      for (std::size_t c = 0; c < categories; ++c) best_beta[c] = model.categories[c].beta;
    }
    if (round == options.rounds) break;
    for (std::size_t c = 0; c < categories; ++c) {
      // A category that agrees keeps its β: a step on its chain's noise would only add noise.
      if (category_agrees(chain.ratio[c], expected[c], options.tolerance)) continue;
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
    for (std::size_t c = 0; c < categories; ++c) {
      record.beta_factor[c] *= best_beta[c] / model.categories[c].beta;
      model.categories[c].beta = best_beta[c];
    }
  }
  record.seconds = clock.seconds();
  return record;
}

}  // namespace shapeproc::fit
