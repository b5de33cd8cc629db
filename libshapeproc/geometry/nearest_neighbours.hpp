// Each point's nearest others, found through a grid: the offsets (minimum image on a torus) to
// its `count` nearest, nearest first. The grid's cells start at twice the mean spacing and double
// for the points whose nearest are not yet certain (fewer than `count` others within a cell), so
// that a query visits a few cells, not every point.
#pragma once

#include <cstddef>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::geometry {

struct NearestNeighbour {
  std::size_t index;  // of the other point
  Vec3 offset;        // from the point to it
};

// Per point, up to `count` neighbours (fewer when there are not that many others), nearest first.
// Points lie in the domain's box (the grid clamps those outside to its border cells).
std::vector<std::vector<NearestNeighbour>> nearest_neighbours(const std::vector<Vec3>& points,
                                                              const Domain& domain,
                                                              std::size_t count);

// The same, offsets only.
std::vector<std::vector<Vec3>> nearest_offsets(const std::vector<Vec3>& points,
                                               const Domain& domain, std::size_t count);

}  // namespace shapeproc::geometry
