#include "libshapeproc/studio/preview_chain.hpp"

#include <algorithm>

#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/run_chains.hpp"

namespace shapeproc::studio {

namespace {

synthesis::SynthesisResult run_one(const sample::ShapeProcessSampler& sampler,
                                   const PreviewSpec& spec, synthesis::SynthesisRecord record,
                                   const std::atomic<bool>* cancel,
                                   const std::function<void()>& watch = {}) {
  synthesis::ChainOptions chains;
  chains.seed = spec.seed;
  chains.record = std::move(record);
  chains.cancel = cancel;
  if (watch) chains.progress = [&watch](long long, long long) { watch(); };
  return std::move(synthesis::run_chains(sampler, chains).front());
}

}  // namespace

synthesis::SynthesisResult sample_output(const model::ShapeProcessModel& model,
                                         const PreviewSpec& spec, synthesis::SynthesisRecord record,
                                         const std::atomic<bool>* cancel,
                                         const std::function<void()>& watch) {
  const geometry::Domain domain =
      geometry::Domain::from_sizes(spec.size, geometry::Boundary::torus);
  fit::OutputSampling sampling;
  sampling.exemplar_density = io::recorded_exemplar_density(model);
  const sample::ShapeProcessSampler sampler(model, domain,
                                            fit::output_sampler_options(model, domain, sampling));
  return run_one(sampler, spec, std::move(record), cancel, watch);
}

long long draft_steps(std::size_t start_count) {
  // 200 steps per element (a third of them shifts: some 65 moves each), at least 20,000 and at
  // most 120,000 (about 0.2 s at the sampler's one to two microseconds per step on the shipped
  // exemplars' previews).
  return std::clamp<long long>(200 * static_cast<long long>(start_count), 20'000, 120'000);
}

synthesis::SynthesisResult sample_draft(const model::ShapeProcessModel& model,
                                        const PreviewSpec& spec,
                                        std::vector<geometry::Element> start,
                                        const std::atomic<bool>* cancel) {
  const geometry::Domain domain =
      geometry::Domain::from_sizes(spec.size, geometry::Boundary::torus);
  sample::SamplerOptions options;
  options.iterations = draft_steps(start.size());
  options.start = std::move(start);
  options.threads = 1;
  const sample::ShapeProcessSampler sampler(model, domain, options);
  synthesis::SynthesisRecord record;
  record.command = "studio draft";
  return run_one(sampler, spec, std::move(record), cancel);
}

}  // namespace shapeproc::studio
