#include "libshapeproc/fit/neighbour_offsets.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/nearest_neighbours.hpp"

namespace shapeproc::fit {

namespace {

// A single element on a torus is its own neighbour at the lattice vectors: its images along each
// axis and the diagonals, nearest first.
std::vector<geometry::NearestNeighbour> own_images(const geometry::Vec3& period, int dimension) {
  std::vector<geometry::NearestNeighbour> out;
  const int z_reach = dimension == 3 ? 1 : 0;
  for (int dz = -z_reach; dz <= z_reach; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        out.push_back({0, geometry::Vec3(dx * period.x(), dy * period.y(), dz * period.z())});
      }
  std::stable_sort(out.begin(), out.end(),
                   [](const geometry::NearestNeighbour& a, const geometry::NearestNeighbour& b) {
                     return a.offset.squaredNorm() < b.offset.squaredNorm();
                   });
  return out;
}

// Candidates looked at per element for the cones' nearest neighbours.
constexpr std::size_t kCandidates = 16;

// Of an element's neighbours (nearest first), the `k` nearest and the nearest in each cone around
// an axis (the neighbours whose offset is largest along that axis, one cone per sign): offsets
// that span the space, so that a crystal grown from them fills it (groovy's elements stand in
// rows 12 px apart, and their 4 nearest neighbours are all in their row, the next row 40 px up).
std::vector<geometry::NearestNeighbour> spanning(
    const std::vector<geometry::NearestNeighbour>& nearest_first, std::size_t k, int dimension) {
  std::vector<geometry::NearestNeighbour> kept;
  std::vector<bool> cone_filled(2 * static_cast<std::size_t>(dimension), false);
  for (std::size_t i = 0; i < nearest_first.size(); ++i) {
    const geometry::Vec3& d = nearest_first[i].offset;
    int axis = 0;
    for (int a = 1; a < dimension; ++a)
      if (std::abs(d[a]) > std::abs(d[axis])) axis = a;
    const std::size_t cone = 2 * static_cast<std::size_t>(axis) + (d[axis] < 0 ? 1 : 0);
    const bool first_in_cone = !cone_filled[cone];
    cone_filled[cone] = true;
    if (i < k || first_in_cone) kept.push_back(nearest_first[i]);
  }
  return kept;
}

}  // namespace

model::NeighbourOffsets neighbour_offsets(const geometry::Scene& exemplar, bool periodic,
                                          const NeighbourOffsetOptions& options) {
  model::NeighbourOffsets result;
  const std::vector<geometry::Element>& elements = exemplar.elements;
  const bool lone = elements.size() == 1 && periodic;
  const geometry::Vec3 period =
      periodic ? geometry::Vec3(exemplar.window.sizes()) : geometry::Vec3::Zero();
  const int k = options.neighbours > 0 ? options.neighbours : (exemplar.dimension == 3 ? 6 : 4);
  std::vector<geometry::Vec3> positions;
  for (const geometry::Element& e : elements) positions.push_back(e.position);
  std::vector<std::vector<geometry::NearestNeighbour>> near = geometry::nearest_neighbours(
      positions,
      geometry::Domain(exemplar.window, exemplar.dimension,
                       periodic ? geometry::Boundary::torus : geometry::Boundary::open),
      std::max(kCandidates, static_cast<std::size_t>(k)));
  if (lone) near[0] = own_images(period, exemplar.dimension);
  for (auto& list : near) list = spanning(list, static_cast<std::size_t>(k), exemplar.dimension);
  double sum = 0.0;
  int counted = 0;
  for (const auto& list : near)
    if (!list.empty()) {
      sum += list.front().offset.norm();
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
    for (const geometry::NearestNeighbour& n : near[i]) {
      const int from = kind(elements[i]);
      const int to = kind(elements[n.index]);
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
