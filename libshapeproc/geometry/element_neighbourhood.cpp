#include "libshapeproc/geometry/element_neighbourhood.hpp"

#include <algorithm>
#include <tuple>
#include <vector>

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

// One candidate pair of the greedy pairing: its squared distance and the two indices.
struct CandidatePair {
  double cost;
  int output, exemplar;
  bool operator<(const CandidatePair& other) const {
    if (cost != other.cost) return cost < other.cost;
    if (output != other.output) return output < other.output;
    return exemplar < other.exemplar;
  }
};

// Calls f(output index, exemplar index, squared distance) for each pair of Ma's greedy pairing,
// closest first. The candidate pairs (same key, nearer than r) are split at (r/4)²: the near ones
// are sorted and paired first, and the far ones only sorted, among those still free, when some
// output neighbour is left without a partner (the order of the pairs is unchanged). When the
// exemplar side is sorted by key (the neighbourhood EM's are), each output neighbour only visits
// its key's range. Buffers are reused by each thread.
template <class F>
void greedy_pairs(const Neighbourhood& output, const Neighbourhood& exemplar, double radius,
                  F&& f) {
  thread_local std::vector<CandidatePair> near, far;
  thread_local std::vector<char> used_output, used_exemplar;
  near.clear();
  far.clear();
  const double cap = radius * radius, split = cap / 16.0;
  const auto by_key = [](const Neighbour& a, const Neighbour& b) { return a.key < b.key; };
  const bool sorted = std::is_sorted(exemplar.begin(), exemplar.end(), by_key);
  for (std::size_t a = 0; a < output.size(); ++a) {
    const Neighbour& o = output[a];
    if (o.key < 0) continue;
    auto first = exemplar.begin(), last = exemplar.end();
    if (sorted) std::tie(first, last) = std::equal_range(first, last, o, by_key);
    for (auto it = first; it != last; ++it) {
      if (it->key != o.key) continue;
      const double c = (o.offset - it->offset).squaredNorm();
      if (c < cap)
        (c < split ? near : far)
            .push_back({c, static_cast<int>(a), static_cast<int>(it - exemplar.begin())});
    }
  }
  used_output.assign(output.size(), 0);
  used_exemplar.assign(exemplar.size(), 0);
  std::size_t paired = 0;
  const auto take = [&](const std::vector<CandidatePair>& pairs) {
    for (const CandidatePair& p : pairs) {
      const auto a = static_cast<std::size_t>(p.output), b = static_cast<std::size_t>(p.exemplar);
      if (used_output[a] || used_exemplar[b]) continue;
      used_output[a] = used_exemplar[b] = 1;
      f(p.output, p.exemplar, p.cost);
      if (++paired == output.size()) return;
    }
  };
  std::sort(near.begin(), near.end());
  take(near);
  if (paired == output.size() || far.empty()) return;
  far.erase(std::remove_if(far.begin(), far.end(),
                           [&](const CandidatePair& p) {
                             return used_output[static_cast<std::size_t>(p.output)] ||
                                    used_exemplar[static_cast<std::size_t>(p.exemplar)];
                           }),
            far.end());
  std::sort(far.begin(), far.end());
  take(far);
}

}  // namespace

std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const Neighbourhood& exemplar,
                                                      double radius) {
  std::vector<std::pair<int, int>> pairs;
  greedy_pairs(output, exemplar, radius, [&](int a, int b, double) { pairs.emplace_back(a, b); });
  return pairs;
}

double neighbourhood_distance(const Neighbourhood& output, const Neighbourhood& exemplar,
                              double radius, double alpha) {
  double sum = 0.0;
  std::size_t paired = 0;
  greedy_pairs(output, exemplar, radius, [&](int a, int b, double c) {
    sum += alpha > 0.0 ? pair_cost(output[static_cast<std::size_t>(a)],
                                   exemplar[static_cast<std::size_t>(b)], radius, alpha)
                       : c;
    ++paired;
  });
  return sum + static_cast<double>(output.size() - paired) * radius * radius;
}

}  // namespace shapeproc::geometry
