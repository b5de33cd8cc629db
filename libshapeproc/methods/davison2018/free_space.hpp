// Free space (Davison et al. 2018, §5.1): where, around an element copied from exemplar element
// e, new elements may come. For each of the k exemplar neighbourhoods most similar to e's,
// co(e), the offsets of their neighbours are gathered,
//     free(e) = { p(c') − p(c) : c' ∈ n(c), c ∈ co(e) },
// and reduced by DBSCAN to the centroids of their clusters. Each free-space vector carries the
// mean bounding radius of the neighbours in its cluster: a free-space point is free while no
// element's bounding circle (sphere) overlaps it.
#pragma once

#include <vector>

#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/k_coherence.hpp"

namespace shapeproc::methods {

struct FreeSpaceVector {
  Vec3 offset = Vec3::Zero();
  double radius = 0.0;
};

// Per exemplar sample. `radius`: each exemplar sample's bounding radius; clusters of offsets
// within `eps` with at least `min_points` members become their centroid, and each noise point
// stays as it is (a place one similar neighbourhood had a neighbour is still a place to grow).
std::vector<std::vector<FreeSpaceVector>> free_space_vectors(const EmExemplar& exemplar,
                                                             const SimilaritySets& sets,
                                                             const std::vector<double>& radius,
                                                             double eps, int min_points);

}  // namespace shapeproc::methods
