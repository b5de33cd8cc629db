// Shape classes of a fitted model (model::ShapeClass): the shapes of a category that its counts
// hold together, so that samples keep the exemplar's mix of shapes.
//   1. Shapes identical up to translation form a class (their geometry in local coordinates
//      equal within kIdenticalTolerance of the exemplar window's diagonal).
//   2. Where the category has more classes than its elements support (a class under
//      kMinElementsPerClass elements), the identical-shape classes are grouped by size instead:
//      ordered by bounding-box area (volume in 3D), then diagonal, and cut into
//      G = min(kMaxSizeGroups, n_c / kMinElementsPerClass) groups of about equal element counts,
//      identical shapes never split.
//   3. A category with a single class needs none; a model whose categories all have one class
//      gets no classes (every shape of a category equally likely, as without classes).
// Each class's weight is its share of the category's elements; shapes no element uses join the
// class of the nearest size.
#pragma once

#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::fit {

inline constexpr int kMinElementsPerClass = kFitDefaults.min_elements_per_class;
inline constexpr int kMaxSizeGroups = kFitDefaults.max_size_groups;
inline constexpr double kIdenticalTolerance = 1e-5;  // of the window's diagonal

// Sets model.shape_classes and every shape's class. `model.shapes` must be the exemplar's shapes,
// in order (as model_skeleton makes them); a point model is left without classes.
void assign_shape_classes(model::ShapeProcessModel& model, const geometry::Scene& exemplar);

}  // namespace shapeproc::fit
