// The position half of the assignment step (Ma et al. 2011, §4.3, eq. 4): output sample positions
// that satisfy, in the least-squares sense, every offset the search predicted,
//     E_p = Σ (p(so) − p(s'o) − p̃(so, s'o))²   over the predictions,
// solved as the sparse positive definite system of the graph Laplacian (Eigen's conjugate
// gradients, each axis to a relative residual of kSolverTolerance). The unknowns are displacements
// from the current positions and every offset takes the minimum image, so the system is the same on
// a torus. A small ridge (kRidge per unit of the mean degree) fixes each connected group's free
// translation to no mean move, and keeps samples without predictions where they are.
#pragma once

#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/methods/common/neighbourhood_search.hpp"

namespace shapeproc::methods {

inline constexpr double kRidge = 1e-6;
inline constexpr double kSolverTolerance = 1e-10;
inline constexpr int kMaxSolverIterations = 10000;

// The displacement of each of the samples at `positions` that minimises E_p, each prediction
// weighted by its weight. `anchors` (empty, or one per sample) adds anchors[i] |d_i|² to E_p:
// a sample's pull towards where it is (growth holds its older elements so).
std::vector<Vec3> solve_positions(const std::vector<Vec3>& positions,
                                  const std::vector<Prediction>& predictions,
                                  const geometry::Domain& domain,
                                  const std::vector<double>& anchors = {});

// E_p at `positions` (for tests and the energy trace).
double position_energy(const std::vector<Vec3>& positions,
                       const std::vector<Prediction>& predictions, const geometry::Domain& domain);

}  // namespace shapeproc::methods
