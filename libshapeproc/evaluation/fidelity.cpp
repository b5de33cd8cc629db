#include "libshapeproc/evaluation/fidelity.hpp"

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <limits>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/fit/mcmc_mle.hpp"
#include "libshapeproc/fit/monte_carlo_moments.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"
#include "libshapeproc/metrics/novelty.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/run_chains.hpp"

namespace shapeproc::evaluation {

namespace {

constexpr int kCollisionOffsets = 256;  // g(r) is not used here: few Monte Carlo offsets

// What the maximum-likelihood fit recorded (fit.estimator): the Monte Carlo standard errors of
// its expectations, by which its estimate is itself uncertain, and the pairs its attraction prior
// holds back in every band. Zeros for other models.
struct FitPrecision {
  std::vector<double> expected_error;
  // The fit's target is t(z) − log γ / σ² where its half-normal prior on log γ > 0 acts (its
  // penalised likelihood's estimating equation): the pairs the prior holds back.
  std::vector<double> prior_shift;
};

FitPrecision fit_precision(const model::ShapeProcessModel& model, std::size_t statistics) {
  FitPrecision f{std::vector<double>(statistics, 0.0), std::vector<double>(statistics, 0.0)};
  if (!model.fit || !model.fit->likelihood) return f;
  const model::LikelihoodRecord& e = *model.fit->likelihood;
  if (e.expected_standard_error.size() == statistics) f.expected_error = e.expected_standard_error;
  const double sd = e.attraction_prior_sd;
  if (sd > 0) {
    const model::Interaction interaction(model);
    for (int p = static_cast<int>(model.categories.size()); p < interaction.parameter_count();
         ++p) {
      const double log_gamma = interaction.log_gamma_of(p);
      if (static_cast<std::size_t>(p) < statistics && std::isfinite(log_gamma) && log_gamma > 0)
        f.prior_shift[static_cast<std::size_t>(p)] = log_gamma / (sd * sd);
    }
  }
  return f;
}

// 1. The model's statistics on the exemplar's own window against the exemplar's.
void check_own_window(const geometry::Scene& exemplar, const model::ShapeProcessModel& model,
                      geometry::Boundary boundary, geometry::EdgeTreatment edge,
                      const FidelityOptions& options, FidelityReport& report) {
  // A fit on the stationary window is checked as it was fitted: the window inside its torus.
  const bool stationary = fit::fitted_on_stationary_window(model);
  const geometry::Domain window =
      stationary ? fit::stationary_domain(exemplar)
                 : geometry::Domain(exemplar.window, exemplar.dimension, boundary);
  fit::ChainsSetting setting = options.sampling;
  if (stationary) setting.observe_region = exemplar.window;
  if (edge == geometry::EdgeTreatment::border) {
    const fit::BorderCondition border = fit::border_condition(exemplar, model);
    setting.fixed = border.fixed;
    setting.free_region = border.region;
  }
  // The chains run the fit's burn-in: compressing for a packed exemplar.
  setting.burn_in_kind = model::output_burn_in(model);
  const fit::StatisticsMoments m = fit::statistics_moments(model, window, setting);
  const std::vector<double> observed = fit::observed_statistics(exemplar, model);
  const std::vector<std::string> names = model::statistic_names(model);
  const model::Interaction interaction(model);
  const FitPrecision fit = fit_precision(model, observed.size());
  for (std::size_t k = 0; k < observed.size(); ++k) {
    StatisticCheck c;
    c.name = k < names.size() ? names[k] : "statistic " + std::to_string(k);
    c.exemplar = observed[k];
    c.target = observed[k] - fit.prior_shift[k];
    c.mean = m.mean[k];
    c.standard_error = std::hypot(m.standard_error[k], fit.expected_error[k]);
    c.count =
        k < model.categories.size() || k >= static_cast<std::size_t>(interaction.parameter_count());
    // Within a tenth of an element or pair: matched, as the fit judges it (fit::kNegligibleGap).
    const double gap = std::abs(c.mean - c.target) <= fit::kNegligibleGap ? 0.0 : c.mean - c.target;
    c.z = gap == 0               ? 0.0
          : c.standard_error > 0 ? gap / c.standard_error
                                 : std::copysign(std::numeric_limits<double>::infinity(), gap);
    double& worst = c.count ? report.worst_count_z : report.worst_pair_z;
    if (c.target != c.exemplar) ++report.penalised;
    worst = std::max(worst, std::abs(c.z));
    report.own_window.push_back(c);
  }
}

int colliding_pairs(const geometry::Scene& scene, geometry::Boundary boundary) {
  if (scene.elements.size() < 2) return 0;
  metrics::StatisticsOptions o;
  o.measurement.periodic = boundary == geometry::Boundary::torus;
  o.offset_samples = kCollisionOffsets;
  return static_cast<int>(
      metrics::compute_statistics(scene, o, core::Random(1)).collisions.pairs.size());
}

// 2. Larger outputs: density, collisions, shape-class mix.
void check_output(const geometry::Scene& exemplar, const model::ShapeProcessModel& model,
                  geometry::Boundary boundary, const FidelityOptions& options,
                  FidelityReport& report) {
  std::vector<double> sides;
  for (int axis = 0; axis < exemplar.dimension; ++axis)
    sides.push_back(options.scale * exemplar.window.sizes()[axis]);
  const geometry::Domain domain = geometry::Domain::from_sizes(sides, geometry::Boundary::torus);
  fit::OutputSampling sampling;  // as `synthesize` samples, but measured however dense it gets
  sampling.stop_runaway = false;
  sampling.decompose = fit::Decomposition::off;
  const sample::ShapeProcessSampler sampler = fit::output_sampler(model, domain, sampling);
  synthesis::ChainOptions chains;
  chains.chains = options.outputs;
  chains.threads = options.sampling.threads;
  chains.seed = options.sampling.seed;
  const std::vector<synthesis::SynthesisResult> outputs = synthesis::run_chains(sampler, chains);

  const double exemplar_density =
      report.exemplar_elements / geometry::measure(exemplar.window, exemplar.dimension);
  const std::size_t classes = model.shape_classes.size();
  std::vector<double> in_output(classes, 0.0), ratios;
  double total = 0.0;
  for (const synthesis::SynthesisResult& output : outputs) {
    const std::vector<geometry::Element>& elements = output.scene.elements;
    ratios.push_back(static_cast<double>(elements.size()) / domain.measure() / exemplar_density);
    total += static_cast<double>(elements.size());
    report.output_collisions += colliding_pairs(output.scene, geometry::Boundary::torus);
    if (!elements.empty()) {
      const metrics::Novelty n =
          metrics::measure_novelty(exemplar, output.scene, geometry::Boundary::torus);
      const double w = 1.0 / static_cast<double>(outputs.size());
      report.patch_copy_share += w * n.output.patch;
      report.patch_copy_chance += w * n.chance.patch;
      report.largest_copied_patch += w * n.output.largest_patch;
      report.lattice_exemplar = n.lattice_exemplar;
      if (n.repeats_exemplar) ++report.outputs_repeating;
    }
    for (const geometry::Element& e : elements)
      if (classes > 0)
        in_output[static_cast<std::size_t>(
            model.shapes[static_cast<std::size_t>(e.shape)].shape_class)] += 1;
  }
  report.outputs = static_cast<int>(outputs.size());
  report.output_elements = total / static_cast<double>(outputs.size());
  double mean = 0.0, spread = 0.0;
  for (double r : ratios) mean += r / static_cast<double>(ratios.size());
  for (double r : ratios) spread += (r - mean) * (r - mean);
  report.density_ratio = mean;
  report.density_ratio_error = ratios.size() > 1
                                   ? std::sqrt(spread / static_cast<double>(ratios.size() - 1) /
                                               static_cast<double>(ratios.size()))
                                   : 0.0;
  report.exemplar_collisions = colliding_pairs(exemplar, boundary);

  report.class_p_value = std::numeric_limits<double>::quiet_NaN();
  if (classes < 2 || total == 0) return;
  std::vector<double> in_exemplar(classes, 0.0);
  for (const geometry::Element& e : exemplar.elements)
    in_exemplar[static_cast<std::size_t>(
        model.shapes[static_cast<std::size_t>(e.shape)].shape_class)] += 1;
  for (std::size_t k = 0; k < classes; ++k) {
    const double expected = total * in_exemplar[k] / static_cast<double>(report.exemplar_elements);
    if (expected > 0) report.class_chi_square += std::pow(in_output[k] - expected, 2) / expected;
  }
  report.class_degrees = static_cast<int>(classes) - 1;
  report.class_p_value = chi_square_upper_tail(report.class_chi_square, report.class_degrees);
}

}  // namespace

double chi_square_upper_tail(double x, int degrees) {
  core::check(degrees >= 1, "chi_square_upper_tail", "degrees of freedom must be >= 1");
  if (!(x > 0)) return 1.0;
  return boost::math::gamma_q(0.5 * degrees, 0.5 * x);
}

FidelityReport check_fidelity(const geometry::Scene& exemplar,
                              const model::ShapeProcessModel& model, geometry::Boundary boundary,
                              geometry::EdgeTreatment edge, const FidelityOptions& options) {
  core::check(options.sampling.chains >= 2, "fidelity", "at least two chains are needed");
  core::check_positive("fidelity", "the output scale", options.scale);
  core::check(options.outputs >= 1 && options.outputs <= 1000, "fidelity",
              "the outputs must be 1 to 1000");
  FidelityReport report;
  report.exemplar_elements = static_cast<int>(exemplar.elements.size());
  core::check(report.exemplar_elements > 0, "fidelity", "the exemplar has no element");
  check_own_window(exemplar, model, boundary, edge, options, report);
  check_output(exemplar, model, boundary, options, report);
  return report;
}

}  // namespace shapeproc::evaluation
