// The whole fit of an exemplar, as `shapeproc fit` and `synthesize` run it: the thresholds and
// the maximum pseudo-likelihood (fit_shape_process.hpp), then, unless asked not to, the maximum
// likelihood by MCMC from that estimate (fit_maximum_likelihood.hpp); a seamless tile is fitted
// on its torus, repeated where it is small or its interactions reach too far (tile_fit.hpp); then
// the density check on the output's scale (density_calibration.hpp).
#pragma once

#include <optional>

#include "libshapeproc/fit/density_calibration.hpp"
#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/fit/mcmc_mle.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::fit {

struct ExemplarFitOptions {
  // The pseudo-likelihood's options. Its quadrature, when automatic, keeps the cells' size on a
  // repeated tile: as many cells per tile as the default gives one. Its progress reports the
  // stages of every pseudo-likelihood fit (a tile may be fitted twice).
  FitOptions fit;
  // The maximum likelihood's options (its progress reports each iteration); none: the model is
  // the pseudo-likelihood's estimate.
  std::optional<MleOptions> likelihood = MleOptions{};
  // The maximum likelihood runs on tiles, whose packings and lattices need it, and on other
  // exemplars of at most this many elements (fit_defaults.hpp). Its chains' cost grows faster
  // than n (more elements, each with more neighbours, over more sweeps); on larger exemplars the
  // pseudo-likelihood, whose efficiency approaches the likelihood's as n grows, and the density
  // check on the output's scale serve. The record notes the choice.
  std::size_t likelihood_elements = kFitDefaults.likelihood_elements;
  // Pairs whose pseudo-likelihood strengths are all within two standard errors of 1 keep their
  // hard core alone (parameter_budget.hpp, prune_neutral_pairs), before the maximum likelihood;
  // not for a packed exemplar (a pseudo-likelihood without a finite maximum) that the maximum
  // likelihood then fits.
  bool prune_neutral = true;
  // A clustered 2D point pattern (not a tile) gains its clusters' centres as a hidden category
  // that its points are anchored to (cluster_centres.hpp); one of several categories is fitted
  // with them pooled, as independent marks (independent_marks.hpp).
  bool clusters = true;
  // The exemplar is one period of a seamless 2D repeat (read with --tile): fitted with periodic
  // edges, on a repeat of it where needed.
  bool tile = false;
  // The density check on the output's scale, and its corrections (density_calibration.hpp); none:
  // the estimate is returned as it is. Its seed, when the maximum likelihood runs, is that of the
  // maximum likelihood's chains; its progress comes through fit.progress as stage "calibration".
  std::optional<CalibrationOptions> calibration = CalibrationOptions{};
};

struct ExemplarFit {
  // The model, with its record (model::FitRecord: the tile's repeats and the fit's notes).
  FitResult result;
  geometry::Scene exemplar;  // as fitted: a tile repeated `repeats` × `repeats`
  int repeats = 1;
};

// The defaults for an exemplar read as a seamless tile (`tile`) or not: a tile is fitted on its
// torus (FitOptions::boundary), as `shapeproc fit --tile` fits it.
ExemplarFitOptions exemplar_fit_options(bool tile);

// Throws core::ArgumentError for options out of range, std::invalid_argument for an exemplar the
// fit cannot take (no elements, a category without any).
ExemplarFit fit_exemplar(const geometry::Scene& exemplar, const ExemplarFitOptions& options);

}  // namespace shapeproc::fit
