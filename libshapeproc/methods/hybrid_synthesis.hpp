// Beyond any published method: a neighbourhood method's output, made collision-free and
// statistically consistent by the shape process fitted to the same exemplar. The start method
// (the neighbourhood EM, region growing or seed-and-grow) gives the structure; the shape-process
// sampler then runs from its output at the fitted model, with shift and birth-death moves, until
// its element count is stationary (or for the given steps).
//
// Each output element of the start becomes the model's shape, in its category (by name), nearest
// its own in size (geometry/shape_size.hpp: turned copies included); the sampler leaves out any
// that the model's hard core forbids beside those before it (sample::SamplerOptions::start). The
// record says so: method "hybrid", hybrid.start_from, and how many start elements were kept.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/shape_size.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::methods {

class HybridSynthesis : public synthesis::Synthesizer {
 public:
  // Throws core::ArgumentError for a model without shapes or of another dimension than the
  // domain (as the sampler does).
  HybridSynthesis(std::unique_ptr<synthesis::Synthesizer> start, model::ShapeProcessModel model,
                  geometry::Domain domain, sample::SamplerOptions options);

  std::string method() const override { return "hybrid"; }
  synthesis::SynthesisResult synthesize(core::Random& random,
                                        const synthesis::ChainControl& control) const override;

  // The start's elements as elements of the model (category and shape), each once; elements of a
  // category the model does not have are left out.
  std::vector<geometry::Element> as_model_elements(const geometry::Scene& start) const;

 private:
  std::unique_ptr<synthesis::Synthesizer> start_;
  model::ShapeProcessModel model_;
  geometry::Domain domain_;
  sample::SamplerOptions options_;
  std::vector<geometry::ShapeSize> model_sizes_;  // per model shape
};

}  // namespace shapeproc::methods
