#include "libshapeproc/fit/neighbour_offsets.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::fit {

namespace {

struct Neighbour {
  double squared;
  int index;
  geometry::Vec3 offset;
};

// Each element's `k` nearest neighbours (fewer when the exemplar has fewer), nearest first.
std::vector<std::vector<Neighbour>> nearest_neighbours(const geometry::Scene& exemplar,
                                                       const geometry::Vec3& period, int k) {
  const std::vector<geometry::Element>& elements = exemplar.elements;
  std::vector<std::vector<Neighbour>> out(elements.size());
  for (std::size_t i = 0; i < elements.size(); ++i) {
    std::vector<Neighbour>& list = out[i];
    for (std::size_t j = 0; j < elements.size(); ++j) {
      if (j == i) continue;
      const geometry::Vec3 t =
          geometry::minimum_image(elements[j].position - elements[i].position, period);
      list.push_back({t.squaredNorm(), static_cast<int>(j), t});
    }
    const std::size_t keep = std::min(list.size(), static_cast<std::size_t>(k));
    std::partial_sort(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(keep), list.end(),
                      [](const Neighbour& a, const Neighbour& b) {
                        return a.squared != b.squared ? a.squared < b.squared : a.index < b.index;
                      });
    list.resize(keep);
  }
  return out;
}

// A single element on a torus is its own neighbour at the lattice vectors: its images along each
// axis and the diagonals.
std::vector<Neighbour> own_images(const geometry::Vec3& period, int dimension) {
  std::vector<Neighbour> out;
  const int z_reach = dimension == 3 ? 1 : 0;
  for (int dz = -z_reach; dz <= z_reach; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        const geometry::Vec3 t(dx * period.x(), dy * period.y(), dz * period.z());
        out.push_back({t.squaredNorm(), 0, t});
      }
  std::stable_sort(out.begin(), out.end(),
                   [](const Neighbour& a, const Neighbour& b) { return a.squared < b.squared; });
  return out;
}

}  // namespace

model::NeighbourOffsets neighbour_offsets(const geometry::Scene& exemplar, bool periodic,
                                          const NeighbourOffsetOptions& options) {
  model::NeighbourOffsets result;
  const std::vector<geometry::Element>& elements = exemplar.elements;
  const geometry::Vec3 period =
      periodic ? geometry::Vec3(exemplar.window.sizes()) : geometry::Vec3::Zero();
  const int k = options.neighbours > 0 ? options.neighbours : (exemplar.dimension == 3 ? 6 : 4);
  std::vector<std::vector<Neighbour>> near = nearest_neighbours(exemplar, period, k);
  if (elements.size() == 1 && periodic) near[0] = own_images(period, exemplar.dimension);
  double sum = 0.0;
  int counted = 0;
  for (const auto& list : near)
    if (!list.empty()) {
      sum += std::sqrt(list.front().squared);
      ++counted;
    }
  if (counted == 0 || !(sum > 0)) return result;
  const double spacing = sum / counted;
  result.radii = {options.small_radius * spacing, options.large_radius * spacing};
  const auto kind = [&](const geometry::Element& e) {
    return exemplar.shapes.empty() ? e.category : e.shape;
  };
  // Per kind of element: its offsets, merged within the small radius.
  std::map<int, std::vector<model::NeighbourOffset>> by_kind;
  for (std::size_t i = 0; i < elements.size(); ++i)
    for (const Neighbour& n : near[i]) {
      const int from = kind(elements[i]);
      const int to = kind(elements[static_cast<std::size_t>(n.index)]);
      std::vector<model::NeighbourOffset>& list = by_kind[from];
      const auto same =
          std::find_if(list.begin(), list.end(), [&](const model::NeighbourOffset& o) {
            return o.to == to && (o.offset - n.offset).norm() < result.radii.front();
          });
      if (same != list.end())
        same->weight += 1.0;
      else
        list.push_back({from, to, n.offset, 1.0});
    }
  for (auto& [from, list] : by_kind) {
    std::stable_sort(list.begin(), list.end(),
                     [](const model::NeighbourOffset& a, const model::NeighbourOffset& b) {
                       return a.weight > b.weight;
                     });
    if (static_cast<int>(list.size()) > options.max_per_kind)
      list.resize(static_cast<std::size_t>(options.max_per_kind));
    result.offsets.insert(result.offsets.end(), list.begin(), list.end());
  }
  return result;
}

}  // namespace shapeproc::fit
