// The whole fit of an exemplar, as `shapeproc fit` and `synthesize` run it: the thresholds and
// the maximum pseudo-likelihood (fit_shape_process.hpp), then, unless asked not to, the maximum
// likelihood by MCMC from that estimate (fit_maximum_likelihood.hpp); a seamless tile is fitted
// on its torus, repeated where it is small or its interactions reach too far (tile_fit.hpp).
#pragma once

#include <optional>

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
  // The exemplar is one period of a seamless 2D repeat (read with --tile): fitted with periodic
  // edges, on a repeat of it where needed.
  bool tile = false;
};

struct ExemplarFit {
  // The model, with its record (model::FitRecord: the tile's repeats and the fit's notes).
  FitResult result;
  geometry::Scene exemplar;  // as fitted: a tile repeated `repeats` × `repeats`
  int repeats = 1;
};

// Throws core::ArgumentError for options out of range, std::invalid_argument for an exemplar the
// fit cannot take (no elements, a category without any).
ExemplarFit fit_exemplar(const geometry::Scene& exemplar, const ExemplarFitOptions& options);

}  // namespace shapeproc::fit
