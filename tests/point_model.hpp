// A point-pattern model for the tests: one category "points" of intensity β, one direction, no
// interaction (a Poisson process until a test adds some).
#pragma once

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::testing {

inline model::ShapeProcessModel point_model(double beta) {
  model::ShapeProcessModel m;
  m.categories.push_back({"points", beta});
  m.measurement.directions = 1;
  return m;
}

}  // namespace shapeproc::testing
