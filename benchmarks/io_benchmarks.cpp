// Reader throughput on the shipped exemplars (run ./build/benchmarks/io_benchmarks).
#include <benchmark/benchmark.h>

#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/svg_reader.hpp"

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

// Hostile sizes: n style-sheet rules, one per element (each element of class cN), and n subpaths
// nested inside each other in one path. Time per element or subpath should not grow with n.
std::string many_rules(int n) {
  std::string rules, elements;
  for (int i = 0; i < n; ++i) {
    rules += ".c" + std::to_string(i) + " { fill: #" + std::to_string(100000 + i % 800000) + " }\n";
    elements += "<rect class=\"c" + std::to_string(i) + "\" x=\"" + std::to_string(10 * (i % 100)) +
                "\" y=\"" + std::to_string(10 * (i / 100)) + "\" width=\"4\" height=\"4\"/>";
  }
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 1000 1000\"><style>" + rules +
         "</style>" + elements + "</svg>";
}

std::string nested_subpaths(int n) {
  std::string d;
  for (int i = 1; i <= n; ++i) {
    const double half = 0.1 * i;
    d += "M" + std::to_string(3000 - half) + " " + std::to_string(3000 - half) + "h" +
         std::to_string(2 * half) + "v" + std::to_string(2 * half) + "h" +
         std::to_string(-2 * half) + "z ";
  }
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 6000 6000\"><path "
         "fill-rule=\"evenodd\" d=\"" +
         d + "\"/></svg>";
}

void BM_ReadHostileSvg(benchmark::State& state, std::string (*make)(int)) {
  const std::string text = make(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const auto scene = shapeproc::io::parse_svg(text, "hostile.svg", {});
    benchmark::DoNotOptimize(scene.elements.size());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK_CAPTURE(BM_ReadHostileSvg, style_sheet_rules, many_rules)
    ->Arg(5000)
    ->Arg(10000)
    ->Arg(20000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReadHostileSvg, nested_subpaths, nested_subpaths)
    ->Arg(2500)
    ->Arg(5000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
