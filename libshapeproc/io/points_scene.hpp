// A scene made from coordinates a program already holds (the Python module's arrays, a CSV
// file's rows): points, or discs of given radii, with categories, in a window.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::io {

struct PointsInput {
  int dimension = 2;
  geometry::Box3 window;  // z = [0, 0] in 2D
  std::vector<geometry::Vec3> positions;
  std::vector<int> categories;              // empty: every element in category 0
  std::vector<std::string> category_names;  // empty: "0", "1", …
  std::vector<double> radii;                // empty: points; else a disc per element (2D only)
  std::string units = "1";
};

// The disc of radius r centred on the origin: a filled circle, as an SVG <circle> reads.
geometry::Shape disc_shape(double r);

// The scene of `input`: one point shape, or one disc shape per distinct radius. Throws
// std::invalid_argument naming what is wrong: sizes that disagree, a coordinate or radius that
// is not finite and positive, a position outside the window, a category without a name, discs in
// 3D, an empty window.
geometry::Scene points_scene(const PointsInput& input);

}  // namespace shapeproc::io
