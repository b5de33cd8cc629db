#include "libshapeproc/sample/domain_decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/parallel_for.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"
#include "libshapeproc/sample/cell_layout.hpp"
#include "libshapeproc/sample/cell_partition.hpp"
#include "libshapeproc/sample/decomposed_cells.hpp"
#include "libshapeproc/sample/stationarity.hpp"

namespace shapeproc::sample {

namespace {

constexpr double kElementsPerCell = 64;  // the cells' size at the pilot's density
constexpr int kLeastSweeps = 20;
constexpr int kMostSweeps = 200;            // about 2,000 steps per element (automatic rule)
constexpr std::size_t kLeastCounts = 24;    // the stationarity test's counts (one per colour visit)
constexpr std::size_t kLeastSpacings = 10;  // its mean nearest distances (one per sweep)
// The pilot torus's side in reaches (2D, 3D): a few hundred elements at the shipped exemplars'
// densities; a 3D torus of 6 reaches held 2,800 pebbles and took minutes.
constexpr double kPilotReaches2 = 6, kPilotReaches3 = 2.5;
constexpr long long kPilotStepsPerElement = 200;
constexpr long long kPilotMostSteps = 2'000'000;

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

}  // namespace

namespace {

// The output's mean nearest spacing (DecomposedCells::spacing) over every process's cells, with
// the cells around each process's own refreshed first: a pair statistic of the whole output,
// cheap beside a sweep, that moves where the count alone may not (elements that rearrange at a
// constant count).
double mean_spacing(DecomposedCells& cells, int threads) {
  CellPartition& partition = cells.partition();
  cells.refresh_borders();
  std::vector<int> own;
  for (int c = 0; c < cells.layout().count(); ++c)
    if (partition.owns(c)) own.push_back(c);
  std::vector<SpacingSum> sums(own.size());
  core::parallel_for(static_cast<long long>(own.size()), threads, [&](long long i) {
    sums[static_cast<std::size_t>(i)] = cells.spacing(own[static_cast<std::size_t>(i)]);
  });
  SpacingSum local;
  for (const SpacingSum& s : sums) {
    local.units += s.units;
    local.elements += s.elements;
  }
  const long long units = partition.sum(local.units), elements = partition.sum(local.elements);
  if (elements == 0) return 0.0;
  return static_cast<double>(units) / DecomposedCells::kSpacingUnits * cells.spacing_cap() /
         static_cast<double>(elements);
}

// The moves of this process's visits, summed over every process.
MoveCounts summed(const std::vector<MoveCounts>& moves, CellPartition& partition) {
  MoveCounts local;
  for (const MoveCounts& m : moves) local += m;
  MoveCounts total;
  for (auto [into, own] : {std::pair{&total.births_accepted, local.births_accepted},
                           {&total.births_proposed, local.births_proposed},
                           {&total.deaths_accepted, local.deaths_accepted},
                           {&total.deaths_proposed, local.deaths_proposed},
                           {&total.shifts_accepted, local.shifts_accepted},
                           {&total.shifts_proposed, local.shifts_proposed}})
    *into = partition.sum(own);
  return total;
}

}  // namespace

SampleResult sample_by_cells(const model::ShapeProcessModel& model, const ChainTables& tables,
                             const ChainRegion& whole, const SamplerOptions& options,
                             core::Random& random, const synthesis::ChainControl& control) {
  if (!options.fixed.empty() || !options.free_region.isEmpty() || options.observe_every > 0)
    throw core::ArgumentError("sample",
                              "the decomposed sampler takes no fixed elements, free region or "
                              "observations");
  OneProcess alone;
  CellPartition& partition = options.partition ? *options.partition : alone;
  if (!options.start.empty() && partition.processes() > 1)
    throw core::ArgumentError("sample", "a run across processes takes no start elements");
  const geometry::Domain& domain = whole.domain;
  const int dimension = tables.dimension;
  const std::uint64_t run_seed = random.index(std::numeric_limits<std::uint64_t>::max());
  const double density = pilot_density(model, tables, whole, visit_seed(run_seed, 0, 0, 0));
  DecomposedCells cells(tables, whole, plan_cells(domain, tables, density), density, partition);
  std::vector<MoveCounts> moves(static_cast<std::size_t>(cells.layout().count()));
  const auto shift_cells = [&] {
    geometry::Vec3 offset = geometry::Vec3::Zero();
    for (int axis = 0; axis < dimension; ++axis)
      offset[axis] = random.uniform(0.0, cells.layout().side()[axis]);
    cells.shift(offset);
  };
  // One pass over the colours; `fill`: random sequential insertion instead of steps.
  long long steps = 0;
  std::vector<int> counts;  // after each colour's visits
  const auto sweep = [&](int number, bool fill) {
    shift_cells();
    for (int colour = 0; colour < cells.layout().colours(); ++colour) {
      std::vector<int> ids;
      long long colour_steps = 0;  // over every process's cells of the colour
      bool any = false;
      for (int c = 0; c < cells.layout().count(); ++c) {
        if (cells.layout().colour(c) != colour) continue;
        any = true;
        colour_steps += cells.visit_steps(c);
        if (partition.owns(c)) ids.push_back(c);
      }
      if (!any) continue;  // a colour of an axis that is not cut
      cells.refresh_borders();
      core::parallel_for(static_cast<long long>(ids.size()), options.threads, [&](long long i) {
        const int cell = ids[static_cast<std::size_t>(i)];
        const std::uint64_t seed =
            visit_seed(run_seed, static_cast<std::uint64_t>(number) + 1,
                       static_cast<std::uint64_t>(colour), static_cast<std::uint64_t>(cell));
        moves[static_cast<std::size_t>(cell)] +=
            cells.visit(cell, cells.visit_steps(cell), fill, seed);
      });
      if (!fill) {
        steps += colour_steps;
        counts.push_back(static_cast<int>(partition.sum(cells.own_size())));
      }
      if (partition.any(control.cancelled())) throw core::Cancelled();
    }
  };
  SampleResult result;
  result.stationary = true;
  if (!options.start.empty()) {
    cells.place(options.start);  // kept where the hard core allows, at the first visit
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
      spacings.push_back(2 * number > kLeastSweeps ? mean_spacing(cells, options.threads) : 0.0);
    if (options.trace_every > 0)
      result.trace.push_back({steps, counts.back(), std::numeric_limits<double>::quiet_NaN()});
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
  result.start_left_out = static_cast<int>(partition.sum(cells.left_out()));
  result.start_kept -= result.start_left_out;
  result.moves = summed(moves, partition);
  result.scene = tables.geometry->shape_space;
  result.scene.elements = cells.own_elements();
  result.cells = cells.layout().count();
  result.sweeps = done;
  result.pilot_density = density;
  result.cell_side = cells.layout().side();
  result.cell_offset = cells.layout().offset();
  return result;
}

}  // namespace shapeproc::sample
