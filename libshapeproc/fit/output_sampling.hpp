// How an output of a fitted model is sampled, as `shapeproc sample` samples it: the model alone
// decides, through the burn-in its fit chose (model::output_burn_in: compressing or crystal, its
// steps a quarter of given iterations), with domain decomposition for large outputs and a stop
// for a chain that runs away (past sample::runaway_count of the expected elements). One function,
// output_sampler, so that every caller that promises "`sample` reproduces this with the same
// seed" (the studio's previews, the density check, fidelity) samples the same chain.
#pragma once

#include <optional>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace shapeproc::fit {

enum class Decomposition { automatic, on, off };

struct OutputSampling {
  long long iterations = 0;  // 0: until the element count is stationary
  double shift_probability = sample::SamplerOptions{}.shift_probability;
  double shift_radius = 0.0;  // 0: the sampler's default
  long long trace_every = 0;
  Decomposition decompose = Decomposition::automatic;
  int threads = 0;         // 0: one per core
  int chains_at_once = 1;  // the chains that share the threads
  bool compress = true;    // false: no compressing burn-in (a chain started from given elements)
  // Stop a chain that runs away (sample::runaway_count); false for checks that measure the model
  // as it is, however dense it gets.
  bool stop_runaway = true;
  // Elements per unit area (volume) of the exemplar (io::recorded_exemplar_density), for the
  // expected size of the output; none: estimated from the model's β.
  std::optional<double> exemplar_density;
};

// Outputs expected to hold at least this many elements are decomposed under `automatic`.
constexpr double kDecomposeFrom = 10'000;

// The sampler of outputs of `model` on `domain`. Throws core::UsageError where the model's
// compressing burn-in needs more steps than `iterations` gives (at least 8).
sample::ShapeProcessSampler output_sampler(const model::ShapeProcessModel& model,
                                           const geometry::Domain& domain,
                                           const OutputSampling& sampling = {});

// Its options, for a caller that adds its own (fixed elements, observations, shared proxies).
sample::SamplerOptions output_sampler_options(const model::ShapeProcessModel& model,
                                              const geometry::Domain& domain,
                                              const OutputSampling& sampling = {});

}  // namespace shapeproc::fit
