#include "libshapeproc/geometry/nearest_neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "libshapeproc/geometry/neighbour_grid.hpp"

namespace shapeproc::geometry {

std::vector<std::vector<NearestNeighbour>> nearest_neighbours(const std::vector<Vec3>& points,
                                                              const Domain& domain,
                                                              std::size_t count) {
  std::vector<std::vector<NearestNeighbour>> out(points.size());
  if (points.size() < 2 || count == 0) return out;
  const int dimension = domain.dimension();
  std::vector<std::size_t> short_of;
  for (std::size_t i = 0; i < points.size(); ++i) short_of.push_back(i);
  double cell =
      2.0 * std::pow(domain.measure() / static_cast<double>(points.size()), 1.0 / dimension);
  double largest = 0.0;  // the box's diagonal (a loop: GCC 12 misreads head(n).norm() here)
  for (int axis = 0; axis < dimension; ++axis)
    largest += domain.sizes()[axis] * domain.sizes()[axis];
  largest = std::sqrt(largest);
  std::vector<std::pair<double, NearestNeighbour>> near;
  while (!short_of.empty()) {
    NeighbourGrid grid(domain.box(), dimension, cell, domain.periodic());
    for (std::size_t i = 0; i < points.size(); ++i) grid.insert(static_cast<int>(i), points[i]);
    std::vector<std::size_t> still;
    for (const std::size_t i : short_of) {
      near.clear();
      grid.for_each_candidate(points[i], [&](int j) {
        if (static_cast<std::size_t>(j) == i) return;
        const Vec3 d = domain.minimum_image(points[static_cast<std::size_t>(j)] - points[i]);
        near.emplace_back(d.squaredNorm(), NearestNeighbour{static_cast<std::size_t>(j), d});
      });
      std::sort(near.begin(), near.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      // Only the candidates within the cell are sure to be the nearest.
      std::size_t sure = 0;
      while (sure < near.size() && near[sure].first <= cell * cell) ++sure;
      if (sure < count && cell < largest) {
        still.push_back(i);
        continue;
      }
      for (std::size_t k = 0; k < std::min(count, near.size()); ++k)
        out[i].push_back(near[k].second);
    }
    short_of = std::move(still);
    cell *= 2.0;
  }
  return out;
}

std::vector<std::vector<Vec3>> nearest_offsets(const std::vector<Vec3>& points,
                                               const Domain& domain, std::size_t count) {
  std::vector<std::vector<Vec3>> out;
  for (const auto& list : nearest_neighbours(points, domain, count)) {
    out.emplace_back();
    for (const NearestNeighbour& n : list) out.back().push_back(n.offset);
  }
  return out;
}

}  // namespace shapeproc::geometry
