#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry {

double Scene::window_measure() const {
  if (window.isEmpty()) return 0.0;
  const Vec3 sizes = window.sizes();
  return dimension == 3 ? sizes.prod() : sizes.x() * sizes.y();
}

Shape Scene::placed_shape(std::size_t index) const {
  const Element& element = elements.at(index);
  Shape shape = shapes.at(static_cast<std::size_t>(element.shape));
  translate(shape, element.position);
  return shape;
}

int Scene::category_index(const std::string& name) {
  for (std::size_t i = 0; i < categories.size(); ++i) {
    if (categories[i].name == name) return static_cast<int>(i);
  }
  categories.push_back({name});
  return static_cast<int>(categories.size() - 1);
}

std::size_t add_element(Scene& scene, Shape shape_in_scene, int category) {
  const Vec3 centre = bounding_box(shape_in_scene).center();
  translate(shape_in_scene, -centre);
  scene.shapes.push_back(std::move(shape_in_scene));
  Element element;
  element.shape = static_cast<int>(scene.shapes.size() - 1);
  element.category = category;
  element.position = centre;
  scene.elements.push_back(element);
  return scene.elements.size() - 1;
}

std::vector<std::size_t> category_counts(const Scene& scene) {
  std::vector<std::size_t> counts(scene.categories.size(), 0);
  for (const Element& e : scene.elements) ++counts.at(static_cast<std::size_t>(e.category));
  return counts;
}

}  // namespace shapeproc::geometry
