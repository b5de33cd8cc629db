// Sampler throughput on the shipped exemplars (run ./build/benchmarks/sample_benchmarks): each
// exemplar is fitted once at the defaults, then 50,000 birth-death steps are run on a domain of
// four times its area (the paper's Table 1 reports 50,000 iterations in 16.8–195.9 s in 2D).
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <vector>

#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/sample/birth_death_chain.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/sample/configuration.hpp"

namespace {

std::string data(const char* relative) { return std::string(SHAPEPROC_DATA_DIR) + "/" + relative; }

struct Fitted {
  shapeproc::model::ShapeProcessModel model;
  std::vector<double> domain;  // W,H of a torus
};

const Fitted& fitted(const char* file, const char* category_by, bool split) {
  static std::map<std::string, std::unique_ptr<Fitted>> cache;
  auto& entry = cache[file];
  if (!entry) {
    shapeproc::io::ReaderOptions reader;
    reader.split_subpaths = split;
    if (category_by) reader.category_by = shapeproc::io::CategoryRule::parse(category_by);
    const auto exemplar = shapeproc::io::read_scene(data(file), reader);
    entry = std::make_unique<Fitted>();
    entry->model = shapeproc::fit::fit_shape_process(exemplar, {}).model;
    const auto size = exemplar.window.sizes();
    entry->domain = {2 * size.x(), 2 * size.y()};
  }
  return *entry;
}

void BM_Sample50k(benchmark::State& state, const char* file, const char* category_by, bool split) {
  const Fitted& f = fitted(file, category_by, split);
  shapeproc::sample::SamplerOptions options;
  options.iterations = 50000;
  std::size_t elements = 0;
  const auto domain =
      shapeproc::geometry::Domain::from_sizes(f.domain, shapeproc::geometry::Boundary::torus);
  for (auto _ : state) {
    shapeproc::core::Random random(1);
    const auto result = shapeproc::sample::sample_shape_process(f.model, domain, options, random);
    elements = result.scene.elements.size();
    benchmark::DoNotOptimize(elements);
  }
  state.counters["elements"] = static_cast<double>(elements);
  state.counters["proposals/s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * 50000), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_Sample50k, dots_random, "svg/dots-random.svg", nullptr, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample50k, dashes_rows, "svg/dashes-rows.svg", nullptr, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample50k, crescents_grid, "svg/crescents-grid.svg", nullptr, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample50k, two_kinds, "svg/two-kinds.svg", "fill", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample50k, rings, "svg/rings.svg", nullptr, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample50k, bubbles, "third-party/hero-patterns/bubbles.svg", nullptr, true)
    ->Unit(benchmark::kMillisecond);

// The floor of a proposal's cost: what a birth cannot do without, one neighbour lookup and the
// exact distances (and, within the range, axes) it needs, timed alone. The configuration is the
// 50,000-step chain's output above (the model near its equilibrium); each iteration asks
// Configuration::log_interaction for an element of a random shape of it at a uniform position.
// Beside BM_Sample50k's proposals per second, it says how far the sampler is from that floor.
void BM_ProposalFloor(benchmark::State& state, const char* file, const char* category_by,
                      bool split) {
  using namespace shapeproc;
  const Fitted& f = fitted(file, category_by, split);
  const auto domain = geometry::Domain::from_sizes(f.domain, geometry::Boundary::torus);
  sample::SamplerOptions options;
  options.iterations = 50000;
  core::Random random(1);
  const auto result = sample::sample_shape_process(f.model, domain, options, random);
  const sample::ChainTables tables(f.model, domain);
  sample::Configuration configuration(*tables.interaction, *tables.geometry->measurer,
                                      tables.geometry->guard.get(), domain, tables.reach);
  std::vector<sample::Link> links;
  for (const geometry::Element& e : result.scene.elements) {
    links.clear();
    configuration.log_interaction(e, -1, links);
    configuration.add(e, 0.0, links);
  }
  std::vector<geometry::Element> asked;
  const auto box = domain.box();
  for (int k = 0; k < 4096 && !result.scene.elements.empty(); ++k) {
    geometry::Element e =
        result.scene.elements[static_cast<std::size_t>(k) % result.scene.elements.size()];
    e.position = box.min() +
                 box.sizes().cwiseProduct(geometry::Vec3(random.uniform(), random.uniform(), 0.0));
    asked.push_back(e);
  }
  std::size_t next = 0;
  for (auto _ : state) {
    links.clear();
    benchmark::DoNotOptimize(
        configuration.log_interaction(asked[next++ % asked.size()], -1, links));
  }
  state.counters["elements"] = static_cast<double>(result.scene.elements.size());
  state.counters["proposals/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_ProposalFloor, dots_random, "svg/dots-random.svg", nullptr, false);
BENCHMARK_CAPTURE(BM_ProposalFloor, dashes_rows, "svg/dashes-rows.svg", nullptr, false);
BENCHMARK_CAPTURE(BM_ProposalFloor, crescents_grid, "svg/crescents-grid.svg", nullptr, false);
BENCHMARK_CAPTURE(BM_ProposalFloor, two_kinds, "svg/two-kinds.svg", "fill", false);
BENCHMARK_CAPTURE(BM_ProposalFloor, rings, "svg/rings.svg", nullptr, true);
BENCHMARK_CAPTURE(BM_ProposalFloor, bubbles, "third-party/hero-patterns/bubbles.svg", nullptr,
                  true);

}  // namespace
BENCHMARK_MAIN();
