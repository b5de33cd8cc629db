// Fitting a seamless tile. On its own torus a small tile's elements are their own images, so a
// tile of fewer than 8 elements is fitted repeated (geometry::tile_repeats). After the fit, the
// repeat must hold the fitted interactions: a pair farther apart than half the torus's side is
// seen at a nearer image, the fit counts it as another pair, and bands the outputs fill get γ = 0
// (leaf, 3 × 3 repeats of 80 × 40, lost a fifth of an output's repeated tile). Such a tile is
// fitted again, once, on a repeat that holds them (geometry::repeats_to_hold, at most
// kMaxTileRepeats). Larger tiles are fitted once on their own torus: refitted 2 × 2 or 3 × 3,
// happy-intersection (45 elements) and random-shapes (24) gave MLE fits that did not converge and
// outputs of ×0.01 and ×1.29 against ×0.96 and ×0.97.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::fit {

// The most repeats a tile is refitted on (fit_defaults.hpp).
constexpr int kMaxTileRepeats = kFitDefaults.max_tile_repeats;

struct TileFit {
  FitResult result;
  geometry::Scene exemplar;  // the tile as fitted (repeated `repeats` × `repeats`)
  int repeats = 1;
  std::vector<std::string> notes;  // a refit, or one that would need too many repeats
};

// Fits `tile` (2D) with `fit_scene(exemplar, repeats)`, repeated as above, then, when `refine` is
// given, refines that fit with `refine(exemplar, repeats, fit)` (the maximum likelihood). The
// interactions' reach depends on the thresholds alone, so the repeat is chosen before the costly
// refinement, which runs once.
TileFit fit_tile(
    const geometry::Scene& tile,
    const std::function<FitResult(const geometry::Scene&, int)>& fit_scene,
    const std::function<FitResult(const geometry::Scene&, int, FitResult)>& refine = {});

}  // namespace shapeproc::fit
