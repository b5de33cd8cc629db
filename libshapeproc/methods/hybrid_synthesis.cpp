#include "libshapeproc/methods/hybrid_synthesis.hpp"

#include <limits>
#include <utility>

#include "libshapeproc/core/error.hpp"

namespace shapeproc::methods {

HybridSynthesis::HybridSynthesis(std::unique_ptr<synthesis::Synthesizer> start,
                                 model::ShapeProcessModel model, geometry::Domain domain,
                                 sample::SamplerOptions options)
    : start_(std::move(start)),
      model_(std::move(model)),
      domain_(std::move(domain)),
      options_(std::move(options)) {
  if (!start_) throw core::ArgumentError("hybrid", "no method to start from");
  if (model_.shapes.empty())
    throw core::ArgumentError("hybrid", "the model has no shapes to give the start's elements");
  for (const model::ModelShape& s : model_.shapes)
    model_sizes_.push_back(geometry::shape_size(s.shape));
  // The sampler's own checks (dimension, options), before anything runs.
  const sample::ShapeProcessSampler check(model_, domain_, options_);
}

std::vector<geometry::Element> HybridSynthesis::as_model_elements(
    const geometry::Scene& start) const {
  // Per start shape and category, the model shape it becomes (computed once).
  std::vector<int> category_of(start.categories.size(), -1);
  for (std::size_t c = 0; c < start.categories.size(); ++c)
    for (std::size_t m = 0; m < model_.categories.size(); ++m)
      if (model_.categories[m].name == start.categories[c].name)
        category_of[c] = static_cast<int>(m);
  std::vector<std::vector<int>> shape_of(start.categories.size(),
                                         std::vector<int>(start.shapes.size(), -2));
  std::vector<geometry::Element> out;
  for (geometry::Element e : start.elements) {
    const auto c = static_cast<std::size_t>(e.category);
    const int category = category_of[c];
    if (category < 0) continue;
    int& shape = shape_of[c][static_cast<std::size_t>(e.shape)];
    if (shape == -2) {
      const geometry::ShapeSize size =
          geometry::shape_size(start.shapes[static_cast<std::size_t>(e.shape)]);
      double best = std::numeric_limits<double>::infinity();
      shape = -1;
      for (std::size_t m = 0; m < model_.shapes.size(); ++m) {
        if (model_.shapes[m].category != category) continue;
        const double d = geometry::size_distance(size, model_sizes_[m]);
        if (d < best) {
          best = d;
          shape = static_cast<int>(m);
        }
      }
    }
    if (shape < 0) continue;
    e.category = category;
    e.shape = shape;
    e.position = domain_.wrap(e.position);
    out.push_back(e);
  }
  return out;
}

synthesis::SynthesisResult HybridSynthesis::synthesize(
    core::Random& random, const synthesis::ChainControl& control) const {
  const synthesis::SynthesisResult first = start_->synthesize(random, control);
  sample::SamplerOptions options = options_;
  options.start = as_model_elements(first.scene);
  const sample::ShapeProcessSampler sampler(model_, domain_, options);
  synthesis::SynthesisResult out = sampler.synthesize(random, control);
  out.record.method = method();
  std::vector<std::pair<std::string, std::string>> own = {
      {"hybrid.start_from", start_->method()},
      {"hybrid.start_elements", std::to_string(first.scene.elements.size())}};
  for (const auto& [key, value] : first.record.options) own.emplace_back("start." + key, value);
  out.record.options.insert(out.record.options.begin(), own.begin(), own.end());
  out.counters.insert(out.counters.begin(),
                      {"start elements", std::to_string(first.scene.elements.size())});
  return out;
}

}  // namespace shapeproc::methods
