// A point-pattern model for the tests: one category "points" of intensity β, one direction, no
// interaction (a Poisson process until a test adds some).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/scene.hpp"
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

// Uniform points in a `side` x `side` window: counts[c].second points of category counts[c].first,
// drawn from `seed`, category after category.
inline geometry::Scene uniform_points(const std::vector<std::pair<std::string, int>>& counts,
                                      double side, std::uint64_t seed) {
  geometry::Scene scene;
  scene.window = geometry::Box3(geometry::Vec3(0, 0, 0), geometry::Vec3(side, side, 0));
  scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  core::Random random(seed);
  for (const auto& [name, count] : counts) {
    const int category = scene.category_index(name);
    for (int k = 0; k < count; ++k) {
      geometry::Element e;
      e.position = geometry::Vec3(random.uniform(0, side), random.uniform(0, side), 0);
      e.category = category;
      scene.elements.push_back(e);
    }
  }
  return scene;
}

}  // namespace shapeproc::testing
