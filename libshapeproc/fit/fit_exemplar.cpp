#include "libshapeproc/fit/fit_exemplar.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

#include "libshapeproc/fit/cluster_centres.hpp"
#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/fit/independent_marks.hpp"
#include "libshapeproc/fit/parameter_budget.hpp"
#include "libshapeproc/fit/tile_fit.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

namespace {

// The options for the exemplar repeated `repeats` times along each axis.
FitOptions repeated_options(const geometry::Scene& exemplar, int repeats, FitOptions options) {
  if (repeats > 1 && options.quadrature == 0 && exemplar.dimension == 2)
    options.quadrature = default_quadrature_cells(2) * repeats;
  return options;
}

// The density check and its corrections, recorded in the model and its notes.
void calibrate(ExemplarFit& fit, const ExemplarFitOptions& options) {
  CalibrationOptions calibration = *options.calibration;
  if (options.likelihood) calibration.seed = options.likelihood->sampling.seed;
  if (!calibration.progress && options.fit.progress) {
    calibration.progress = [&](int round, int rounds) {
      options.fit.progress("calibration", round, rounds);
    };
  }
  model::ShapeProcessModel& model = fit.result.model;
  model::CalibrationRecord record = calibrate_density(model, fit.exemplar, calibration);
  std::ostringstream note;
  note << "density on a torus of " << record.multiple << " x " << record.multiple << " windows: ";
  for (std::size_t c = 0; c < record.ratio_after.size(); ++c) {
    note << (c ? ", " : "") << "'" << model.categories[c].name << "'"
         << (model.categories[c].anchor >= 0 ? " per base" : "") << " x" << std::setprecision(3)
         << record.ratio_before[c];
    if (record.rounds > 1) note << " -> x" << record.ratio_after[c];
  }
  if (record.ran_away)
    note << "; chains ran away, every γ > 1 raised to the power " << record.attraction_shrink;
  if (!record.converged)
    note << "; did not agree within the tolerance after " << record.rounds << " chains";
  model.fit->notes.push_back(note.str());
  fit.result.notes.push_back(note.str());
  model.fit->calibration = std::move(record);
}

// A point pattern: every shape of the exemplar a point.
bool point_pattern(const geometry::Scene& exemplar) {
  return !exemplar.shapes.empty() &&
         std::all_of(exemplar.shapes.begin(), exemplar.shapes.end(), [](const geometry::Shape& s) {
           return std::holds_alternative<geometry::PointShape>(s.geometry);
         });
}

// The clusters of a 2D point pattern (cluster_centres.hpp), when the options ask for them and it
// is one (not a tile); the test's note joins `notes`.
ClusterFit exemplar_clusters(const geometry::Scene& exemplar, const ExemplarFitOptions& options,
                             std::vector<std::string>& notes) {
  if (!options.clusters || options.tile || !point_pattern(exemplar)) return {};
  ClusterFit clusters = find_clusters(exemplar, options.fit.boundary == geometry::Boundary::torus);
  notes.push_back(clusters.note);
  return clusters;
}

// Adds `centres` to the exemplar as one more category; returns its index.
int add_centres(geometry::Scene& exemplar, const std::vector<geometry::Vec3>& centres) {
  std::string name = "cluster centre";
  const auto taken = [&](const std::string& n) {
    return std::any_of(exemplar.categories.begin(), exemplar.categories.end(),
                       [&](const geometry::Category& c) { return c.name == n; });
  };
  while (taken(name)) name += "'";
  const int category = exemplar.category_index(name);
  for (const geometry::Vec3& c : centres) exemplar.elements.push_back({0, category, c});
  return category;
}

// Given the centres, the points of a cluster are placed as a cluster process places its
// children: around their centre, independently up to their repulsion. A pairwise γ > 1 among them
// would count the clustering twice, and condenses (data/corpus thomas: its chains ran away); a γ
// of 0 where a band of two small classes saw no pair, or a γ < 1 within two standard errors of 1,
// is a few points' chance arrangement, not a repulsion. Those are set to 1; the hard cores and
// the clear repulsions stay. A note says how many.
void children_given_centres(model::ShapeProcessModel& model, int centres,
                            std::vector<std::string>& notes) {
  const auto on_centres = [&](int c) {
    return model.categories[static_cast<std::size_t>(c)].anchor == centres;
  };
  const auto repulsion = [](const model::AxisParameters& axis, std::size_t k) {
    const double g = axis.gammas[k], se = axis.gamma_standard_errors[k];
    return axis.status[k] == model::ParameterStatus::free && g < 1.0 && std::isfinite(se) &&
           std::log(g) < -kFitDefaults.neutral_z * se / g;
  };
  int released = 0, pairs = 0;
  for (model::PairInteraction& pair : model.interactions) {
    if (!on_centres(pair.first) || !on_centres(pair.second)) continue;
    ++pairs;
    for (model::AxisParameters& axis : pair.axes)
      for (std::size_t k = 0; k < axis.gammas.size(); ++k) {
        if (axis.gammas[k] == 1.0 || repulsion(axis, k)) continue;
        axis.gammas[k] = 1.0;
        axis.status[k] = model::ParameterStatus::fixed;
        axis.gamma_standard_errors[k] = std::numeric_limits<double>::quiet_NaN();
        if (!axis.saturations.empty()) axis.saturations[k] = 0;
        ++released;
      }
  }
  if (released > 0)
    notes.push_back(std::to_string(released) + " band(s) of the " + std::to_string(pairs) +
                    " pair(s) of clustered categories set to 1 (attractions, and repulsions "
                    "within two standard errors): the clustering is the cluster centres'");
}

}  // namespace

ExemplarFitOptions exemplar_fit_options(bool tile) {
  ExemplarFitOptions options;
  options.tile = tile;
  if (tile) options.fit.boundary = geometry::Boundary::torus;
  return options;
}

ExemplarFit fit_exemplar(const geometry::Scene& exemplar, const ExemplarFitOptions& options) {
  const bool likelihood = options.likelihood &&
                          (options.tile || exemplar.elements.size() <= options.likelihood_elements);
  int centres = -1;     // the hidden category of a clustered pattern's centres
  bool pooled = false;  // its categories fitted as one (independent_marks.hpp)
  const auto pseudo_likelihood = [&](const geometry::Scene& scene, int repeats) {
    FitOptions fit_options = repeated_options(scene, repeats, options.fit);
    // A saturated band counts an element's neighbours of every category: not one to split.
    fit_options.saturation = fit_options.saturation && !options.tile && !pooled;
    FitResult result = fit_shape_process(scene, fit_options);
    // A pseudo-likelihood without a finite maximum (a packed exemplar) has standard errors that
    // say nothing; where the maximum likelihood follows, it judges the strengths instead.
    if (options.prune_neutral && !(likelihood && packed_exemplar(result.model))) {
      for (std::string& note : prune_neutral_pairs(result.model)) {
        result.notes.push_back(note);
        if (result.model.fit) result.model.fit->notes.push_back(note);
      }
    }
    return result;
  };
  const auto maximum_likelihood = [&](const geometry::Scene& scene, int repeats, FitResult mpl) {
    if (!likelihood) return mpl;
    const bool saturated = model::Interaction(mpl.model).saturated();
    if (mpl.model.layer_count() > 1 || saturated) {
      // Each layer's likelihood is conditional on the exemplar's layers below, which chains from
      // empty do not hold fixed; the layered model is left to its pseudo-likelihood. So is a
      // saturated one, whose profile over s was of the pseudo-likelihood.
      const std::string note =
          std::string("maximum likelihood not run: a ") + (saturated ? "saturated" : "layered") +
          " model, fitted by its pseudo-likelihood and checked on the output's scale";
      mpl.notes.push_back(note);
      if (mpl.model.fit) mpl.model.fit->notes.push_back(note);
      return mpl;
    }
    return refine_to_maximum_likelihood(scene, repeated_options(scene, repeats, options.fit),
                                        std::move(mpl), *options.likelihood);
  };
  ExemplarFit fit;
  std::vector<std::string> tile_notes;
  if (options.tile && exemplar.dimension == 2) {
    TileFit tile = fit_tile(exemplar, pseudo_likelihood, maximum_likelihood);
    fit.result = std::move(tile.result);
    fit.exemplar = std::move(tile.exemplar);
    fit.repeats = tile.repeats;
    tile_notes = std::move(tile.notes);
  } else {
    fit.exemplar = exemplar;
    const ClusterFit clusters = exemplar_clusters(exemplar, options, tile_notes);
    pooled = clusters.clustered && exemplar.categories.size() > 1;
    geometry::Scene scene = pooled ? pool_categories(exemplar) : geometry::Scene{};
    geometry::Scene& fitted = pooled ? scene : fit.exemplar;
    if (clusters.clustered) centres = add_centres(fitted, clusters.centres);
    fit.result = maximum_likelihood(fitted, 1, pseudo_likelihood(fitted, 1));
    if (centres >= 0) {
      fit.result.model.categories[static_cast<std::size_t>(centres)].hidden = true;
      children_given_centres(fit.result.model, centres, tile_notes);
    }
    if (pooled) {
      split_into_marks(fit.result.model, 0, exemplar);
      centres = add_centres(fit.exemplar, clusters.centres);
      tile_notes.push_back("clusters: the " + std::to_string(exemplar.categories.size()) +
                           " categories fitted as one, then split in their shares (independent "
                           "marks): each cluster's mix of categories is not modelled");
    }
  }
  for (const std::string& note : fit.exemplar.notes) fit.result.notes.push_back("reading: " + note);
  if (!fit.result.model.fit) fit.result.model.fit.emplace();
  model::FitRecord& record = *fit.result.model.fit;
  if (fit.repeats > 1) record.tile_repeats = fit.repeats;
  if (centres >= 0) record.elements = static_cast<long long>(exemplar.elements.size());
  for (const std::string& note : tile_notes) {
    record.notes.push_back(note);
    fit.result.notes.push_back(note);
  }
  if (options.likelihood && !likelihood) {
    const std::string note =
        "maximum likelihood not run: " + std::to_string(exemplar.elements.size()) +
        " elements, over " + std::to_string(options.likelihood_elements) +
        "; the pseudo-likelihood's estimate, checked on the output's scale";
    record.notes.push_back(note);
    fit.result.notes.push_back(note);
  }
  if (options.calibration) calibrate(fit, options);
  // Centres that the check could not hold (a small exemplar's separated data: its points' bands
  // around the centres unbounded, the chains running away) leave the model worse than none: it is
  // fitted again without them.
  const auto& check = fit.result.model.fit->calibration;
  if (centres >= 0 && check && check->ran_away && !check->converged) {
    ExemplarFitOptions without = options;
    without.clusters = false;
    ExemplarFit again = fit_exemplar(exemplar, without);
    const std::string note =
        "clusters: the model with cluster centres ran away on the output's scale; fitted without "
        "them";
    again.result.notes.push_back(note);
    again.result.model.fit->notes.push_back(note);
    return again;
  }
  return fit;
}

}  // namespace shapeproc::fit
