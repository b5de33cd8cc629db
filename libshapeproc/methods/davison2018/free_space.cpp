#include "libshapeproc/methods/davison2018/free_space.hpp"

#include <map>
#include <utility>

#include "libshapeproc/methods/davison2018/detail/dbscan.hpp"

namespace shapeproc::methods {

std::vector<std::vector<FreeSpaceVector>> free_space_vectors(const EmExemplar& exemplar,
                                                             const SimilaritySets& sets,
                                                             const std::vector<double>& radius,
                                                             double eps, int min_points) {
  std::vector<std::vector<FreeSpaceVector>> out(exemplar.samples.size());
  for (std::size_t e = 0; e < out.size(); ++e) {
    std::vector<Vec3> offsets;
    std::vector<double> radii;
    for (const int c : sets.sets[e])
      for (const geometry::Neighbour& n : exemplar.near[static_cast<std::size_t>(c)]) {
        offsets.push_back(n.offset);
        radii.push_back(radius[static_cast<std::size_t>(n.element)]);
      }
    const std::vector<int> label = dbscan(offsets, eps, min_points);
    std::map<int, std::pair<FreeSpaceVector, int>> clusters;
    int lone = -1;  // a noise point is a cluster of its own
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      auto& [sum, count] = clusters[label[i] == kNoise ? lone-- : label[i]];
      sum.offset += offsets[i];
      sum.radius += radii[i];
      ++count;
    }
    for (const auto& [id, entry] : clusters) {
      const double n = static_cast<double>(entry.second);
      out[e].push_back({entry.first.offset / n, entry.first.radius / n});
    }
  }
  return out;
}

}  // namespace shapeproc::methods
