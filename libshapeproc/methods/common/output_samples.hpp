// The neighbourhood EM's output while it is being synthesised: samples (positions, ids, keys)
// grouped by element, and for each element the exemplar element it copies (its q: shape,
// category, shape class).
#pragma once

#include <vector>

#include "libshapeproc/methods/common/em_exemplar.hpp"

namespace shapeproc::methods {

struct OutputSamples {
  ElementSamples samples;
  std::vector<int> source;     // per element: the exemplar element whose attributes it has
  std::vector<int> attribute;  // per sample: its element's source's attribute code

  std::size_t elements() const { return source.size(); }
  // Appends an element copying exemplar element `source`, its samples at the template's offsets
  // from `position` (turned by `radians` about z). Returns its index.
  int add(const EmExemplar& exemplar, int source, const Vec3& position, double radians = 0.0);
  // Makes element `e` copy exemplar element `source` instead (same sample count).
  void set_source(const EmExemplar& exemplar, int e, int source);
};

}  // namespace shapeproc::methods
