// The statistic t(ξ | exemplar) at one location, measured pair by pair: what the quadrature
// evaluates where it samples points instead of integrating cells exactly (an anchored category's
// rings, fit/anchored_quadrature.hpp; the cells of a model with saturated bands, whose statistic
// depends on the neighbours' own counts, model/saturation.hpp).
#pragma once

#include <vector>

#include "libshapeproc/fit/exemplar_statistics.hpp"
#include "libshapeproc/fit/quadrature_cell.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

class PointCounter {
 public:
  // `statistics`: the exemplar's, whose own counts in saturated bands the counts read (may be
  // null for a model without saturated bands). The references must outlive the counter.
  PointCounter(const geometry::Scene& exemplar, bool periodic,
               const geometry::PairMeasurer& measurer, const model::Interaction& interaction,
               const ExemplarStatistics* statistics);

  // t(ξ | exemplar) into `counts`; false where λ(ξ) is 0: a hard core, or an anchored category
  // off every base.
  bool counts(const geometry::Element& xi, model::InteractionCounts& counts) const;

 private:
  const std::vector<geometry::Element>& data_;
  const geometry::PairMeasurer& measurer_;
  const model::Interaction& interaction_;
  const ExemplarStatistics* statistics_;
  double reach_ = 0.0;
  geometry::NeighbourGrid grid_;
};

// A cell of `sizes` centred on ξ's position sampled at the k^d centres of a regular sub-grid
// (ξ's category and shape at each): one part of fraction 1/k^d per point where λ is not 0.
std::vector<CellPart> sampled_cell(const PointCounter& counter, const geometry::Element& xi,
                                   const geometry::Vec3& sizes, int dimension, int k);

}  // namespace shapeproc::fit
