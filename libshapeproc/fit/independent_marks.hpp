// Categories as independent marks of one arrangement (docs/fit.md, "Clusters"). A clustered point
// pattern of several categories, a few points of each per cluster, gives each pair of categories
// too few pairs for a γ, and each category too few points for its own profile around the centres
// (data/corpus cluster-classes: 178 γ from 108 points, classes at ×0.05–×6). The fit instead
// pools the categories into one, fits that, and splits the model back: category c takes
// β_c = β n_c / n, and every pair of categories the pooled category's interaction with itself (with
// the others, its interaction with them). A multi-type process whose interactions do not depend on
// the types and whose β_c are in proportion is the pooled process with each element's category
// drawn independently, in the exemplar's shares: the split model is that process exactly.
#pragma once

#include <string>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

// The exemplar with every element in one category named `name` (its categories' names joined
// when empty).
geometry::Scene pool_categories(const geometry::Scene& exemplar, const std::string& name = {});

// Replaces the point-pattern model's category `pooled` by the categories of `marked` (the exemplar
// before pooling), in their order, at indices 0 … C − 1; the model's other categories follow in
// their order. β splits by the categories' element counts in `marked`. Throws
// std::invalid_argument for a model with shapes (not a point pattern), `pooled` out of range, or a
// category anchored to `pooled`.
void split_into_marks(model::ShapeProcessModel& model, int pooled, const geometry::Scene& marked);

}  // namespace shapeproc::fit
