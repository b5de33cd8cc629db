#include "libshapeproc/geometry/element_neighbourhood.hpp"

#include <algorithm>
#include <tuple>

namespace shapeproc::geometry {

namespace {

std::vector<Vec3> positions_of(const std::vector<Element>& elements) {
  std::vector<Vec3> out;
  out.reserve(elements.size());
  for (const Element& e : elements) out.push_back(e.position);
  return out;
}

std::vector<int> keys_of(const std::vector<Element>& elements, const std::vector<int>& map) {
  std::vector<int> out;
  out.reserve(elements.size());
  for (const Element& e : elements)
    out.push_back(map.empty() ? e.category : map[static_cast<std::size_t>(e.category)]);
  return out;
}

}  // namespace

NeighbourhoodIndex::NeighbourhoodIndex(const std::vector<Element>& elements, const Domain& domain,
                                       double radius, const std::vector<int>& category_map)
    : NeighbourhoodIndex(positions_of(elements), keys_of(elements, category_map), {}, domain,
                         radius) {}

NeighbourhoodIndex::NeighbourhoodIndex(std::vector<Vec3> positions, std::vector<int> keys,
                                       std::vector<int> attributes, const Domain& domain,
                                       double radius)
    : positions_(std::move(positions)),
      keys_(std::move(keys)),
      attributes_(std::move(attributes)),
      domain_(domain),
      radius_(radius),
      grid_(domain.box(), domain.dimension(), radius, domain.periodic()) {
  if (keys_.empty()) keys_.assign(positions_.size(), 0);
  if (attributes_.empty()) attributes_.assign(positions_.size(), 0);
  for (std::size_t i = 0; i < positions_.size(); ++i)
    grid_.insert(static_cast<int>(i), positions_[i]);
}

Neighbourhood NeighbourhoodIndex::around(const Vec3& position, int skip) const {
  Neighbourhood out;
  grid_.for_each_candidate(position, [&](int j) {
    if (j == skip) return;
    const std::size_t k = static_cast<std::size_t>(j);
    const Vec3 t = domain_.minimum_image(positions_[k] - position);
    if (t.norm() >= radius_) return;
    out.push_back({t, keys_[k], j, attributes_[k]});
  });
  std::sort(out.begin(), out.end(),
            [](const Neighbour& a, const Neighbour& b) { return a.element < b.element; });
  return out;
}

Neighbourhood NeighbourhoodIndex::of(std::size_t centre) const {
  return around(positions_[centre], static_cast<int>(centre));
}

namespace {

// The greedy pairing's candidates: (squared distance, output index, exemplar index), ascending.
std::vector<std::tuple<double, int, int>> candidate_pairs(const Neighbourhood& output,
                                                          const Neighbourhood& exemplar,
                                                          double cap) {
  std::vector<std::tuple<double, int, int>> candidates;
  for (std::size_t a = 0; a < output.size(); ++a) {
    for (std::size_t b = 0; b < exemplar.size(); ++b) {
      if (output[a].key != exemplar[b].key || output[a].key < 0) continue;
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
                              double radius, double alpha) {
  const double cap = radius * radius;
  double sum = 0.0;
  std::size_t paired = 0;
  std::vector<bool> used_output(output.size(), false), used_exemplar(exemplar.size(), false);
  for (const auto& [c, a, b] : candidate_pairs(output, exemplar, cap)) {
    if (used_output[static_cast<std::size_t>(a)] || used_exemplar[static_cast<std::size_t>(b)])
      continue;
    used_output[static_cast<std::size_t>(a)] = used_exemplar[static_cast<std::size_t>(b)] = true;
    sum += alpha > 0.0 ? pair_cost(output[static_cast<std::size_t>(a)],
                                   exemplar[static_cast<std::size_t>(b)], radius, alpha)
                       : c;
    if (++paired == output.size()) break;
  }
  return sum + static_cast<double>(output.size() - paired) * cap;
}

}  // namespace shapeproc::geometry
