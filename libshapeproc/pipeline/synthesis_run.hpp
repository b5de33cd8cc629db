// A whole synthesis in one call: the shape process fitted where the method needs a model, the
// method made ready on the domain, its chains run, and the outputs checked (an emptied chain is
// refused). What `shapeproc synthesize` and `shapeproc sample` do before they write their files,
// and what `compare` does for each method; writing is the caller's (io/scene_writers.hpp).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "libshapeproc/core/resource_budget.hpp"
#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/methods/synthesizer_factory.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/synthesis/run_chains.hpp"

namespace shapeproc::pipeline {

struct SynthesisRun;

// How a fitted (or loaded) model's outputs are sampled.
struct SamplingRequest {
  fit::OutputSampling sampling;  // its exemplar density and chains at once are filled in
  // Chains, threads, seed, the records' caller part, progress and cancellation.
  synthesis::ChainOptions chains;
  core::ResourceBudget budget;  // an output beyond it is refused before any chain runs
  // Called once the method is ready, before its chains run, with what the run has to say so far
  // (SynthesisRun::described, warnings): a caller may show it, or inspect the synthesizer.
  std::function<void(const synthesis::Synthesizer&, const SynthesisRun&)> ready;
};

struct SynthesisRequest {
  methods::Method method = methods::Method::shape_process;
  // The shape process and the hybrid: how the model is fitted (fit_exemplar.hpp).
  fit::ExemplarFitOptions fit;
  // The other methods' own options (a hybrid's: its start's and the sampler's).
  methods::MethodOptions options;
  SamplingRequest sample;
  // The shape process: each chain starts from the exemplar (as fitted) tiled over the domain,
  // without the compressing burn-in, instead of from empty.
  bool start_at_exemplar = false;
  // The exemplar's file, which errors about it name.
  std::string source;
  // Called with the fit as soon as it is done, before any chain runs: a caller may complete its
  // record, write it or show it.
  std::function<void(fit::ExemplarFit&)> fitted;
};

struct SynthesisRun {
  std::optional<model::ShapeProcessModel> model;    // the model fitted (shape process, hybrid)
  std::vector<synthesis::SynthesisResult> results;  // in chain order
  // What the method learnt from the exemplar, a line each (methods::describe_synthesizer), and
  // warnings about the run, for the caller to show.
  std::vector<std::string> described, warnings;
  // Elements per unit measure that the outputs' counts are judged against
  // (synthesis::check_output); 0 where the domain's mask or map changes the count, or the method
  // has no model.
  double exemplar_density = 0.0;
  bool automatic_stop = true;  // the chains ran to their own stopping rule
};

// Samples `model` on `domain`, as `shapeproc sample` does; from `start_tile` tiled over the domain
// where given. Throws core::UsageError when the output is beyond the budget ({size} names the
// domain's size) or a chain empties; core::Cancelled when cancelled.
SynthesisRun sample_model(const model::ShapeProcessModel& model, const geometry::Domain& domain,
                          const SamplingRequest& request,
                          const geometry::Scene* start_tile = nullptr);

// Synthesises outputs like `exemplar` (read with `boundary`: a seamless tile is a torus) on
// `domain` with `request.method`. Throws as sample_model does, core::InputError naming
// `request.source` for an exemplar the fit cannot take, and core::UsageError for a fit beyond the
// budget.
SynthesisRun synthesize(const geometry::Scene& exemplar, geometry::Boundary boundary,
                        const geometry::Domain& domain, const SynthesisRequest& request);

}  // namespace shapeproc::pipeline
