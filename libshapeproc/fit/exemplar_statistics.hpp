// The data side of the log pseudo-likelihood (docs/mathematics.md, "Maximum pseudo-likelihood"
// and "Edge treatment"): the region whose points contribute, each exemplar element's statistic
// t(z_n | z \ z_n), their sum over the elements inside the region, and the pairs observed in each
// band.
#pragma once

#include <vector>

#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

// The window of the sums: W, or W eroded by the interaction range R for the border correction.
// The region whose elements and quadrature points count. For the border treatment, an element at
// the border distance up to rounding counts as inside: positions within `tolerance` (1e-9 of the
// window's longest side) outside the eroded box are kept, so that 1 − 0.9 < 0.1 in floating
// point does not drop a point drawn exactly at the border distance (docs/fit.md).
struct FitRegion {
  geometry::Box3 box;
  int dimension = 2;
  double tolerance = 0.0;
  bool contains(const geometry::Vec3& p) const {
    for (int axis = 0; axis < dimension; ++axis)
      if (p[axis] < box.min()[axis] - tolerance || p[axis] > box.max()[axis] + tolerance)
        return false;
    return true;
  }
};

// Throws core::ArgumentError when the border treatment leaves no window.
FitRegion fit_region(const geometry::Scene& exemplar, geometry::EdgeTreatment edge, double range);

struct ExemplarStatistics {
  std::vector<model::InteractionCounts> per_element;  // t(z_n | z \ z_n), every element
  // Every element's own count of neighbours t_n(z) in each saturated band (model/saturation.hpp);
  // empty without saturated bands.
  std::vector<model::InteractionCounts> own_saturated;
  std::vector<double> data_sum;   // Σ_n t(z_n) over the region, β entries included
  std::vector<int> per_category;  // elements of each category inside the region
  int data_points = 0;            // elements inside the region
};

// The statistics of the exemplar's pairs under `interaction`; counts the pairs of each band into
// model.interactions[...].observed_pairs. Throws core::ArgumentError when a pair lies below its
// hard-core distance or the region keeps no element of a category.
ExemplarStatistics exemplar_statistics(const geometry::Scene& exemplar,
                                       const std::vector<geometry::PairRecord>& pairs,
                                       const model::Interaction& interaction,
                                       const FitRegion& region, model::ShapeProcessModel& model);

}  // namespace shapeproc::fit
