// The studio's previews of a model. The picture a preview settles on is exactly the output of
// `shapeproc sample MODEL --size W,H --seed S` (same options, same chain, same bytes); while that
// chain runs, a draft continues the picture on screen under the edited model for a short fixed
// number of steps, so that an edit shows within a fraction of a second (docs/studio.md,
// "Previews").
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::studio {

struct PreviewSpec {
  std::vector<double> size;  // W,H of the torus sampled, in the model's units
  std::uint64_t seed = 1;
};

// `shapeproc sample`'s output for `model` (its options: fit::output_sampler_options, one chain
// of `spec.seed` on a torus of `spec.size`). `record` holds the caller's part of the output's
// record (command, arguments, inputs). Throws core::Cancelled once `cancel` is set; `watch`, if
// given, is called every so many steps (it may set `cancel`).
synthesis::SynthesisResult sample_output(const model::ShapeProcessModel& model,
                                         const PreviewSpec& spec, synthesis::SynthesisRecord record,
                                         const std::atomic<bool>* cancel,
                                         const std::function<void()>& watch = {});

// Steps a draft takes from `start_count` elements: enough sweeps for the edited interaction to
// move every element several times, bounded so that a draft stays a fraction of a second.
long long draft_steps(std::size_t start_count);

// A draft: the chain of `model` continued from `start` (elements the hard core now forbids are
// left out) for draft_steps, without a burn-in. Deterministic in `spec.seed`; not what `sample`
// makes.
synthesis::SynthesisResult sample_draft(const model::ShapeProcessModel& model,
                                        const PreviewSpec& spec,
                                        std::vector<geometry::Element> start,
                                        const std::atomic<bool>* cancel);

}  // namespace shapeproc::studio
