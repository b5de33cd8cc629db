#include "libshapeproc/geometry/element_neighbourhood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
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
    if (t.squaredNorm() >= radius_ * radius_) return;
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
// (`all(a, visit)`), among the exemplar neighbours still free. The pairs are those of one sort
// of every candidate (uncontested near pairs come first, unsorted). Buffers are reused by each
// thread.
//
// `bound`: once Σ over the output neighbours of a lower bound of their pair's cost (their
// nearest near candidate, else (r/4)²) reaches it, no pair is made and that sum is returned;
// likewise after the near pairs (their costs, and (r/4)² for each neighbour left); otherwise
// the result is -1 (pairs made before a bound stops are to be discarded).
template <class Near, class All, class Floor, class F>
double greedy_core(const Neighbourhood& output, std::size_t exemplar_size, double radius,
                   Near&& near_of, All&& all_of, Floor&& floor_of, F&& f, double bound) {
  // One thread-local object (one lookup of the thread's storage per call, not six).
  struct Buffers {
    std::vector<CandidatePair> near, contested, far;
    std::vector<char> used_output, used_exemplar;
    std::vector<unsigned char> referrers;  // 0, 1 or 2 (two or more)
  };
  thread_local Buffers buffers;
  // Plain references, not a structured binding: the lambdas below capture them.
  auto& near = buffers.near;
  auto& contested = buffers.contested;
  auto& far = buffers.far;
  auto& used_output = buffers.used_output;
  auto& used_exemplar = buffers.used_exemplar;
  auto& referrers = buffers.referrers;
  near.clear();
  const double cap = radius * radius, split = cap / 16.0;
  double lower = 0.0;
  for (std::size_t a = 0; a < output.size(); ++a) {
    const Neighbour& o = output[a];
    double nearest = split;
    if (o.key >= 0) {
      near_of(a, [&](std::size_t b, double c) {
        if (c < split) {
          near.push_back({c, static_cast<int>(a), static_cast<int>(b)});
          nearest = std::min(nearest, c);
        }
      });
    }
    if (nearest == split) nearest = std::max(split, floor_of(a));
    lower += nearest;
    if (lower >= bound) return lower;
  }
  used_output.assign(output.size(), 0);
  used_exemplar.assign(exemplar_size, 0);
  std::size_t paired = 0;
  double near_sum = 0.0;  // the pairs' squared distances so far
  // The greedy pass over `pairs` (grouped by output neighbour), closest first, stopping once
  // every output neighbour in it is paired.
  const auto take = [&](std::vector<CandidatePair>& pairs) {
    std::size_t open = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i)
      if (i == 0 || pairs[i - 1].output != pairs[i].output) ++open;
    std::sort(pairs.begin(), pairs.end());
    for (const CandidatePair& p : pairs) {
      if (open == 0) return;
      const auto a = static_cast<std::size_t>(p.output), b = static_cast<std::size_t>(p.exemplar);
      if (used_output[a] || used_exemplar[b]) continue;
      used_output[a] = used_exemplar[b] = 1;
      f(p.output, p.exemplar, p.cost);
      near_sum += p.cost;
      --open;
      if (++paired == output.size()) return;
    }
  };
  // A pair whose two sides have no other near candidate is taken whenever the sorted greedy
  // pass reaches it and blocks nothing, so such pairs are taken first, unsorted (most pairs of a
  // good candidate are); only the contested rest is sorted.
  referrers.assign(exemplar_size, 0);
  for (const CandidatePair& p : near) {
    unsigned char& r = referrers[static_cast<std::size_t>(p.exemplar)];
    r = r == 0 ? 1 : 2;
  }
  contested.clear();
  for (std::size_t i = 0; i < near.size(); ++i) {
    const CandidatePair& p = near[i];
    const bool alone = (i == 0 || near[i - 1].output != p.output) &&
                       (i + 1 == near.size() || near[i + 1].output != p.output);
    if (alone && referrers[static_cast<std::size_t>(p.exemplar)] == 1) {
      used_output[static_cast<std::size_t>(p.output)] = 1;
      used_exemplar[static_cast<std::size_t>(p.exemplar)] = 1;
      f(p.output, p.exemplar, p.cost);
      near_sum += p.cost;
      ++paired;
    } else {
      contested.push_back(p);
    }
  }
  if (paired == output.size()) return -1.0;
  take(contested);
  if (paired == output.size()) return -1.0;
  // Every neighbour still free costs at least (r/4)² (a far pair or none), so the near pairs
  // and that give a second, tighter lower bound before the far candidates are gathered.
  const double after_near = near_sum + static_cast<double>(output.size() - paired) * split;
  if (after_near >= bound) return after_near;
  far.clear();
  for (std::size_t a = 0; a < output.size(); ++a) {
    const Neighbour& o = output[a];
    if (used_output[a] || o.key < 0) continue;
    all_of(a, [&](std::size_t b, double c) {
      if (used_exemplar[b]) return;
      if (c >= split && c < cap) far.push_back({c, static_cast<int>(a), static_cast<int>(b)});
    });
  }
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
    const Neighbour& o = output[a];
    auto first = exemplar.begin(), last = exemplar.end();
    if (sorted) std::tie(first, last) = std::equal_range(first, last, o, by_key);
    for (auto it = first; it != last; ++it)
      if (it->key == o.key)
        visit(static_cast<std::size_t>(it - exemplar.begin()),
              (o.offset - it->offset).squaredNorm());
  };
  return greedy_core(
      output, exemplar.size(), radius, scan, scan, [](std::size_t) { return 0.0; }, f, bound);
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
  const double cap = radius * radius;
  const auto floor = [&](std::size_t a) { return exemplar.nearest_bound(output[a], cap); };
  return greedy_core(output, exemplar.size(), radius, near, all, floor, f, bound);
}

// `attribute_of(b)`: the attribute of exemplar neighbour b.
template <class Exemplar, class Attribute>
double distance(const Neighbourhood& output, const Exemplar& exemplar, Attribute&& attribute_of,
                double radius, double alpha, double bound,
                std::vector<std::pair<int, int>>* pairs = nullptr) {
  double sum = 0.0;
  std::size_t paired = 0;
  if (pairs) pairs->clear();
  const double cap = radius * radius;
  const double lower = greedy_pairs(
      output, exemplar, radius,
      [&](int a, int b, double c) {
        if (alpha > 0.0 && output[static_cast<std::size_t>(a)].attribute !=
                               attribute_of(static_cast<std::size_t>(b)))
          c = std::min(c + alpha, cap);
        sum += c;
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
  return distance(
      output, exemplar, [&](std::size_t b) { return exemplar[b].attribute; }, radius, alpha, bound);
}

double neighbourhood_distance(const Neighbourhood& output, const PairingNeighbourhood& exemplar,
                              double radius, double alpha, double bound,
                              std::vector<std::pair<int, int>>* pairs) {
  return distance(
      output, exemplar, [&](std::size_t b) { return exemplar.attribute(b); }, radius, alpha, bound,
      pairs);
}

// PairingNeighbourhood: the neighbours sorted by key, then by cell of a grid of side r/4 over
// the offsets [−2r, 2r)^dim (offsets beyond fall in the border cells).

PairingNeighbourhood::PairingNeighbourhood(Neighbourhood neighbours, double radius, int dimension)
    : neighbours_(std::move(neighbours)),
      per_cell_(4.0 / radius),
      dimension_(dimension),
      radius_(radius) {
  cells_ = dimension_ == 3 ? kCells * kCells * kCells : kCells * kCells;
  if (neighbours_.size() > std::numeric_limits<Start>::max())
    throw std::length_error("a pairing neighbourhood holds at most 65,535 neighbours");
  struct Entry {
    int key, cell;
    Neighbour neighbour;
  };
  std::vector<Entry> entries;
  entries.reserve(neighbours_.size());
  for (const Neighbour& n : neighbours_) {
    const int z = dimension_ == 3 ? axis_cell(n.offset.z()) : 0;
    entries.push_back(
        {n.key, (z * kCells + axis_cell(n.offset.y())) * kCells + axis_cell(n.offset.x()), n});
  }
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.key, a.cell) < std::tie(b.key, b.cell);
  });
  neighbours_.clear();
  for (std::size_t first = 0; first < entries.size();) {
    std::size_t last = first;
    while (last < entries.size() && entries[last].key == entries[first].key) ++last;
    distinct_keys_.push_back(entries[first].key);
    std::size_t i = first;
    for (int c = 0; c <= cells_; ++c) {
      while (i < last && entries[i].cell < c) ++i;
      cell_start_.push_back(static_cast<Start>(i));
    }
    first = last;
  }
  for (const Entry& e : entries) {
    keys_.push_back(e.key);
    neighbours_.push_back(e.neighbour);
    xyz_.insert(xyz_.end(),
                {e.neighbour.offset.x(), e.neighbour.offset.y(), e.neighbour.offset.z()});
    attributes_.push_back(e.neighbour.attribute);
  }
  for (std::size_t k = 0; k < distinct_keys_.size(); ++k) {
    if (distinct_keys_[k] < 0) continue;
    const auto key = static_cast<std::size_t>(distinct_keys_[k]);
    if (slots_.size() <= key) slots_.resize(key + 1, -1);
    slots_[key] = static_cast<int>(k);
  }
  build_lower_bound_grid();
}

namespace {

// Cells per axis of the lower bound's grid over [−r, r): side r/8 in 2D, r/4 in 3D.
int bound_cells(int dimension) { return dimension == 3 ? 8 : 16; }

}  // namespace

void PairingNeighbourhood::build_lower_bound_grid() {
  const int per_axis = bound_cells(dimension_);
  const int depth = dimension_ == 3 ? per_axis : 1;
  bound_cells_ = per_axis * per_axis * depth;
  const double side = 2.0 * radius_ / per_axis;
  const double cap = radius_ * radius_;
  nearest_.assign(distinct_keys_.size() * static_cast<std::size_t>(bound_cells_),
                  static_cast<float>(cap));
  const auto gap = [&](double x, int cell) {
    const double low = -radius_ + cell * side, high = low + side;
    return x < low ? low - x : x > high ? x - high : 0.0;
  };
  for (std::size_t k = 0; k < distinct_keys_.size(); ++k) {
    const auto [first, last] = key_range(distinct_keys_[k]);
    float* field = nearest_.data() + k * static_cast<std::size_t>(bound_cells_);
    for (int cz = 0; cz < depth; ++cz)
      for (int cy = 0; cy < per_axis; ++cy)
        for (int cx = 0; cx < per_axis; ++cx) {
          double best = cap;
          for (std::size_t i = first; i < last; ++i) {
            const double gx = gap(xyz_[3 * i], cx), gy = gap(xyz_[3 * i + 1], cy);
            const double gz = dimension_ == 3 ? gap(xyz_[3 * i + 2], cz) : 0.0;
            best = std::min(best, gx * gx + gy * gy + gz * gz);
          }
          // Lowered by a hair, for a query the cell's floor assigns here though rounding puts it
          // just outside the cell's box, then rounded down, so that the float never exceeds the
          // distance it stands for.
          best = std::max(0.0, best * (1.0 - 1e-9) - 1e-12 * cap);
          float rounded = static_cast<float>(best);
          if (static_cast<double>(rounded) > best) rounded = std::nextafter(rounded, 0.0f);
          field[(cz * per_axis + cy) * per_axis + cx] = rounded;
        }
  }
}

double PairingNeighbourhood::nearest_bound(const Neighbour& o, double cap) const {
  const int slot = slot_of(o.key);
  if (slot < 0) return cap;  // no partner of its key: unpaired
  const int per_axis = bound_cells(dimension_);
  const double per_side = per_axis / (2.0 * radius_);
  const auto cell = [&](double x) {
    return static_cast<int>(std::floor((x + radius_) * per_side));
  };
  const int cx = cell(o.offset.x()), cy = cell(o.offset.y());
  const int cz = dimension_ == 3 ? cell(o.offset.z()) : 0;
  const int depth = dimension_ == 3 ? per_axis : 1;
  // Offsets outside the grid (beyond r) are given no bound.
  if (cx < 0 || cx >= per_axis || cy < 0 || cy >= per_axis || cz < 0 || cz >= depth) return 0.0;
  const float* field =
      nearest_.data() + static_cast<std::size_t>(slot) * static_cast<std::size_t>(bound_cells_);
  return std::min(cap, static_cast<double>(field[(cz * per_axis + cy) * per_axis + cx]));
}

int PairingNeighbourhood::axis_cell(double x) const {
  return std::clamp(static_cast<int>(std::floor(x * per_cell_)) + kCells / 2, 0, kCells - 1);
}

std::pair<std::size_t, std::size_t> PairingNeighbourhood::key_range(int key) const {
  const auto [first, last] = std::equal_range(keys_.begin(), keys_.end(), key);
  return {static_cast<std::size_t>(first - keys_.begin()),
          static_cast<std::size_t>(last - keys_.begin())};
}

}  // namespace shapeproc::geometry
