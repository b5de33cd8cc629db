// Large outputs (run ./build/benchmarks/large_outputs MODEL [largest], largest 100000 by default,
// 1000000 for the full table; minutes): for outputs of 10^3, 10^4, ... elements up to `largest`
// at the model's recorded exemplar density, on a square torus, the decomposed sampler's run to a
// stationary count (domain_decomposition.hpp) on 1 and on 2 threads, then the whole-domain chain
// started from that output (its cost per step: 400,000 steps less 100,000). Prints per run the
// elements, steps, seconds, sweeps and microseconds per step, the speed-up of 2 threads over 1, and
// the process's peak memory so far. docs/performance.md holds the figures.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace {

using namespace shapeproc;
using Clock = std::chrono::steady_clock;

double peak_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

struct Run {
  sample::SampleResult result;
  double seconds = 0;
};

Run run(const model::ShapeProcessModel& model, const geometry::Domain& domain,
        const sample::SamplerOptions& options) {
  const sample::ShapeProcessSampler sampler(model, domain, options);
  core::Random random(1);
  const auto start = Clock::now();
  Run r;
  r.result = sampler.sample(random);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: large_outputs MODEL.json [largest elements, default 100000]\n");
    return 2;
  }
  try {
    const model::ShapeProcessModel model = io::read_model(argv[1]);
    const double largest = argc > 2 ? std::atof(argv[2]) : 1e5;
    const std::optional<double> density = io::recorded_exemplar_density(model);
    if (!density || model.dimension != 2) {
      std::fprintf(stderr, "large_outputs: needs a 2D model with its fit record\n");
      return 2;
    }
    std::printf(
        "| target elements | side | threads | elements | steps | sweeps | cells | seconds | "
        "µs per step | speed-up | whole-domain µs per step | peak MB |\n|---|---|---|---|---|---|"
        "---|---|---|---|---|---|\n");
    for (double target = 1e3; target <= largest * 1.0001; target *= 10) {
      const double side = std::sqrt(target / *density);
      const geometry::Domain domain =
          geometry::Domain::from_sizes({side, side}, geometry::Boundary::torus);
      double one_thread = 0;
      for (int threads : {1, 2}) {
        if (threads == 1 && target > 1e5) continue;  // the million on 2 threads only
        sample::SamplerOptions options;
        options.decompose = true;
        options.threads = threads;
        const Run cut = run(model, domain, options);
        if (threads == 1) one_thread = cut.seconds;
        // The whole-domain chain's cost per step at this size: 400,000 steps less 100,000 from
        // the same start (which costs a measurement per element to set up).
        sample::SamplerOptions whole;
        whole.start = cut.result.scene.elements;
        whole.iterations = 100000;
        const double shorter = run(model, domain, whole).seconds;
        whole.iterations = 400000;
        const double longer = run(model, domain, whole).seconds;
        std::printf(
            "| %.0f | %.0f | %d | %zu | %lld | %d | %d | %.1f | %.2f | %s | %.2f | %.0f |\n",
            target, side, threads, cut.result.scene.elements.size(), cut.result.iterations,
            cut.result.sweeps, cut.result.cells, cut.seconds,
            1e6 * cut.seconds / static_cast<double>(cut.result.iterations),
            threads == 2 && one_thread > 0
                ? (std::to_string(one_thread / cut.seconds).substr(0, 4)).c_str()
                : "–",
            1e6 * (longer - shorter) / 300000.0, peak_megabytes());
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "large_outputs: %s\n", e.what());
    return 1;
  }
  return 0;
}
