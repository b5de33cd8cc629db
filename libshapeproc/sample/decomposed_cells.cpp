#include "libshapeproc/sample/decomposed_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "libshapeproc/sample/birth_death_chain.hpp"

namespace shapeproc::sample {

namespace {

constexpr double kStepsPerElement = 10;  // steps of a visit per expected element of its cell
constexpr long long kLeastVisitSteps = 50;
constexpr long long kInsertAttempts = 30;  // random sequential insertion: tries per element wanted

}  // namespace

std::uint64_t visit_seed(std::uint64_t run, std::uint64_t sweep, std::uint64_t colour,
                         std::uint64_t cell) {
  std::uint64_t z = run;
  for (std::uint64_t part : {sweep, colour, cell}) {
    z += 0x9E3779B97F4A7C15ULL * (part + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
  }
  return z;
}

DecomposedCells::DecomposedCells(const ChainTables& tables, const ChainRegion& whole,
                                 CellLayout layout, double density, CellPartition& partition)
    : tables_(tables),
      whole_(whole),
      layout_(std::move(layout)),
      density_(density),
      partition_(partition),
      cells_(static_cast<std::size_t>(layout_.count())),
      left_out_(static_cast<std::size_t>(layout_.count()), 0) {
  partition_.plan(layout_);
}

void DecomposedCells::shift(const geometry::Vec3& offset) {
  // Every own element, tagged with where it was; then each to its new cell, here or elsewhere.
  std::vector<MovingElement> held;
  for (int c = 0; c < layout_.count(); ++c) {
    if (!partition_.owns(c)) continue;
    const auto& cell = cells_[static_cast<std::size_t>(c)];
    for (std::size_t k = 0; k < cell.size(); ++k) held.push_back({cell[k], c, static_cast<int>(k)});
  }
  layout_.set_offset(offset);
  for (auto& cell : cells_) cell.clear();
  std::vector<std::vector<MovingElement>> outgoing(
      static_cast<std::size_t>(partition_.processes()));
  std::vector<std::vector<MovingElement>> arriving(cells_.size());
  for (const MovingElement& m : held) {
    const int to = layout_.cell_of(m.element.position);
    if (partition_.owns(to))
      arriving[static_cast<std::size_t>(to)].push_back(m);
    else
      outgoing[static_cast<std::size_t>(partition_.owner(to))].push_back(m);
  }
  bool received = false;
  for (const MovingElement& m : partition_.exchange_moving(std::move(outgoing))) {
    arriving[static_cast<std::size_t>(layout_.cell_of(m.element.position))].push_back(m);
    received = true;
  }
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    auto& list = arriving[c];
    // One process lists a cell's elements by former cell, then place: so must several.
    if (received)
      std::sort(list.begin(), list.end(), [](const MovingElement& a, const MovingElement& b) {
        return std::tie(a.from_cell, a.place) < std::tie(b.from_cell, b.place);
      });
    for (const MovingElement& m : list) cells_[c].push_back(m.element);
  }
}

void DecomposedCells::place(const std::vector<geometry::Element>& elements) {
  for (const geometry::Element& e : elements)
    cells_[static_cast<std::size_t>(layout_.cell_of(e.position))].push_back(e);
}

std::vector<geometry::Element> DecomposedCells::own_elements() const {
  std::vector<geometry::Element> out;
  for (int c = 0; c < layout_.count(); ++c) {
    if (!partition_.owns(c)) continue;
    const auto& cell = cells_[static_cast<std::size_t>(c)];
    out.insert(out.end(), cell.begin(), cell.end());
  }
  return out;
}

long long DecomposedCells::own_size() const {
  long long n = 0;
  for (int c = 0; c < layout_.count(); ++c)
    if (partition_.owns(c)) n += static_cast<long long>(cells_[static_cast<std::size_t>(c)].size());
  return n;
}

int DecomposedCells::left_out() const {
  int n = 0;
  for (int k : left_out_) n += k;
  return n;
}

double DecomposedCells::measure(int cell) const {
  return geometry::measure(layout_.box(cell), tables_.dimension);
}

long long DecomposedCells::visit_steps(int cell) const {
  if (!(measure(cell) > 0)) return 0;  // an open domain's empty partial cell
  return std::max(kLeastVisitSteps, std::llround(kStepsPerElement * density_ * measure(cell)));
}

MoveCounts DecomposedCells::visit(int cell, long long steps, bool fill, std::uint64_t seed) {
  const geometry::Box3 box = layout_.box(cell);
  if (!(measure(cell) > 0)) return {};
  const geometry::Vec3 centre = box.center();
  geometry::Vec3 margin = geometry::Vec3::Zero();  // none along the axes cells span
  for (int axis = 0; axis < tables_.dimension; ++axis)
    if (layout_.cut(axis)) margin[axis] = tables_.reach;
  geometry::Box3 grid(box.min() - margin, box.max() + margin);
  if (!whole_.domain.periodic()) grid = grid.intersection(whole_.domain.box());
  ChainRegion region{whole_.domain.periodic()
                         ? geometry::Domain(grid, tables_.dimension, geometry::Boundary::open)
                         : whole_.domain,
                     box};
  region.grid_box = grid;
  region.confined = true;
  if (whole_.domain.periodic()) region.local_factor = &whole_.domain;
  region.period = layout_.spanned_period();
  region.shift_probability = whole_.shift_probability;
  region.near_birth_share = whole_.near_birth_share;
  region.shift_radius = whole_.shift_radius;
  std::vector<geometry::Element> around, own;
  for (int other : layout_.around(cell)) {
    for (geometry::Element e : cells_[static_cast<std::size_t>(other)]) {
      e.position = layout_.image_near(e.position, centre);
      if (grid.contains(e.position)) around.push_back(e);
    }
  }
  for (geometry::Element e : cells_[static_cast<std::size_t>(cell)]) {
    e.position = layout_.image_near(e.position, centre);
    own.push_back(e);
  }
  core::Random random(seed);
  BirthDeathChain chain(tables_, region, random, {}, {});
  chain.add_surroundings(around);
  chain.add_start(own);
  if (fill) {
    const double wanted =
        density_ * measure(cell) - static_cast<double>(chain.free_elements().size());
    const int n = static_cast<int>(std::max(0.0, std::round(wanted)));
    chain.insert_at_random(n, kInsertAttempts * std::max(1, n));
  } else {
    for (long long s = 0; s < steps; ++s) chain.step();
  }
  std::vector<geometry::Element>& mine = cells_[static_cast<std::size_t>(cell)];
  mine = chain.free_elements();
  for (geometry::Element& e : mine) e.position = whole_.domain.wrap(e.position);
  // Own elements the hard core refused on entering (start elements in conflict; none after the
  // first visit): written by this cell's visit only.
  left_out_[static_cast<std::size_t>(cell)] += chain.start_left_out();
  return chain.moves();
}

double DecomposedCells::spacing_cap() const {
  double cap = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < tables_.dimension; ++axis)
    if (layout_.cut(axis)) cap = std::min(cap, layout_.side()[axis]);
  return cap;
}

SpacingSum DecomposedCells::spacing(int cell) const {
  const auto& own = cells_[static_cast<std::size_t>(cell)];
  if (own.empty()) return {};
  const geometry::Vec3 centre = layout_.box(cell).center();
  const geometry::Vec3 period = layout_.spanned_period();
  std::vector<geometry::Vec3> points;  // the cell's own first, then those around
  for (const geometry::Element& e : own) points.push_back(layout_.image_near(e.position, centre));
  for (int other : layout_.around(cell))
    for (const geometry::Element& e : cells_[static_cast<std::size_t>(other)])
      points.push_back(layout_.image_near(e.position, centre));
  const double cap = spacing_cap();
  SpacingSum sum;
  for (std::size_t i = 0; i < own.size(); ++i) {
    double nearest = cap * cap;
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (j == i) continue;
      geometry::Vec3 d = points[j] - points[i];
      for (int axis = 0; axis < 3; ++axis)  // a cell spanning a torus's axis wraps along it
        if (period[axis] > 0) d[axis] -= period[axis] * std::round(d[axis] / period[axis]);
      nearest = std::min(nearest, d.squaredNorm());
    }
    sum.units += std::llround(std::sqrt(nearest) / cap * kSpacingUnits);
    ++sum.elements;
  }
  return sum;
}

}  // namespace shapeproc::sample
