// The fitted model checked where it will be used (docs/fit.md, "Density on the output's scale").
// A model fitted on a small window can reproduce the exemplar's density there and not on a larger
// domain: an attraction that a window's edges hold in check condenses on a torus of four windows,
// and an estimate that the pseudo-likelihood could not bound (a packed exemplar) leaves β far off.
// So, before a fit is returned, chains from empty on a torus `multiple` times the exemplar's window
// along x and y (a 3D exemplar keeps its depth: a layer, extended sideways), sampled as an output
// is (fit/output_sampling.hpp), measure each category's density against the exemplar's, and the
// model is corrected until they agree:
//   - a chain that runs away (sample/runaway.hpp) halves every log γ > 0 (shrinks the attraction
//     towards 1) and the check runs again;
//   - an anchored category (fit/category_layers.hpp) is measured per base: its ratio over its
//     base category's, since its count follows the bases' and its β sets how many each carries;
//   - otherwise each category whose density is off by more than the tolerance has β_c multiplied
//     by exemplar density / chain density (clamped to [1/8, 8]): the counts' moment equation that
//     the maximum likelihood solves, solved on the larger domain by a few fixed-point steps; once
//     a β too low and one too high are known, the next step halves that bracket in log β.
// A check that never agrees keeps the β of its closest chain (by its worst category's ratio, in
// log): a lattice whose crystal packs denser than its exemplar, say, has no β that gives the
// exemplar's count. The record (model::CalibrationRecord) keeps the ratios before and after (the
// chain kept) and the corrections.
#pragma once

#include <cstdint>
#include <functional>

#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

struct CalibrationOptions {
  // The torus: the exemplar's window times this along x and y (3D: the depth as it is).
  double multiple = kFitDefaults.calibration_multiple;
  // A category's density agrees when its ratio to the exemplar's is within this, or within two
  // Monte Carlo standard errors of the chain's mean count (from its effective sample size; two
  // Poisson standard errors, 2 / √expected, for a chain too short to tell), whichever is wider.
  double tolerance = kFitDefaults.calibration_tolerance;
  // Chains at most (each correction is followed by a chain that checks it).
  int rounds = kFitDefaults.calibration_rounds;
  std::uint64_t seed = 1;
  int threads = 0;  // of each chain (0: one per core); the result does not depend on them
  // Called before each chain with its number (1-based) and the most there may be.
  std::function<void(int round, int rounds)> progress;
};

// Checks `model` (fitted to `exemplar`, which gives the densities) and corrects it in place.
model::CalibrationRecord calibrate_density(model::ShapeProcessModel& model,
                                           const geometry::Scene& exemplar,
                                           const CalibrationOptions& options);

}  // namespace shapeproc::fit
