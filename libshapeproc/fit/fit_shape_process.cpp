#include "libshapeproc/fit/fit_shape_process.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/fit/category_layers.hpp"
#include "libshapeproc/fit/detail/existence_check.hpp"
#include "libshapeproc/fit/detail/model_assembly.hpp"
#include "libshapeproc/fit/detail/quadrature_design.hpp"
#include "libshapeproc/fit/exemplar_statistics.hpp"
#include "libshapeproc/fit/fit_thresholds.hpp"
#include "libshapeproc/fit/neighbour_offsets.hpp"
#include "libshapeproc/fit/saturation_choice.hpp"
#include "libshapeproc/fit/shape_classes.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

int default_quadrature_cells(int dimension) { return dimension == 3 ? 8 : 48; }

namespace {}  // namespace

const char* edge_name(const FitOptions& options) {
  if (options.boundary == geometry::Boundary::torus) return "periodic";
  return geometry::to_string(options.edge);
}

FitResult fit_shape_process(const geometry::Scene& exemplar, const FitOptions& options) {
  check_fit_options(options);
  FitResult result;
  model::ShapeProcessModel& model = result.model;
  model = model_skeleton(exemplar, options);
  const std::vector<std::vector<int>> shapes_of = shapes_by_category(exemplar);

  const auto stage = [&](const char* name) {
    if (options.progress) options.progress(name, 0, 0);
  };
  // Proxies and every pair's measurements.
  stage("proxies");
  // The exemplar's window as a domain: a torus for the periodic edge treatment.
  const geometry::Domain window(exemplar.window, exemplar.dimension, options.boundary);
  const bool periodic = window.periodic();
  core::Stopwatch clock;
  const geometry::PairMeasurer measurer(exemplar, model.measurement_options(periodic));
  result.seconds.proxies = clock.seconds();
  stage("measurements");
  clock.restart();
  const std::vector<geometry::PairRecord> pairs = measurer.all_pairs(exemplar.elements);
  result.seconds.measurements = clock.seconds();

  add_thresholds(model, exemplar, pairs, measurer.bins(), options, result.notes);
  for (std::string& note : assign_layers(model, exemplar, pairs, measurer, options.layer_share))
    result.notes.push_back(std::move(note));
  assign_shape_classes(model, exemplar);
  model.neighbour_offsets = neighbour_offsets(exemplar, periodic);
  model.neighbour_offsets.share = std::max(0.0, options.near_birth_share);
  const model::Interaction interaction(model);
  const FitRegion region = fit_region(exemplar, options.edge, interaction.range());
  const ExemplarStatistics statistics =
      exemplar_statistics(exemplar, pairs, interaction, region, model);
  result.data_points = statistics.data_points;

  stage("quadrature");
  clock.restart();
  const QuadratureDesign quadrature = quadrature_design(exemplar, options, region, measurer,
                                                        interaction, statistics, shapes_of, window);
  result.quadrature_cells = quadrature.cells;
  result.quadrature_lines = quadrature.lines;
  result.quadrature_points = static_cast<int>(quadrature.design.points.size());
  const bool existence = can_check_existence(options.data_weight);
  PseudoLikelihoodDesign heavier;
  if (existence) heavier = with_data_share(quadrature, options.data_weight, kExistenceFactor);
  PseudoLikelihoodDesign design = quadrature.design;
  merge_equal_points(design);
  if (existence) merge_equal_points(heavier);
  result.seconds.quadrature = clock.seconds();

  stage("optimisation");
  // Maximum pseudo-likelihood, from β at the data's density and γ = 1.
  clock.restart();
  const double measure = geometry::measure(region.box, exemplar.dimension);
  std::vector<double> start(static_cast<std::size_t>(design.parameter_count), 0.0);
  for (std::size_t c = 0; c < model.categories.size(); ++c)
    start[c] = std::log(statistics.per_category[c] / measure);
  MpleResult mple = maximise_pseudo_likelihood(design, start);
  const bool follows_share = existence && check_existence(heavier, mple);
  result.seconds.optimisation = clock.seconds();
  result.log_pseudo_likelihood = mple.log_pseudo_likelihood;

  assign_estimates(model, interaction, mple);
  add_existence_notes(mple, follows_share, result.notes);
  // Attraction between points is saturated where the data prefer it: a pairwise γ > 1 between
  // points has no density (the chain condenses, Kelly & Ripley 1976); shapes kept apart by their
  // hard core do.
  if (options.saturation && model.shapes.empty()) {
    const std::vector<int> bands = attractive_bands(model, interaction, kFitDefaults.saturation_z);
    if (!bands.empty()) {
      stage("saturation");
      clock.restart();
      // Each candidate fitted on its own sampled quadrature, from the same start.
      const auto fit_candidate = [&](const model::ShapeProcessModel& candidate) {
        model::ShapeProcessModel counted = candidate;  // its observed pairs are counted again
        const model::Interaction saturated(counted);
        const ExemplarStatistics own =
            exemplar_statistics(exemplar, pairs, saturated, region, counted);
        QuadratureDesign sampled = quadrature_design(exemplar, options, region, measurer, saturated,
                                                     own, shapes_of, window);
        merge_equal_points(sampled.design);
        return maximise_pseudo_likelihood(sampled.design, start);
      };
      const std::vector<double> levels(kFitDefaults.saturation_quantiles.begin(),
                                       kFitDefaults.saturation_quantiles.end());
      SaturationChoice choice =
          choose_saturation(model, interaction, bands,
                            saturation_candidates(pairs, exemplar, interaction, bands, levels),
                            kFitDefaults.saturation_gain, fit_candidate);
      result.notes.push_back(choice.note);
      if (choice.saturated) {
        set_saturations(model, interaction, bands, choice.saturations);
        assign_estimates(model, model::Interaction(model), choice.mple);
        mple = std::move(choice.mple);
        result.log_pseudo_likelihood = mple.log_pseudo_likelihood;
      }
      result.seconds.optimisation += clock.seconds();
    }
  }
  model.fit = pseudo_likelihood_record(exemplar, options, result, quadrature.cells_along, mple);
  return result;
}

}  // namespace shapeproc::fit
