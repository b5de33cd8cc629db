#include "libshapeproc/fit/fit_exemplar.hpp"

#include <utility>

#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/fit/tile_fit.hpp"

namespace shapeproc::fit {

namespace {

// The options for the exemplar repeated `repeats` times along each axis.
FitOptions repeated_options(const geometry::Scene& exemplar, int repeats, FitOptions options) {
  if (repeats > 1 && options.quadrature == 0 && exemplar.dimension == 2)
    options.quadrature = default_quadrature_cells(2) * repeats;
  return options;
}

}  // namespace

ExemplarFit fit_exemplar(const geometry::Scene& exemplar, const ExemplarFitOptions& options) {
  const auto pseudo_likelihood = [&](const geometry::Scene& scene, int repeats) {
    return fit_shape_process(scene, repeated_options(scene, repeats, options.fit));
  };
  const auto maximum_likelihood = [&](const geometry::Scene& scene, int repeats, FitResult mpl) {
    if (!options.likelihood) return mpl;
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
    fit.result = maximum_likelihood(exemplar, 1, pseudo_likelihood(exemplar, 1));
  }
  for (const std::string& note : fit.exemplar.notes) fit.result.notes.push_back("reading: " + note);
  if (!fit.result.model.fit) fit.result.model.fit.emplace();
  model::FitRecord& record = *fit.result.model.fit;
  if (fit.repeats > 1) record.tile_repeats = fit.repeats;
  for (const std::string& note : tile_notes) {
    record.notes.push_back(note);
    fit.result.notes.push_back(note);
  }
  return fit;
}

}  // namespace shapeproc::fit
