// Whether the maximum pseudo-likelihood estimate exists (docs/fit.md): the fit maximises again
// on the same quadrature with ten times the data points' share. Where the continuum LPL has a
// maximum, the tiny share hardly moves it (below 0.3% on the shipped exemplars that have one);
// where it has none (packed exemplars: no location with the data's neighbourhoods has positive
// measure), the share alone holds the maximum and the estimates follow it (90–170%). Parameters
// whose logarithm moves by more than 0.01 are marked unbounded.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/fit/detail/quadrature_design.hpp"

namespace shapeproc::fit {

inline constexpr double kExistenceFactor = 10.0;
inline constexpr double kExistenceTolerance = 0.01;

// Whether the check can run at this share (κ > 0 and 10κ < 1).
bool can_check_existence(double data_weight);

// Maximises `heavier` (the design with ten times the share, merged) from mple.theta and marks the
// free parameters that move as unbounded in mple.status. Returns whether any did.
bool check_existence(const PseudoLikelihoodDesign& heavier, MpleResult& mple);

// The notes that explain unbounded parameters: those that follow the data points' share, and
// those left at the search bound by separated statistics.
void add_existence_notes(const MpleResult& mple, bool follows_share,
                         std::vector<std::string>& notes);

}  // namespace shapeproc::fit
