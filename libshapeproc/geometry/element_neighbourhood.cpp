#include "libshapeproc/geometry/element_neighbourhood.hpp"

#include <algorithm>
#include <tuple>

namespace shapeproc::geometry {

NeighbourhoodIndex::NeighbourhoodIndex(const std::vector<Element>& elements, const Domain& domain,
                                       double radius, std::vector<int> category_map)
    : elements_(elements),
      domain_(domain),
      radius_(radius),
      category_map_(std::move(category_map)),
      grid_(domain.box(), domain.dimension(), radius, domain.periodic()) {
  for (std::size_t i = 0; i < elements.size(); ++i)
    grid_.insert(static_cast<int>(i), elements[i].position);
}

Neighbourhood NeighbourhoodIndex::around(const Vec3& position, int skip) const {
  Neighbourhood out;
  grid_.for_each_candidate(position, [&](int j) {
    if (j == skip) return;
    const Element& other = elements_[static_cast<std::size_t>(j)];
    const Vec3 t = domain_.minimum_image(other.position - position);
    if (t.norm() >= radius_) return;
    const int category = category_map_.empty()
                             ? other.category
                             : category_map_[static_cast<std::size_t>(other.category)];
    out.push_back({t, category, j});
  });
  std::sort(out.begin(), out.end(),
            [](const Neighbour& a, const Neighbour& b) { return a.element < b.element; });
  return out;
}

Neighbourhood NeighbourhoodIndex::of(std::size_t centre) const {
  return around(elements_[centre].position, static_cast<int>(centre));
}

namespace {

// The greedy pairing's candidates: (squared distance, output index, exemplar index), ascending.
std::vector<std::tuple<double, int, int>> candidate_pairs(const Neighbourhood& output,
                                                          const Neighbourhood& exemplar,
                                                          double cap) {
  std::vector<std::tuple<double, int, int>> candidates;
  for (std::size_t a = 0; a < output.size(); ++a) {
    for (std::size_t b = 0; b < exemplar.size(); ++b) {
      if (output[a].category != exemplar[b].category || output[a].category < 0) continue;
      const double c = (output[a].offset - exemplar[b].offset).squaredNorm();
      if (c < cap) candidates.emplace_back(c, static_cast<int>(a), static_cast<int>(b));
    }
  }
  std::sort(candidates.begin(), candidates.end());
  return candidates;
}

}  // namespace

std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const Neighbourhood& exemplar,
                                                      double radius) {
  std::vector<std::pair<int, int>> pairs;
  std::vector<bool> used_output(output.size(), false), used_exemplar(exemplar.size(), false);
  for (const auto& [c, a, b] : candidate_pairs(output, exemplar, radius * radius)) {
    if (used_output[static_cast<std::size_t>(a)] || used_exemplar[static_cast<std::size_t>(b)])
      continue;
    used_output[static_cast<std::size_t>(a)] = used_exemplar[static_cast<std::size_t>(b)] = true;
    pairs.emplace_back(a, b);
    if (pairs.size() == output.size()) break;
  }
  return pairs;
}

double neighbourhood_distance(const Neighbourhood& output, const Neighbourhood& exemplar,
                              double radius) {
  const double cap = radius * radius;
  double sum = 0.0;
  std::size_t paired = 0;
  std::vector<bool> used_output(output.size(), false), used_exemplar(exemplar.size(), false);
  for (const auto& [c, a, b] : candidate_pairs(output, exemplar, cap)) {
    if (used_output[static_cast<std::size_t>(a)] || used_exemplar[static_cast<std::size_t>(b)])
      continue;
    used_output[static_cast<std::size_t>(a)] = used_exemplar[static_cast<std::size_t>(b)] = true;
    sum += c;
    if (++paired == output.size()) break;
  }
  return sum + static_cast<double>(output.size() - paired) * cap;
}

}  // namespace shapeproc::geometry
