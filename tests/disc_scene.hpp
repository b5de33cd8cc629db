// Filled discs as scene elements, for tests of overlapping and nested shapes.
#pragma once

#include "libshapeproc/geometry/arc.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::testing {

// Adds a disc of radius r centred on (x, y) as an element of category c.
inline void add_disc(geometry::Scene& scene, double x, double y, double r, int c) {
  geometry::Drawable2 d;
  d.paths.push_back(geometry::ellipse_path({x, y}, r, r));
  geometry::add_element(scene, geometry::Shape{geometry::PlanarShape{{d}}, ""}, c);
}

}  // namespace shapeproc::testing
