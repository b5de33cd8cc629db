// Fit times on the shipped exemplars (run ./build/benchmarks/fit_benchmarks): the whole fit at the
// defaults, the pseudo-likelihood fit and then the maximum-likelihood fit by MCMC from it (4 chains
// on the machine's cores). The target: under 5 s per 2D exemplar on 2 cores.
#include <benchmark/benchmark.h>

#include <string>

#include "libshapeproc/fit/fit_maximum_likelihood.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/io/scene_io.hpp"

namespace {

std::string data(const char* relative) { return std::string(SHAPEPROC_DATA_DIR) + "/" + relative; }

void BM_MaximumLikelihoodFit(benchmark::State& state, const char* file, const char* category_by,
                             bool split) {
  shapeproc::io::ReaderOptions reader;
  reader.split_subpaths = split;
  if (category_by) reader.category_by = shapeproc::io::CategoryRule::parse(category_by);
  const auto exemplar = shapeproc::io::read_scene(data(file), reader);
  const shapeproc::fit::FitOptions options;
  int iterations = 0;
  bool converged = false;
  for (auto _ : state) {
    auto mple = shapeproc::fit::fit_shape_process(exemplar, options);
    const auto result =
        shapeproc::fit::refine_to_maximum_likelihood(exemplar, options, std::move(mple), {});
    benchmark::DoNotOptimize(result.model.categories[0].beta);
    const auto& estimator = result.model.fit->likelihood;
    converged = estimator && estimator->converged;
    iterations = estimator ? estimator->iterations : 0;
  }
  state.counters["elements"] = static_cast<double>(exemplar.elements.size());
  state.counters["mle_iterations"] = iterations;
  state.counters["converged"] = converged ? 1 : 0;
}

}  // namespace

#define SHAPEPROC_FIT_BENCHMARK(name, file, category_by, split)              \
  BENCHMARK_CAPTURE(BM_MaximumLikelihoodFit, name, file, category_by, split) \
      ->Unit(benchmark::kSecond)                                             \
      ->Iterations(1)                                                        \
      ->Repetitions(3)                                                       \
      ->ReportAggregatesOnly(true)

SHAPEPROC_FIT_BENCHMARK(dots_random, "svg/dots-random.svg", nullptr, false);
SHAPEPROC_FIT_BENCHMARK(two_kinds, "svg/two-kinds.svg", "fill", false);
SHAPEPROC_FIT_BENCHMARK(rings, "svg/rings.svg", nullptr, true);
SHAPEPROC_FIT_BENCHMARK(crescents_grid, "svg/crescents-grid.svg", nullptr, false);
SHAPEPROC_FIT_BENCHMARK(dashes_rows, "svg/dashes-rows.svg", nullptr, false);
SHAPEPROC_FIT_BENCHMARK(bubbles, "third-party/hero-patterns/bubbles.svg", nullptr, true);
SHAPEPROC_FIT_BENCHMARK(tic_tac_toe, "third-party/hero-patterns/tic-tac-toe.svg", nullptr, true);

BENCHMARK_MAIN();
