// Region growing's density, calibrated. Growth fills every free-space point whose bounding
// circle fits, so the output's density is set by the bounding radii, not by the exemplar: with
// the automatic radii (half each exemplar element's nearest distance) a sparse, irregular
// exemplar grows about twice as dense, because its closest pairs give small circles that then
// pack everywhere (Davison et al. 2018 §6.1: "if it is too small, it will lead to crowded output").
// The calibration chooses the scale s ≥ 1 of the automatic radii at which the growth reproduces
// the exemplar's density: pilot growths on a torus holding about kPilotElements elements of the
// exemplar's density, each at the scale s·(ratio)^(1/d) of the one before (the density of
// packed circles goes as r^−d), stopping within kCalibrationTolerance or after kMostPilots. The
// radii only ever grow (a smaller circle would let elements overlap), so an output already as
// sparse as its exemplar keeps them. Radii given by hand (GrowthOptions::bounding_radius) and
// palettes are not calibrated.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/methods/davison2018/growth_analysis.hpp"
#include "libshapeproc/methods/davison2018/growth_state.hpp"

namespace shapeproc::methods {

inline constexpr double kPilotElements = 300.0;
inline constexpr double kCalibrationTolerance = 0.05;  // |density ratio − 1| accepted
inline constexpr int kMostPilots = 6;
inline constexpr double kLargestRadiusScale = 4.0;

struct DensityCalibration {
  double scale = 1.0;  // of the automatic bounding radii
  struct Pilot {
    double scale = 1.0;
    double ratio = 1.0;  // the pilot's density over the exemplar's
  };
  std::vector<Pilot> pilots;    // in the order grown; empty when not calibrated
  std::string summary() const;  // "×1.32 (4 pilots: ×2.21 at 1, …)" or "as given"
};

// Grows `exemplar` over a domain and returns how many elements it made.
using PilotGrowth =
    std::function<std::size_t(const GrowthExemplar&, const geometry::Domain&, core::Random&)>;

// The calibration for an output on `output` (its dimension; the pilots' torus is no larger than
// it). Draws the pilots' seed from `random`.
DensityCalibration calibrate_density(const GrowthExemplar& exemplar, const GrowthOptions& options,
                                     const geometry::Domain& output, core::Random& random,
                                     const PilotGrowth& grow);

// `exemplar` with every bounding radius, and the radius of every free-space vector, times `scale`.
GrowthExemplar with_scaled_radii(const GrowthExemplar& exemplar, double scale);

}  // namespace shapeproc::methods
