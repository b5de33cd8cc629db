// Where the exemplar's elements have their neighbours, for the sampler's births near neighbours
// (model::NeighbourOffsets; docs/mathematics.md, "Births near neighbours"). Steers proposals
// only: no parameter of the density comes from it.
#pragma once

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

struct NeighbourOffsetOptions {
  // Nearest neighbours per element (and each axis cone's nearest); 0: 4 in 2D, 6 in 3D.
  int neighbours = 0;
  int max_per_kind = 64;       // the heaviest offsets kept per kind of element
  double small_radius = 0.01;  // the proposal radii, as shares of the mean nearest-neighbour
  double large_radius = 0.1;   // distance
};

// For every element, its nearest neighbours by reference position (the nearest image on a
// `periodic` window), and the nearest in each cone around an axis (so that the offsets span the
// space, as a crystal grown from them must), each giving the offset from the element's kind (shape,
// or category for a point pattern) to the neighbour's. Offsets of one pair of kinds nearer each
// other than the small radius are merged (their weights, counts of pairs, summed). Empty for an
// exemplar without a neighbour (a single element on an open window).
model::NeighbourOffsets neighbour_offsets(const geometry::Scene& exemplar, bool periodic,
                                          const NeighbourOffsetOptions& options = {});

}  // namespace shapeproc::fit
