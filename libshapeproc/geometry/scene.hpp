// Scenes: an exemplar read from a file, or a synthesised arrangement. A scene is a shape space
// (shapes in local coordinates) plus elements that place those shapes.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::geometry {

struct Category {
  std::string name;
};

// An element x = (u, s, c): reference position u (centre of the placed shape's bounding box),
// shape s (an index into Scene::shapes) and category c (an index into Scene::categories).
struct Element {
  int shape = 0;
  int category = 0;
  Vec3 position = Vec3::Zero();  // z = 0 in 2D
};

struct Scene {
  int dimension = 2;         // 2 or 3
  Box3 window;               // the observation window W; z = [0, 0] in 2D
  std::string units = "px";  // length unit of every coordinate
  std::vector<Category> categories;
  std::vector<Shape> shapes;  // local coordinates, bounding-box centre at the origin
  std::vector<Element> elements;
  std::vector<std::string> notes;  // what the reader decided or met, one sentence each

  // Area (2D) or volume (3D) of the window.
  double window_measure() const;
  // The shape of element `index` in scene coordinates.
  Shape placed_shape(std::size_t index) const;
  // Index of the category called `name`, appending it if new.
  int category_index(const std::string& name);
};

// Adds an element whose shape is given in scene coordinates: the shape is moved so that its
// bounding-box centre is the origin, stored, and placed back at that centre. Returns its index.
std::size_t add_element(Scene& scene, Shape shape_in_scene, int category);

// Per category, the number of elements.
std::vector<std::size_t> category_counts(const Scene& scene);

}  // namespace shapeproc::geometry
