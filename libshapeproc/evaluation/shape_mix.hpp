// The shape mix of an output against its exemplar's (docs/metrics.md): does the output keep the
// exemplar's shares of its kinds of shape? The kinds are the exemplar's shape classes, as a fit
// makes them (fit/shape_classes.hpp: identical shapes, or size groups), within each category.
// An output element, whatever method made it and however it was turned, joins the class of its
// category whose shapes are nearest its own in size: the size of a shape is its radius about its
// centroid and its filled area (2D), both unchanged by turning and moving it. The output's class
// counts are then tested against the exemplar's shares by Pearson's chi-square. Classes whose
// shapes have one size (a stroke and its turned copy) are one kind here, since no output element
// could tell which of them it is.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/geometry/shape_size.hpp"

namespace shapeproc::evaluation {

struct ShapeMix {
  std::vector<std::string> classes;   // "category" or "category: class label"
  std::vector<int> exemplar, output;  // elements per class
  int unmatched = 0;                  // output elements of a category the exemplar does not have
  double chi_square = 0.0, p_value = 1.0;
  int degrees = 0;  // classes − 1; 0: nothing to test (a single class)
};

// The exemplar's side, once for any number of outputs: its classes, their counts, and its kinds
// of element (each category and shape once, with its size and class).
struct ShapeKinds {
  struct Kind {
    std::string category;
    geometry::ShapeSize size;
    int shape_class = 0;
  };
  std::vector<std::string> classes;
  std::vector<int> exemplar;  // elements per class
  int elements = 0;
  std::vector<Kind> kinds;
};

ShapeKinds shape_kinds(const geometry::Scene& exemplar);
ShapeMix shape_mix(const ShapeKinds& exemplar, const geometry::Scene& output);
// One-off: shape_mix(shape_kinds(exemplar), output).
ShapeMix shape_mix(const geometry::Scene& exemplar, const geometry::Scene& output);

}  // namespace shapeproc::evaluation
