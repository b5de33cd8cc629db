// Average neighbourhood distance (Davison et al. 2018, eq. 5) with the neighbourhood metric of
// Ma et al. 2011 (eq. 1): the yardstick every synthesis method can be compared on.
//
// For an element o of the output, n(o) holds the other elements whose reference positions lie
// within the radius r of o's (minimum image on a torus), as offsets p(o') − p(o). Its distance to
// an exemplar neighbourhood n(e) (e of o's category) is
//     |n(o) − n(e)| = Σ_{o' ∈ n(o)} min(|p̂(o') − p̂(e')|², r²),
// where o' is paired with an exemplar element e' of the same category by Ma's greedy rule (the
// closest remaining pair first); an o' left without a partner closer than r costs r². The exemplar
// side has no preset extent (every exemplar element can be a partner), as in Ma et al. The
// average neighbourhood distance is the mean over the output's elements of the smallest
// |n(o) − n(e)| over the exemplar's elements.
//
// A periodic exemplar smaller than the neighbourhoods' diameter is repeated first
// (geometry::repeat_to_reach), so that the nearest image does not hide further images.
// Elements whose neighbourhood reaches outside an open window are not used as centres (their
// neighbourhoods are cut), on either side, unless no element is far enough from the edge.
#pragma once

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::metrics {

struct NeighbourhoodDistance {
  double mean = 0.0;        // eq. 5, in squared length units
  double normalised = 0.0;  // mean / a², a the exemplar's mean spacing (|W| / n)^(1/dim)
  double radius = 0.0;      // r
  int output_centres = 0;
  int exemplar_centres = 0;
  double mean_neighbours = 0.0;  // mean |n(o)| over the output centres
};

// `radius` 0 means twice the exemplar's mean spacing (a 2-ring neighbourhood, Davison et al. §6).
// Throws std::invalid_argument when either scene is empty or their dimensions differ.
NeighbourhoodDistance average_neighbourhood_distance(const geometry::Scene& output,
                                                     geometry::Boundary output_boundary,
                                                     const geometry::Scene& exemplar,
                                                     geometry::Boundary exemplar_boundary,
                                                     double radius = 0.0);

}  // namespace shapeproc::metrics
