// Each point's nearest others, found through a grid: the offsets (minimum image on a torus) to
// its `count` nearest, nearest first. The grid's cells start at twice the mean spacing and double
// for the points whose nearest are not yet certain (fewer than `count` others within a cell), so
// that a query visits a few cells, not every point.
#pragma once

#include <cstddef>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::geometry {

// Per point, up to `count` offsets (fewer when there are not that many others), nearest first.
// Points lie in the domain's box (the grid clamps those outside to its border cells).
std::vector<std::vector<Vec3>> nearest_offsets(const std::vector<Vec3>& points,
                                               const Domain& domain, std::size_t count);

}  // namespace shapeproc::geometry
