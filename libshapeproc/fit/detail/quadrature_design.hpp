// The quadrature side of the log pseudo-likelihood (docs/mathematics.md, "Maximum
// pseudo-likelihood"; Baddeley & Turner 2000): a grid of cells tiling the fit region, each cell
// crossed with m shapes of S_c (all, or m in rotation), each dummy integrated over its cell
// (quadrature_cell.hpp) or, with lines, along its row (line_quadrature.hpp), with weight (1 −
// κ)|cell| / m; and the n_c data points of category c with κ|W| / n_c each (κ =
// options.data_weight). The weights still sum to |W|, every observed statistic has exposure, and
// the share does not shrink with the cells, so the maximum has a limit as they are refined even on
// exemplars whose continuum LPL has no finite maximum (docs/fit.md).
#pragma once

#include <vector>

#include "libshapeproc/fit/exemplar_statistics.hpp"
#include "libshapeproc/fit/pseudo_likelihood.hpp"
#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::fit {

struct QuadratureDesign {
  PseudoLikelihoodDesign design;  // data points first, then the dummies' pieces; not merged
  std::size_t data_points = 0;    // the first data_points points are the data points
  int cells = 0;
  int cells_along = 0;  // along the region's longest side
  bool lines = false;   // rows of cells integrated as exact lines
};

// The design for `exemplar` (its statistics in `statistics`), integrated on FitOptions::threads
// threads (the result does not depend on the thread count). `window`: the exemplar's window as a
// domain, a torus for the periodic edge treatment.
QuadratureDesign quadrature_design(const geometry::Scene& exemplar, const FitOptions& options,
                                   const FitRegion& region, const geometry::PairMeasurer& measurer,
                                   const model::Interaction& interaction,
                                   const ExemplarStatistics& statistics,
                                   const std::vector<std::vector<int>>& shapes_of,
                                   const geometry::Domain& window);

// The same design with the data points' share multiplied by `factor` (the dummies' share scaled
// so the weights still sum to |W|).
PseudoLikelihoodDesign with_data_share(const QuadratureDesign& quadrature, double data_weight,
                                       double factor);

// Points with the same category and statistics contribute w·exp(θ·t) with the same t: merged
// (most dummies see no neighbour or the same few), in a deterministic order.
void merge_equal_points(PseudoLikelihoodDesign& design);

}  // namespace shapeproc::fit
