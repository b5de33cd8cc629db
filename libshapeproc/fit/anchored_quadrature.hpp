// The pseudo-likelihood's quadrature of an anchored category (docs/mathematics.md, "Layers").
// Its intensity is 0 except within its anchor reach of a base, a thin ring around each base for
// decorations on an edge: a grid of cells a few times wider than the ring resolves it poorly, and
// the integral of λ there is what fixes β. So the ring is integrated by Monte Carlo instead: for
// each exemplar element of the base category, points uniform in the disc of radius (the base's
// bounding radius + the anchored shapes' largest + the reach) about it, each of weight
// (disc area / points) / (number of such discs that hold it), so that the weights of a region
// covered by several discs sum to its area once. A point is kept where the intensity is not 0:
// inside the fit region (a torus wraps it), no hard core violated, on a base.
#pragma once

#include <vector>

#include "libshapeproc/fit/exemplar_statistics.hpp"
#include "libshapeproc/fit/point_counts.hpp"
#include "libshapeproc/fit/pseudo_likelihood.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

// The quadrature points of every anchored category of `interaction`, `per_base` per base element
// (drawn from a fixed seed: the same exemplar gives the same points), each point's statistic from
// `counter`. `window`: the exemplar's window as a domain (a torus for the periodic edge
// treatment).
std::vector<QuadraturePoint> anchored_quadrature(const geometry::Scene& exemplar,
                                                 const FitRegion& region,
                                                 const geometry::PairMeasurer& measurer,
                                                 const model::Interaction& interaction,
                                                 const std::vector<std::vector<int>>& shapes_of,
                                                 const geometry::Domain& window,
                                                 const PointCounter& counter, int per_base);

}  // namespace shapeproc::fit
