// Pair measurements: d and o between two elements, and all pairs of a 1,000-element exemplar.
// Run: ./build/benchmarks/measurement_benchmarks
#include <benchmark/benchmark.h>

#include <random>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "tests/geometry/measurement_fixtures.hpp"

namespace {

using namespace shapeproc::geometry;

// Two regular n-gons of radius 1, 0.2 apart, one rotated by half a step.
Scene two_polygons(int n) {
  std::vector<Vec2> a, b;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * 3.14159265358979323846 * k / n;
    a.emplace_back(std::cos(angle), std::sin(angle));
    b.emplace_back(std::cos(angle + 3.14159265358979323846 / n),
                   std::sin(angle + 3.14159265358979323846 / n));
  }
  return fixtures::scene_of(
      {fixtures::planar({fixtures::polygon(a)}), fixtures::planar({fixtures::polygon(b)})},
      {{0, 0}, {2.1, 0.4}});
}

MeasurementOptions exact_proxies() {
  MeasurementOptions options;
  options.proxy.tolerance = 0.0;  // keep every segment: the proxy is the polygon itself
  return options;
}

void BM_Distance2D(benchmark::State& state) {
  const Scene scene = two_polygons(static_cast<int>(state.range(0)));
  const PairMeasurer measurer(scene, exact_proxies());
  const Vec3 offset = scene.elements[1].position - scene.elements[0].position;
  for (auto _ : state) benchmark::DoNotOptimize(measurer.distance(0, 1, offset));
  state.counters["segments"] = static_cast<double>(measurer.proxies2()[0].segment_count());
}
BENCHMARK(BM_Distance2D)->Arg(8)->Arg(50)->Arg(500);

// The direction between the scene's two shapes, the second at `offset` from the first.
void time_direction(benchmark::State& state, const Scene& scene, const Vec3& offset) {
  const PairMeasurer measurer(scene, exact_proxies());
  for (auto _ : state) benchmark::DoNotOptimize(measurer.direction(0, 1, offset));
  state.counters["segments"] = static_cast<double>(measurer.proxies2()[0].segment_count());
}

// Near: the polygons 0.2 apart. Apart: their centres 5 apart (2.5 times the sum of their radii),
// the pair's multipole expansion (its table built on the first call).
void BM_Direction2D(benchmark::State& state, bool apart) {
  const Scene scene = two_polygons(static_cast<int>(state.range(0)));
  time_direction(
      state, scene,
      apart ? Vec3(4.0, 3.0, 0.0) : Vec3(scene.elements[1].position - scene.elements[0].position));
}
BENCHMARK_CAPTURE(BM_Direction2D, near, false)->Arg(8)->Arg(50)->Arg(500);
BENCHMARK_CAPTURE(BM_Direction2D, apart, true)->Arg(8)->Arg(50)->Arg(500);

// Two gears of n corners (radius 1 and 0.9 alternating, like a stamp's perforations: not round, so
// no circle decides), 0.15 apart: the edge pairs near the contact, the other shape's edge clusters
// further away.
Scene two_gears(int n) {
  std::vector<Vec2> a;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * 3.14159265358979323846 * k / n, radius = k % 2 == 0 ? 1.0 : 0.9;
    a.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  return fixtures::scene_of(
      {fixtures::planar({fixtures::polygon(a)}), fixtures::planar({fixtures::polygon(a)})},
      {{0, 0}, {2.15, 0.0}});
}

void BM_DirectionGears(benchmark::State& state) {
  const Scene scene = two_gears(static_cast<int>(state.range(0)));
  time_direction(state, scene, scene.elements[1].position - scene.elements[0].position);
}
BENCHMARK(BM_DirectionGears)->Arg(50)->Arg(500)->Arg(2000);

// The axis of the two gears' direction over a chain-like stream of offsets: 4,096 offsets near
// contact (centres 2.0–2.3 apart, within 0.3 of the line of centres), asked over and over. With
// the table (table = 1) against the exact integral each time (table = 0); `answered` is the
// table's share of the queries.
void BM_AxisFromTable(benchmark::State& state, bool table) {
  const Scene scene = two_gears(static_cast<int>(state.range(0)));
  const PairMeasurer measurer(scene, exact_proxies());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> along(2.0, 2.3), across(-0.3, 0.3);
  std::vector<Vec3> offsets;
  for (int k = 0; k < 4096; ++k) offsets.emplace_back(along(rng), across(rng), 0.0);
  std::size_t next = 0;
  for (auto _ : state) {
    const Vec3& offset = offsets[next++ % offsets.size()];
    benchmark::DoNotOptimize(table ? measurer.axis(0, 1, offset)
                                   : measurer.bins().axis_of(measurer.direction(0, 1, offset)));
  }
  state.counters["segments"] = static_cast<double>(measurer.proxies2()[0].segment_count());
  if (table) {
    state.counters["answered"] = static_cast<double>(measurer.force_table()->answered()) /
                                 static_cast<double>(measurer.force_table()->queries());
  }
}
BENCHMARK_CAPTURE(BM_AxisFromTable, exact, false)->Arg(500)->Iterations(20000);
BENCHMARK_CAPTURE(BM_AxisFromTable, table, true)->Arg(500)->Iterations(20000);

// UV spheres of radius 1, 0.2 apart: 50 triangles (5 x 6) or 500 (25 x 11).
Scene two_spheres(int triangles) {
  const TriangleMesh mesh =
      triangles <= 50 ? fixtures::uv_sphere(1, 5, 6) : fixtures::uv_sphere(1, 25, 11);
  return fixtures::scene_of_meshes({mesh, mesh}, {{0, 0, 0}, {2.1, 0.3, 0.2}});
}

// d (what = 0) or o (what = 1) between the two spheres.
void BM_Spheres(benchmark::State& state, int what) {
  const Scene scene = two_spheres(static_cast<int>(state.range(0)));
  MeasurementOptions options = exact_proxies();
  options.directions = 12;
  const PairMeasurer measurer(scene, options);
  const Vec3 offset = scene.elements[1].position - scene.elements[0].position;
  for (auto _ : state) {
    if (what == 0)
      benchmark::DoNotOptimize(measurer.distance(0, 1, offset));
    else
      benchmark::DoNotOptimize(measurer.direction(0, 1, offset));
  }
  state.counters["triangles"] = static_cast<double>(measurer.proxies3()[0].triangles.size());
}
BENCHMARK_CAPTURE(BM_Spheres, distance3d, 0)->Arg(50)->Arg(500);
BENCHMARK_CAPTURE(BM_Spheres, direction3d, 1)->Arg(50)->Arg(500);

// 1,000 random 12-gons (radius 0.4 to 1) at density about 0.25 per unit area, each its own shape.
Scene thousand_elements() {
  std::mt19937 rng(1000);
  std::uniform_real_distribution<double> position(0, 63);
  std::vector<Shape> shapes;
  std::vector<Vec2> positions;
  for (int i = 0; i < 1000; ++i) {
    shapes.push_back(fixtures::random_polygon(rng, 12, 1.0));
    positions.emplace_back(position(rng), position(rng));
  }
  return fixtures::scene_of(shapes, positions, Box3(Vec3(0, 0, 0), Vec3(63, 63, 0)));
}

void BM_AllPairs1000(benchmark::State& state) {
  const Scene scene = thousand_elements();
  MeasurementOptions options;
  options.distance = state.range(0) == 0 ? DistanceKind::shape : DistanceKind::shape;
  const PairMeasurer measurer(scene, options);
  const double range =
      state.range(0) == 0 ? PairMeasurer::kNoCutoff : static_cast<double>(state.range(0));
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = measurer.all_pairs(scene.elements, range).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}
// 0: every pair (d and o for all 499,500); 3: pairs closer than 3 units (about 2 radii).
BENCHMARK(BM_AllPairs1000)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_AllDistances1000(benchmark::State& state) {
  const Scene scene = thousand_elements();
  const PairMeasurer measurer(scene, MeasurementOptions{});
  for (auto _ : state) {
    double sum = 0;
    for (std::size_t i = 0; i < scene.elements.size(); ++i)
      for (std::size_t j = i + 1; j < scene.elements.size(); ++j)
        sum += measurer.distance(scene.elements[i].shape, scene.elements[j].shape,
                                 scene.elements[j].position - scene.elements[i].position);
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_AllDistances1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
