// One neighbourhood-EM iteration (Ma et al. 2011) on outputs of about 1,000 elements (run
// ./build/benchmarks/compare_benchmarks): a k-coherence search over every output sample, the
// least-squares positions, the attribute vote and the energy check of the new positions. Ma et
// al. report about 5 s per iteration for 1,000 elements; the target here is 0.5 s on one core.
#include <benchmark/benchmark.h>

#include <cmath>

#include "libshapeproc/compare/attribute_vote.hpp"
#include "libshapeproc/compare/neighbourhood_em.hpp"
#include "libshapeproc/compare/position_assignment.hpp"
#include "libshapeproc/compare/region_growing.hpp"
#include "libshapeproc/compare/seed_and_grow.hpp"
#include "libshapeproc/io/scene_io.hpp"

namespace {

using namespace shapeproc;

std::string data(const char* relative) { return std::string(SHAPEPROC_DATA_DIR) + "/" + relative; }

void BM_EmIteration(benchmark::State& state, const char* file, const char* category_by) {
  io::ReaderOptions reader;
  if (category_by) reader.category_by = io::CategoryRule::parse(category_by);
  const geometry::Scene exemplar = io::read_scene(data(file), reader);
  // A square torus holding about 1,000 elements at the exemplar's density.
  const double side =
      std::sqrt(1000.0 * exemplar.window_measure() / static_cast<double>(exemplar.elements.size()));
  const auto domain = geometry::Domain::from_sizes({side, side}, geometry::Boundary::torus);
  const compare::NeighbourhoodEm em(exemplar, geometry::Boundary::open, domain, {});
  const compare::EmExemplar& ex = em.exemplar();
  const compare::SimilaritySets sets =
      compare::build_similarity_sets(ex, 5, ex.spacing * ex.spacing);
  compare::SearchSettings settings;
  settings.alpha = settings.lambda = ex.spacing * ex.spacing;
  settings.sets = &sets;
  compare::SearchSettings fixed = settings;
  fixed.rule = compare::SearchRule::fixed;
  core::Random random(1);
  compare::InitialOutput start = compare::initialise(
      ex, domain, {}, compare::Initialisation::patch_copy, settings.alpha, random);
  compare::SearchResult seed;
  seed.match = start.copied_from;
  const compare::SearchResult first = compare::search(ex, start.output, domain, settings, seed);
  for (auto _ : state) {
    const compare::SearchResult found = compare::search(ex, start.output, domain, settings, first);
    const auto d =
        compare::solve_positions(start.output.samples.positions, found.predictions, domain);
    compare::OutputSamples moved = start.output;
    for (std::size_t s = 0; s < moved.samples.size(); ++s)
      moved.samples.positions[s] = domain.wrap(moved.samples.positions[s] + d[s]);
    const auto sources = compare::vote_attributes(ex, start.output, found);
    benchmark::DoNotOptimize(sources);
    const compare::SearchResult energy = compare::search(ex, moved, domain, fixed, found);
    benchmark::DoNotOptimize(energy.energy);
  }
  const double elements = static_cast<double>(start.output.elements());
  state.counters["elements"] = elements;
  state.counters["samples"] = static_cast<double>(start.output.samples.size());
  // Seconds per iteration per 1,000 elements: the inverse of the rate of thousands of elements
  // an iteration (kIsIterationInvariantRate multiplies by iterations and divides by seconds).
  state.counters["s_per_1000_elements"] =
      benchmark::Counter(elements / 1000.0, benchmark::Counter::kIsIterationInvariantRate |
                                                benchmark::Counter::kInvert);
}

// Growth of a square torus holding about 10,000 elements at the exemplar's density, one core:
// region growing (Davison et al. 2018; the paper reports 1,100 to 3,200 elements per second, the
// target is 10,000) and seed-and-grow (Ijiri et al. 2008; the paper: 1,000 elements in about 5 s,
// the target is 5,000).
template <class Method, class Options>
void grow_torus(benchmark::State& state, const char* file, bool tile, const Options& options) {
  io::ReaderOptions reader;
  reader.tile = tile;
  const geometry::Scene exemplar = io::read_scene(data(file), reader);
  const double side = std::sqrt(10000.0 * exemplar.window_measure() /
                                static_cast<double>(exemplar.elements.size()));
  const auto domain = geometry::Domain::from_sizes({side, side}, geometry::Boundary::torus);
  const Method growth(exemplar, tile ? geometry::Boundary::torus : geometry::Boundary::open, domain,
                      options);
  double elements = 0.0;
  for (auto _ : state) {
    core::Random random(1);
    elements = static_cast<double>(growth.synthesize(random, {}).scene.elements.size());
  }
  state.counters["elements"] = elements;
  state.counters["elements_per_s"] =
      benchmark::Counter(elements, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_RegionGrowing(benchmark::State& state, const char* file, bool tile, bool optimise) {
  compare::GrowthOptions options;
  options.optimise = optimise;
  grow_torus<compare::RegionGrowing>(state, file, tile, options);
}

void BM_SeedAndGrow(benchmark::State& state, const char* file, bool tile, bool relax) {
  compare::SeedGrowthOptions options;
  options.relax = relax;
  grow_torus<compare::SeedAndGrow>(state, file, tile, options);
}

}  // namespace

BENCHMARK_CAPTURE(BM_SeedAndGrow, dots_random, "svg/dots-random.svg", false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SeedAndGrow, crescents_grid, "svg/crescents-grid.svg", false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SeedAndGrow, bubbles_tile, "third-party/hero-patterns/bubbles.svg", true, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SeedAndGrow, dots_random_no_relax, "svg/dots-random.svg", false, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RegionGrowing, dots_random, "svg/dots-random.svg", false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RegionGrowing, crescents_grid, "svg/crescents-grid.svg", false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RegionGrowing, bubbles_tile, "third-party/hero-patterns/bubbles.svg", true,
                  true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RegionGrowing, crescents_grid_no_optimise, "svg/crescents-grid.svg", false,
                  false)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_EmIteration, dots_random, "svg/dots-random.svg", nullptr)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EmIteration, two_kinds, "svg/two-kinds.svg", "fill")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EmIteration, crescents_grid, "svg/crescents-grid.svg", nullptr)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EmIteration, rings, "svg/rings.svg", nullptr)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EmIteration, dashes_rows, "svg/dashes-rows.svg", nullptr)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
