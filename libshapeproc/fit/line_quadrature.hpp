// Quadrature of the conditional intensity along lines, exact along each line.
//
// The conditional intensity of a dummy (shape s at u) is piecewise constant in u. Along a line
// u = start + x e_0 it changes where the distance to a neighbour crosses a threshold or where the
// relative orientation crosses a sector boundary. The distance is 1-Lipschitz in u, so marching
// by the gap to the nearest threshold never steps over a crossing (sphere tracing); sector
// changes are caught by steps no longer than a fraction of the sector's width at the pair's
// separation, or any length the boxes' direction cone guarantees. Each change is then located by
// bisection to `tolerance`. The result is the exact measure (to the tolerance) of every
// statistic along the line; a midpoint rule across lines integrates over the window, with an
// error that shrinks faster than the first order of cell midpoints (docs/fit.md).
#pragma once

#include <utility>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

struct LineContext {
  const model::Interaction* interaction = nullptr;
  const geometry::PairMeasurer* measurer = nullptr;
  const std::vector<geometry::Element>* data = nullptr;
  int dimension = 2;
  geometry::Vec3 period =
      geometry::Vec3::Zero();  // window sizes when periodic (minimum image), else 0
  double tolerance = 1e-6;     // length to which changes are located
};

struct LinePiece {
  double length = 0.0;                      // measure along the line with these statistics
  std::vector<std::pair<int, int>> counts;  // (θ index, count), sorted
};

// Pieces of the line {start + x e_0 : 0 ≤ x ≤ length} where shape `shape` of `category` has
// λ > 0 (hard-core stretches left out), one piece per distinct statistic.
std::vector<LinePiece> integrate_line(const LineContext& context, int category, int shape,
                                      const geometry::Vec3& start, double length);

}  // namespace shapeproc::fit
