// How elements of different categories sit relative to one another (the relations of
// Ecormier-Nocca et al. 2019's multi-class discs, for any 2D shapes): apart, touching,
// overlapping (outlines crossing) or nested (one wholly inside the other's filled region). The
// share of each category's elements nested in, or overlapping, an element of another category
// says whether an output keeps an exemplar's decorations on their bases or mushrooms under their
// trees.
#pragma once

#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::metrics {

// inside: the first shape lies wholly in the second's filled region; contains: the reverse.
enum class Relation { apart, touching, overlapping, inside, contains };

// The relation of shape `a` at the origin and shape `b` at `offset` (2D, shape distance).
Relation relation(const geometry::PairMeasurer& measurer, int a, int b,
                  const geometry::Vec3& offset);

const char* to_string(Relation relation);

// Per category, the share of its elements that lie inside an element of another category, and
// the share that overlap one (and lie inside none). Empty vectors for 3D scenes and point
// patterns. Periodic windows (the measurer's option) use minimum-image offsets.
struct CategoryRelations {
  std::vector<double> nested, overlapping;
  bool empty() const { return nested.empty(); }
};
CategoryRelations category_relations(const geometry::Scene& scene,
                                     const geometry::PairMeasurer& measurer);

}  // namespace shapeproc::metrics
