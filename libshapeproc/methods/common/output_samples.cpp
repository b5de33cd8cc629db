#include "libshapeproc/methods/common/output_samples.hpp"

#include "libshapeproc/core/assert.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"

namespace shapeproc::methods {

int OutputSamples::add(const EmExemplar& exemplar, int from, const Vec3& position, double radians) {
  const geometry::Element& element = exemplar.scene.elements[static_cast<std::size_t>(from)];
  const SampleTemplate& t = exemplar.templates[static_cast<std::size_t>(element.shape)];
  const int count = static_cast<int>(t.offsets.size());
  const int index = static_cast<int>(source.size());
  if (samples.first.empty()) samples.first.push_back(0);
  for (int k = 0; k < count; ++k) {
    samples.positions.push_back(position +
                                turn_about_z(t.offsets[static_cast<std::size_t>(k)], radians));
    samples.element.push_back(index);
    samples.sample_id.push_back(k);
    samples.key.push_back(sample_key(count, k));
    attribute.push_back(exemplar.attribute[static_cast<std::size_t>(from)]);
  }
  samples.first.push_back(static_cast<int>(samples.positions.size()));
  source.push_back(from);
  return index;
}

void OutputSamples::set_source(const EmExemplar& exemplar, int e, int from) {
  const auto index = static_cast<std::size_t>(e);
  SHAPEPROC_ASSERT(samples.count_of(e) == exemplar.samples.count_of(from),
                   "a source with the element's sample count");
  source[index] = from;
  for (int s = samples.first[index]; s < samples.first[index + 1]; ++s)
    attribute[static_cast<std::size_t>(s)] = exemplar.attribute[static_cast<std::size_t>(from)];
}

}  // namespace shapeproc::methods
