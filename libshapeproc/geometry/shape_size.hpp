// The size of a shape, unchanged by moving or turning it: its radius about the centroid of its
// outline points (mesh vertices in 3D) and its filled area (2D; 0 in 3D and for points). It tells
// which drawn shape an element of any output is, whatever method placed and turned it
// (evaluation/shape_mix.hpp, compare/hybrid_synthesis.hpp).
#pragma once

#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::geometry {

struct ShapeSize {
  double radius = 0.0, area = 0.0;
};

ShapeSize shape_size(const Shape& shape);

// Σ |log ratio| of radius and area: 0 for equal sizes, about 0.01 for sizes 1% apart.
double size_distance(const ShapeSize& a, const ShapeSize& b);

}  // namespace shapeproc::geometry
