// Region growing's density, calibrated. Growth fills every free-space point whose bounding
// circle fits, so the output's density is set by the bounding radii, not by the exemplar: with
// the automatic radii (half each exemplar element's nearest distance) a sparse, irregular
// exemplar grows about twice as dense, because its closest pairs give small circles that then
// pack everywhere (Davison et al. 2018 §6.1: "if it is too small, it will lead to crowded output").
// Larger circles would forbid those close pairs. The calibration instead limits how many
// elements a copy's neighbourhood (a ball of the neighbourhood radius around it) may already
// hold: c times the exemplar's mean count in such a ball. A first pilot growth, on a torus
// holding about kPilotElements elements of the exemplar's density, runs without the limit; where
// it comes out within kCalibrationTolerance of the exemplar's density, or sparser, there is none.
// Otherwise the pilots start at c = 1 and take c / (density ratio) next (the density follows the
// limit once it binds), until one is within the tolerance or after kMostPilots; the output grows
// with the closest pilot's c. Palettes and radii given by hand (GrowthOptions::bounding_radius)
// are not calibrated.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
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
inline constexpr double kFewestNeighbours = 0.25;  // the smallest c tried

struct DensityCalibration {
  // c, the limit on a copy's neighbours over the exemplar's mean count; infinite: no limit.
  double crowding = std::numeric_limits<double>::infinity();
  struct Pilot {
    double crowding = std::numeric_limits<double>::infinity();
    double ratio = 1.0;  // the pilot's density over the exemplar's
  };
  std::vector<Pilot> pilots;    // in the order grown; empty when not calibrated
  std::string summary() const;  // "×0.84 (3 pilots: …)", "none (1 pilot: …)" or "not calibrated"
};

// Grows the exemplar over a domain with the limit c (infinite: none) and returns how many
// elements it made.
using PilotGrowth = std::function<std::size_t(double, const geometry::Domain&, core::Random&)>;

// The calibration for an output on `output` (its dimension; the pilots' torus is no larger than
// it). Draws the pilots' seed from `random`.
DensityCalibration calibrate_density(const GrowthExemplar& exemplar, const GrowthOptions& options,
                                     const geometry::Domain& output, core::Random& random,
                                     const PilotGrowth& grow);

}  // namespace shapeproc::methods
