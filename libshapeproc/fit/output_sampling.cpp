#include "libshapeproc/fit/output_sampling.hpp"

#include <algorithm>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/parallel_for.hpp"
#include "libshapeproc/sample/output_estimate.hpp"
#include "libshapeproc/sample/runaway.hpp"

namespace shapeproc::fit {

sample::SamplerOptions output_sampler_options(const model::ShapeProcessModel& model,
                                              const geometry::Domain& domain,
                                              const OutputSampling& sampling) {
  sample::SamplerOptions options;
  options.iterations = sampling.iterations;
  options.shift_probability = sampling.shift_probability;
  options.shift_radius = sampling.shift_radius;
  options.trace_every = sampling.trace_every;
  const int at_once = std::max(1, sampling.chains_at_once);
  const core::ResourceEstimate estimate =
      sample::estimate_output(model, domain, sampling.exemplar_density, at_once);
  if (sampling.stop_runaway) options.runaway_count = sample::runaway_count(estimate.elements);
  options.decompose =
      sampling.decompose == Decomposition::on ||
      (sampling.decompose == Decomposition::automatic && estimate.elements >= kDecomposeFrom);
  // The threads left to each chain of those that run at once.
  options.threads = std::max(1, core::loop_threads(sampling.threads, 1 << 20) / at_once);
  if (sampling.compress) options.compression.burn_in_kind = model::output_burn_in(model);
  if (options.compression.enabled() && options.iterations > 0) {
    if (options.iterations < 8)
      throw core::UsageError(
          "{iterations}: this model's outputs start with the compressing burn-in (its fit "
          "found a packed exemplar), which needs at least 8 steps");
    options.compression.release_steps = options.iterations / 4;
  }
  return options;
}

sample::ShapeProcessSampler output_sampler(const model::ShapeProcessModel& model,
                                           const geometry::Domain& domain,
                                           const OutputSampling& sampling) {
  return sample::ShapeProcessSampler(model, domain,
                                     output_sampler_options(model, domain, sampling));
}

}  // namespace shapeproc::fit
