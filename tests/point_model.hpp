// A point-pattern model for the tests: one category "points" of intensity β, one direction, no
// interaction (a Poisson process until a test adds some).
#pragma once

#include <vector>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::testing {

inline model::ShapeProcessModel point_model(double beta) {
  model::ShapeProcessModel m;
  m.categories.push_back({"points", beta});
  m.measurement.directions = 1;
  return m;
}

// The same with one isotropic interaction of the points with themselves: hard core below
// thresholds[0], γ_k on [thresholds[k-1], thresholds[k]).
inline model::ShapeProcessModel point_model(double beta, std::vector<double> thresholds,
                                            std::vector<double> gammas) {
  model::ShapeProcessModel m = point_model(beta);
  model::PairInteraction pair;
  model::AxisParameters axis;
  axis.thresholds = std::move(thresholds);
  axis.gammas = std::move(gammas);
  pair.axes = {axis};
  m.interactions = {pair};
  return m;
}

}  // namespace shapeproc::testing
