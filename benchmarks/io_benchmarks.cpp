// Reader throughput on the shipped exemplars (run ./build/benchmarks/io_benchmarks).
#include <benchmark/benchmark.h>

#include "libshapeproc/io/scene_io.hpp"

namespace {

using shapeproc::io::ReaderOptions;

std::string data(const char* relative) { return std::string(SHAPEPROC_DATA_DIR) + "/" + relative; }

void BM_ReadSvg(benchmark::State& state, const char* file, bool split) {
  ReaderOptions options;
  options.split_subpaths = split;
  const std::string path = data(file);
  std::size_t elements = 0;
  for (auto _ : state) {
    const auto scene = shapeproc::io::read_scene(path, options);
    elements = scene.elements.size();
    benchmark::DoNotOptimize(elements);
  }
  state.counters["elements"] = static_cast<double>(elements);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * elements));
}
BENCHMARK_CAPTURE(BM_ReadSvg, two_kinds, "svg/two-kinds.svg", false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ReadSvg, rings_split, "svg/rings.svg", true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ReadSvg, bubbles_split, "third-party/hero-patterns/bubbles.svg", true)
    ->Unit(benchmark::kMicrosecond);

void BM_ReadMesh(benchmark::State& state) {
  const std::string path = data("mesh/pebbles.obj");
  for (auto _ : state) {
    const auto scene = shapeproc::io::read_scene(path, {});
    benchmark::DoNotOptimize(scene.elements.size());
  }
}
BENCHMARK(BM_ReadMesh)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
