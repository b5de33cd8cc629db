#include "libshapeproc/geometry/element_neighbourhood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

// Ma's greedy pairing, closest pair first, calling f(output index, exemplar index, squared
// distance) for each pair. It runs in two phases split at (r/4)²: the near candidate pairs of
// every output neighbour (`near(a, visit)` calls visit(b) for a superset of its exemplar
// partners of its key nearer than r/4) are sorted and paired first; then, only for the output
// neighbours left without a partner, every other candidate of their key nearer than r
// (`all(a, visit)`), among the exemplar neighbours still free. The pairs and their order are
// those of one sort of every candidate. Buffers are reused by each thread.
//
// `bound`: once Σ over the output neighbours of a lower bound of their pair's cost (their
// nearest near candidate, else (r/4)²) reaches it, no pair is made and that sum is returned;
// otherwise the result is -1.
template <class Near, class All, class F>
double greedy_core(const Neighbourhood& output, const Neighbourhood& exemplar, double radius,
                   Near&& near_of, All&& all_of, F&& f, double bound) {
  thread_local std::vector<CandidatePair> near, far;
  thread_local std::vector<char> used_output, used_exemplar;
  near.clear();
  const double cap = radius * radius, split = cap / 16.0;
  double lower = 0.0;
  for (std::size_t a = 0; a < output.size(); ++a) {
    const Neighbour& o = output[a];
    double nearest = split;
    if (o.key >= 0) {
      near_of(a, [&](std::size_t b) {
        const Neighbour& e = exemplar[b];
        if (e.key != o.key) return;
        const double c = (o.offset - e.offset).squaredNorm();
        if (c < split) {
          near.push_back({c, static_cast<int>(a), static_cast<int>(b)});
          nearest = std::min(nearest, c);
        }
      });
    }
    lower += nearest;
    if (lower >= bound) return lower;
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
  if (paired == output.size()) return -1.0;
  far.clear();
  for (std::size_t a = 0; a < output.size(); ++a) {
    const Neighbour& o = output[a];
    if (used_output[a] || o.key < 0) continue;
    all_of(a, [&](std::size_t b) {
      const Neighbour& e = exemplar[b];
      if (used_exemplar[b] || e.key != o.key) return;
      const double c = (o.offset - e.offset).squaredNorm();
      if (c >= split && c < cap) far.push_back({c, static_cast<int>(a), static_cast<int>(b)});
    });
  }
  std::sort(far.begin(), far.end());
  take(far);
  return -1.0;
}

// The pairing against a plain neighbourhood: a scan of the exemplar side (of the key's range
// when it is sorted by key).
template <class F>
double greedy_pairs(const Neighbourhood& output, const Neighbourhood& exemplar, double radius,
                    F&& f, double bound = std::numeric_limits<double>::infinity()) {
  const auto by_key = [](const Neighbour& a, const Neighbour& b) { return a.key < b.key; };
  const bool sorted = std::is_sorted(exemplar.begin(), exemplar.end(), by_key);
  const auto scan = [&](std::size_t a, auto&& visit) {
    auto first = exemplar.begin(), last = exemplar.end();
    if (sorted) std::tie(first, last) = std::equal_range(first, last, output[a], by_key);
    for (auto it = first; it != last; ++it) visit(static_cast<std::size_t>(it - exemplar.begin()));
  };
  return greedy_core(output, exemplar, radius, scan, scan, f, bound);
}

// The pairing against an indexed neighbourhood: near partners from the grid.
template <class F>
double greedy_pairs(const Neighbourhood& output, const PairingNeighbourhood& exemplar,
                    double radius, F&& f, double bound = std::numeric_limits<double>::infinity()) {
  const auto near = [&](std::size_t a, auto&& visit) {
    exemplar.for_each_within(output[a].key, output[a].offset, 1, visit);
  };
  const auto all = [&](std::size_t a, auto&& visit) {
    exemplar.for_each_within(output[a].key, output[a].offset, 4, visit);
  };
  return greedy_core(output, exemplar.neighbours(), radius, near, all, f, bound);
}

template <class Exemplar>
double distance(const Neighbourhood& output, const Exemplar& exemplar,
                const Neighbourhood& partners, double radius, double alpha, double bound,
                std::vector<std::pair<int, int>>* pairs = nullptr) {
  double sum = 0.0;
  std::size_t paired = 0;
  if (pairs) pairs->clear();
  const double lower = greedy_pairs(
      output, exemplar, radius,
      [&](int a, int b, double c) {
        sum += alpha > 0.0 ? pair_cost(output[static_cast<std::size_t>(a)],
                                       partners[static_cast<std::size_t>(b)], radius, alpha)
                           : c;
        ++paired;
        if (pairs) pairs->emplace_back(a, b);
      },
      bound);
  if (lower >= 0.0) {
    if (pairs) pairs->clear();
    return lower;
  }
  return sum + static_cast<double>(output.size() - paired) * radius * radius;
}

}  // namespace

std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const Neighbourhood& exemplar,
                                                      double radius) {
  std::vector<std::pair<int, int>> pairs;
  greedy_pairs(output, exemplar, radius, [&](int a, int b, double) { pairs.emplace_back(a, b); });
  return pairs;
}

std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const PairingNeighbourhood& exemplar,
                                                      double radius) {
  std::vector<std::pair<int, int>> pairs;
  greedy_pairs(output, exemplar, radius, [&](int a, int b, double) { pairs.emplace_back(a, b); });
  return pairs;
}

double neighbourhood_distance(const Neighbourhood& output, const Neighbourhood& exemplar,
                              double radius, double alpha, double bound) {
  return distance(output, exemplar, exemplar, radius, alpha, bound);
}

double neighbourhood_distance(const Neighbourhood& output, const PairingNeighbourhood& exemplar,
                              double radius, double alpha, double bound,
                              std::vector<std::pair<int, int>>* pairs) {
  return distance(output, exemplar, exemplar.neighbours(), radius, alpha, bound, pairs);
}

// PairingNeighbourhood: the neighbours sorted by key, then by cell of a grid of side r/4 over
// the offsets [−2r, 2r)^dim (offsets beyond fall in the border cells).

PairingNeighbourhood::PairingNeighbourhood(Neighbourhood neighbours, double radius, int dimension)
    : neighbours_(std::move(neighbours)), side_(radius / 4.0), dimension_(dimension) {
  const int rows = dimension_ == 3 ? kCells * kCells : kCells;
  struct Entry {
    int key, row, column;
    Neighbour neighbour;
  };
  std::vector<Entry> entries;
  entries.reserve(neighbours_.size());
  for (const Neighbour& n : neighbours_) {
    const int z = dimension_ == 3 ? axis_cell(n.offset.z()) : 0;
    entries.push_back({n.key, z * kCells + axis_cell(n.offset.y()), axis_cell(n.offset.x()), n});
  }
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.key, a.row, a.column) < std::tie(b.key, b.row, b.column);
  });
  neighbours_.clear();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const Entry& e = entries[i];
    if (distinct_keys_.empty() || distinct_keys_.back() != e.key) {
      distinct_keys_.push_back(e.key);
      row_start_.insert(row_start_.end(), static_cast<std::size_t>(rows + 1), static_cast<int>(i));
    }
    keys_.push_back(e.key);
    column_.push_back(e.column);
    neighbours_.push_back(e.neighbour);
    // Rows after this one start after it (until a later entry says otherwise).
    int* start =
        row_start_.data() + (distinct_keys_.size() - 1) * static_cast<std::size_t>(rows + 1);
    for (int r = e.row + 1; r <= rows; ++r) start[r] = static_cast<int>(i) + 1;
  }
}

int PairingNeighbourhood::axis_cell(double x) const {
  return std::clamp(static_cast<int>(std::floor(x / side_)) + kCells / 2, 0, kCells - 1);
}

std::pair<std::size_t, std::size_t> PairingNeighbourhood::key_range(int key) const {
  const auto [first, last] = std::equal_range(keys_.begin(), keys_.end(), key);
  return {static_cast<std::size_t>(first - keys_.begin()),
          static_cast<std::size_t>(last - keys_.begin())};
}

}  // namespace shapeproc::geometry
