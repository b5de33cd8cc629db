#include "libshapeproc/sample/domain_decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/parallel_for.hpp"
#include "libshapeproc/geometry/nearest_neighbours.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"
#include "libshapeproc/sample/cell_layout.hpp"
#include "libshapeproc/sample/stationarity.hpp"

namespace shapeproc::sample {

namespace {

constexpr double kElementsPerCell = 64;  // the cells' size at the pilot's density
constexpr double kStepsPerElement = 10;  // steps of a visit per expected element of its cell
constexpr long long kLeastVisitSteps = 50;
constexpr int kLeastSweeps = 20;
constexpr int kMostSweeps = 200;            // about 2,000 steps per element (automatic rule)
constexpr std::size_t kLeastCounts = 24;    // the stationarity test's counts (one per colour visit)
constexpr std::size_t kLeastSpacings = 10;  // its mean nearest distances (one per sweep)
// The pilot torus's side in reaches (2D, 3D): a few hundred elements at the shipped exemplars'
// densities; a 3D torus of 6 reaches held 2,800 pebbles and took minutes.
constexpr double kPilotReaches2 = 6, kPilotReaches3 = 2.5;
constexpr long long kPilotStepsPerElement = 200;
constexpr long long kPilotMostSteps = 2'000'000;
constexpr long long kInsertAttempts = 30;  // random sequential insertion: tries per element wanted

// SplitMix64 of the parts: a visit's seed from the run's, the sweep, the colour and the cell.
std::uint64_t mix(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  std::uint64_t z = seed;
  for (std::uint64_t part : {a, b, c}) {
    z += 0x9E3779B97F4A7C15ULL * (part + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
  }
  return z;
}

// The model's stationary density (elements per unit measure): exact without interaction, else the
// mean count over the second half of a chain on a torus of kPilotReaches2 or 3 reaches (at most the
// domain's sizes), run until that half looks stationary and the chain has made
// kPilotStepsPerElement steps per element. It sets the fill's target and the visits' lengths, so
// it need not be precise: the decomposed chain itself reaches the model's count.
double pilot_density(const model::ShapeProcessModel& model, const ChainTables& tables,
                     const ChainRegion& whole, std::uint64_t seed) {
  if (!(tables.interaction->range() > 0)) {
    double density = 0.0;
    for (double log_beta : tables.log_beta) density += std::exp(log_beta);
    return density;
  }
  const geometry::Box3& box = whole.domain.box();
  geometry::Vec3 sizes = geometry::Vec3::Zero();
  for (int axis = 0; axis < tables.dimension; ++axis)
    sizes[axis] =
        std::min(box.sizes()[axis],
                 (tables.dimension == 3 ? kPilotReaches3 : kPilotReaches2) * tables.reach);
  const geometry::Domain torus(geometry::Box3(box.min(), box.min() + sizes), tables.dimension,
                               geometry::Boundary::torus);
  const ChainTables pilot_tables(model, torus, nullptr, false, tables.layer);
  ChainRegion region{torus, torus.box()};
  region.shift_probability = whole.shift_probability;
  region.near_birth_share = whole.near_birth_share;
  region.shift_radius = whole.shift_radius;
  core::Random random(seed);
  BirthDeathChain chain(pilot_tables, region, random, {}, {});
  std::vector<int> counts;  // every 10 steps
  for (long long step = 1; step <= kPilotMostSteps; ++step) {
    chain.step();
    if (step % 10 == 0) counts.push_back(chain.size());
    if (step % 5000 == 0 && step >= kPilotStepsPerElement * chain.size() && is_stationary(counts))
      break;
  }
  double sum = 0.0;
  for (std::size_t i = counts.size() / 2; i < counts.size(); ++i) sum += counts[i];
  const double mean =
      sum / static_cast<double>(std::max<std::size_t>(1, counts.size() - counts.size() / 2));
  return mean / torus.measure();
}

// The decomposed chain's state and one visit of a cell.
class Cells {
 public:
  Cells(const ChainTables& tables, const ChainRegion& whole, CellLayout layout, double density)
      : tables_(tables), whole_(whole), layout_(std::move(layout)), density_(density) {}

  CellLayout& layout() { return layout_; }

  // Moves every element to the cell that holds it under the current offset.
  void sort_into_cells(std::vector<Element> elements) {
    cells_.assign(static_cast<std::size_t>(layout_.count()), {});
    left_out_.resize(cells_.size(), 0);
    for (const Element& e : elements)
      cells_[static_cast<std::size_t>(layout_.cell_of(e.position))].push_back(e);
  }

  std::vector<Element> all() const {
    std::vector<Element> out;
    for (const auto& cell : cells_) out.insert(out.end(), cell.begin(), cell.end());
    return out;
  }

  // Start elements the hard core refused, over every visit so far.
  int left_out() const {
    int n = 0;
    for (int k : left_out_) n += k;
    return n;
  }

  long long size() const {
    long long n = 0;
    for (const auto& cell : cells_) n += static_cast<long long>(cell.size());
    return n;
  }

  double measure(int cell) const { return geometry::measure(layout_.box(cell), tables_.dimension); }

  // The steps of a visit: fixed by the pilot's density and the cell's measure.
  long long visit_steps(int cell) const {
    if (!(measure(cell) > 0)) return 0;  // an open domain's empty partial cell
    return std::max(kLeastVisitSteps, std::llround(kStepsPerElement * density_ * measure(cell)));
  }

  // Updates `cell` given the elements around it: `steps` birth-death steps, or (fill) random
  // sequential insertion up to the pilot's density. Only the cell's own list changes, so cells of
  // one colour may be visited at once.
  MoveCounts visit(int cell, long long steps, bool fill, std::uint64_t seed) {
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
    region.period = layout_.spanned_period();
    region.shift_probability = whole_.shift_probability;
    region.near_birth_share = whole_.near_birth_share;
    region.shift_radius = whole_.shift_radius;
    std::vector<Element> around, own;
    for (int other : layout_.around(cell)) {
      for (Element e : cells_[static_cast<std::size_t>(other)]) {
        e.position = layout_.image_near(e.position, centre);
        if (grid.contains(e.position)) around.push_back(e);
      }
    }
    for (Element e : cells_[static_cast<std::size_t>(cell)]) {
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
    std::vector<Element>& mine = cells_[static_cast<std::size_t>(cell)];
    mine = chain.free_elements();
    for (Element& e : mine) e.position = whole_.domain.wrap(e.position);
    // Own elements the hard core refused on entering (start elements in conflict; none after the
    // first visit): written by this cell's visit only.
    left_out_[static_cast<std::size_t>(cell)] += chain.start_left_out();
    return chain.moves();
  }

 private:
  const ChainTables& tables_;
  const ChainRegion& whole_;
  CellLayout layout_;
  double density_;
  std::vector<std::vector<Element>> cells_;
  std::vector<int> left_out_;  // per cell
};

}  // namespace

double cell_side(double reach, double density, int dimension) {
  const double holding = density > 0 ? std::pow(kElementsPerCell / density, 1.0 / dimension) : 0.0;
  return std::max(reach, holding);
}

bool decomposable(const geometry::Domain& domain, double reach) {
  return CellLayout::plan(domain, std::max(reach, 1e-12 * domain.box().sizes().maxCoeff()))
      .has_value();
}

namespace {

// Cells of the preferred side at `density`, or as large as the domain allows (4 per axis on a
// torus, 2 on an open domain), never under the reach.
CellLayout plan_cells(const geometry::Domain& domain, const ChainTables& tables, double density) {
  const double least_cells = domain.periodic() ? 4 : 2;
  double fits = std::numeric_limits<double>::infinity();  // over the axes that can be cut
  for (int axis = 0; axis < tables.dimension; ++axis) {
    const double size = domain.box().sizes()[axis];
    if (size >= least_cells * tables.reach) fits = std::min(fits, size / least_cells);
  }
  std::optional<CellLayout> layout = CellLayout::plan(
      domain,
      std::max(tables.reach, std::min(cell_side(tables.reach, density, tables.dimension), fits)));
  if (!layout)
    throw core::ArgumentError("sample", "the domain is too small to cut into cells of the reach");
  return *layout;
}

// The elements' mean distance to their nearest neighbour (reference positions, the nearest image
// on a torus): a pair statistic of the whole output, cheap beside a sweep (one grid pass), that
// moves where the count alone may not (elements that rearrange at a constant count).
double mean_nearest_distance(const std::vector<Element>& elements, const geometry::Domain& domain) {
  if (elements.size() < 2) return 0.0;
  std::vector<geometry::Vec3> points;
  points.reserve(elements.size());
  for (const Element& e : elements) points.push_back(e.position);
  double sum = 0.0;
  for (const auto& nearest : geometry::nearest_neighbours(points, domain, 1))
    if (!nearest.empty()) sum += nearest.front().offset.norm();
  return sum / static_cast<double>(points.size());
}

}  // namespace

SampleResult sample_by_cells(const model::ShapeProcessModel& model, const ChainTables& tables,
                             const ChainRegion& whole, const SamplerOptions& options,
                             core::Random& random, const synthesis::ChainControl& control) {
  if (!options.fixed.empty() || !options.free_region.isEmpty() || options.observe_every > 0)
    throw core::ArgumentError("sample",
                              "the decomposed sampler takes no fixed elements, free region or "
                              "observations");
  const geometry::Domain& domain = whole.domain;
  const int dimension = tables.dimension;
  const std::uint64_t run_seed = random.index(std::numeric_limits<std::uint64_t>::max());
  const double density = pilot_density(model, tables, whole, mix(run_seed, 0, 0, 0));
  Cells cells(tables, whole, plan_cells(domain, tables, density), density);
  std::vector<MoveCounts> moves(static_cast<std::size_t>(cells.layout().count()));
  const auto shift_cells = [&] {
    geometry::Vec3 offset = geometry::Vec3::Zero();
    for (int axis = 0; axis < dimension; ++axis)
      offset[axis] = random.uniform(0.0, cells.layout().side()[axis]);
    std::vector<Element> elements = cells.all();
    cells.layout().set_offset(offset);
    cells.sort_into_cells(std::move(elements));
  };
  // One pass over the colours; `fill`: random sequential insertion instead of steps.
  long long steps = 0;
  std::vector<int> counts;  // after each colour's visits
  const auto sweep = [&](int number, bool fill) {
    shift_cells();
    for (int colour = 0; colour < cells.layout().colours(); ++colour) {
      std::vector<int> ids;
      for (int c = 0; c < cells.layout().count(); ++c)
        if (cells.layout().colour(c) == colour) ids.push_back(c);
      if (ids.empty()) continue;  // a colour of an axis that is not cut
      core::parallel_for(static_cast<long long>(ids.size()), options.threads, [&](long long i) {
        const int cell = ids[static_cast<std::size_t>(i)];
        const std::uint64_t seed =
            mix(run_seed, static_cast<std::uint64_t>(number) + 1,
                static_cast<std::uint64_t>(colour), static_cast<std::uint64_t>(cell));
        moves[static_cast<std::size_t>(cell)] +=
            cells.visit(cell, cells.visit_steps(cell), fill, seed);
      });
      if (!fill) {
        for (int id : ids) steps += cells.visit_steps(id);
        counts.push_back(static_cast<int>(cells.size()));
      }
      if (control.cancelled()) throw core::Cancelled();
    }
  };

  SampleResult result;
  result.stationary = true;
  if (!options.start.empty()) {
    cells.sort_into_cells(options.start);  // kept where the hard core allows, at the first visit
    result.start_kept = static_cast<int>(options.start.size());  // less those left out, below
  } else {
    sweep(0, true);
  }
  const bool automatic = options.iterations <= 0;
  const long long total = automatic ? 0 : options.iterations;
  int done = 0;
  std::vector<double> spacings;  // the mean nearest distance after each sweep
  for (int number = 1;; ++number) {
    sweep(number, false);
    done = number;
    // The test reads the second half of the values only, and checks from kLeastSweeps on: the
    // sweeps before half of that are never read (a placeholder keeps the count).
    if (automatic)
      spacings.push_back(2 * number > kLeastSweeps ? mean_nearest_distance(cells.all(), domain)
                                                   : 0.0);
    if (options.trace_every > 0)
      result.trace.push_back(
          {steps, static_cast<int>(cells.size()), std::numeric_limits<double>::quiet_NaN()});
    if (control.progress) control.progress(steps, total);
    if (!automatic) {
      if (steps >= total) break;
      continue;
    }
    if (number >= kLeastSweeps && counts.size() >= 2 * kLeastCounts) {
      result.trend = count_trend(counts, kLeastCounts);
      result.spacing_trend = value_trend(spacings, kLeastSpacings);
      if (result.trend.stationary && result.spacing_trend.stationary) break;
    }
    if (number >= kMostSweeps) {
      result.stationary = false;
      break;
    }
  }
  result.iterations = steps;
  result.start_left_out = cells.left_out();
  result.start_kept -= result.start_left_out;
  for (const MoveCounts& m : moves) result.moves += m;
  result.scene = tables.geometry->shape_space;
  result.scene.elements = cells.all();
  result.cells = cells.layout().count();
  result.sweeps = done;
  result.pilot_density = density;
  result.cell_side = cells.layout().side();
  result.cell_offset = cells.layout().offset();
  return result;
}

}  // namespace shapeproc::sample
