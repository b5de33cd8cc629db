#include "libshapeproc/pipeline/synthesis_run.hpp"

#include <memory>
#include <stdexcept>
#include <utility>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/fit/fit_estimate.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/sample/output_estimate.hpp"
#include "libshapeproc/synthesis/output_check.hpp"

namespace shapeproc::pipeline {

namespace {

// The chains of `synthesizer`, refused when one emptied.
void run(const synthesis::Synthesizer& synthesizer, const SamplingRequest& request,
         SynthesisRun& run) {
  if (request.ready) request.ready(synthesizer, run);
  run.results = synthesis::run_chains(synthesizer, request.chains);
  synthesis::refuse_emptied(run.results, run.exemplar_density, run.automatic_stop);
}

// The budget of an output at the exemplar's density, checked before anything is fitted.
void check_output_budget(const geometry::Scene& exemplar, const geometry::Domain& domain,
                         const SamplingRequest& request) {
  const double measure = exemplar.window_measure();
  if (!(measure > 0)) return;
  const double density = static_cast<double>(exemplar.elements.size()) / measure;
  const int at_once = synthesis::chains_at_once(request.chains.chains, request.chains.threads);
  core::check_budget(sample::estimate_output(density, domain, exemplar.dimension, at_once),
                     request.budget, "the output", "{size}");
}

fit::ExemplarFit fit_model(const geometry::Scene& exemplar, const SynthesisRequest& request) {
  core::check_budget(fit::estimate_fit(exemplar, request.fit.fit).resources, request.sample.budget,
                     "the fit of " + request.source,
                     "{quadrature}, {directions} or the thresholds");
  fit::ExemplarFit fit;
  try {
    fit = fit::fit_exemplar(exemplar, request.fit);
  } catch (const std::invalid_argument& e) {
    throw core::InputError(request.source, 0, e.what());
  }
  if (request.fitted) request.fitted(fit);
  return fit;
}

}  // namespace

SynthesisRun sample_model(const model::ShapeProcessModel& model, const geometry::Domain& domain,
                          const SamplingRequest& request, const geometry::Scene* start_tile) {
  const int at_once = synthesis::chains_at_once(request.chains.chains, request.chains.threads);
  const std::optional<double> density = io::recorded_exemplar_density(model);
  core::check_budget(sample::estimate_output(model, domain, density, at_once), request.budget,
                     "the output", "{size}");
  fit::OutputSampling sampling = request.sampling;
  sampling.exemplar_density = density;
  sampling.chains_at_once = at_once;
  sampling.compress = start_tile == nullptr;
  sample::SamplerOptions options = fit::output_sampler_options(model, domain, sampling);
  SynthesisRun out;
  if (start_tile) {
    options.start = geometry::tile_over(*start_tile, domain.box());
    out.described.push_back("start: the exemplar tiled over the output (" +
                            std::to_string(options.start.size()) +
                            " elements): the output begins as a copy of the exemplar, which the "
                            "chain then moves");
  }
  const sample::ShapeProcessSampler sampler(model, domain, options);
  if (sampler.torus_smaller_than_reach())
    out.warnings.push_back(
        "the output torus is smaller than twice the model's reach (" +
        core::format_general(2 * sampler.reach(), 4) +
        "): elements meet their own images, and pairs seen at a nearer image may be refused; "
        "give a larger {size}");
  // The count to expect, on a plain box (a mask or an intensity map changes it).
  out.exemplar_density = domain.has_local_factor() ? 0.0 : density.value_or(0.0);
  out.automatic_stop = request.sampling.iterations <= 0;
  run(sampler, request, out);
  return out;
}

SynthesisRun synthesize(const geometry::Scene& exemplar, geometry::Boundary boundary,
                        const geometry::Domain& domain, const SynthesisRequest& request) {
  using methods::Method;
  check_output_budget(exemplar, domain, request.sample);
  std::optional<fit::ExemplarFit> fit;
  if (request.method == Method::shape_process || request.method == Method::hybrid)
    fit = fit_model(exemplar, request);
  if (request.method == Method::shape_process) {
    SynthesisRun out = sample_model(fit->result.model, domain, request.sample,
                                    request.start_at_exemplar ? &fit->exemplar : nullptr);
    out.model = std::move(fit->result.model);
    return out;
  }
  const auto synthesizer =
      methods::make_synthesizer(request.method, exemplar, boundary, domain, request.options,
                                fit ? &fit->result.model : nullptr);
  SynthesisRun out;
  out.described = methods::describe_synthesizer(*synthesizer, exemplar, request.options);
  out.automatic_stop = request.sample.sampling.iterations <= 0;
  run(*synthesizer, request.sample, out);
  if (fit) out.model = std::move(fit->result.model);
  return out;
}

}  // namespace shapeproc::pipeline
