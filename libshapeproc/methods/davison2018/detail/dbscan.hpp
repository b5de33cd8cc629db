// Density-based clustering (DBSCAN, Ester et al. 1996), as Davison et al. 2018 use it to reduce
// free-space vectors: a point with at least `min_points` points (itself included) within `eps`
// is a core point; clusters are the core points connected through such neighbourhoods, with the
// border points they reach; the rest is noise. Points are visited in index order, so a border
// point reachable from two clusters joins the first (the labels do not depend on anything else).
#pragma once

#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::methods {

inline constexpr int kNoise = -1;

// Per point: its cluster (0, 1, ... in order of discovery) or kNoise. O(n²): for the few hundred
// vectors of one element's similar neighbourhoods.
std::vector<int> dbscan(const std::vector<geometry::Vec3>& points, double eps, int min_points);

}  // namespace shapeproc::methods
