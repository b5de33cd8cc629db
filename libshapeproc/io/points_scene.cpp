#include "libshapeproc/io/points_scene.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "libshapeproc/geometry/arc.hpp"

namespace shapeproc::io {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("points: " + what);
}

}  // namespace

geometry::Shape disc_shape(double r) {
  geometry::Drawable2 drawable;
  drawable.paths.push_back(geometry::ellipse_path(geometry::Vec2::Zero(), r, r));
  drawable.style["fill"] = "#000000";
  return geometry::Shape{geometry::PlanarShape{{std::move(drawable)}}, "disc"};
}

geometry::Scene points_scene(const PointsInput& input) {
  require(input.dimension == 2 || input.dimension == 3, "the dimension must be 2 or 3");
  const std::size_t n = input.positions.size();
  require(input.categories.empty() || input.categories.size() == n,
          std::to_string(input.categories.size()) + " categories for " + std::to_string(n) +
              " positions");
  require(input.radii.empty() || input.radii.size() == n,
          std::to_string(input.radii.size()) + " radii for " + std::to_string(n) + " positions");
  require(input.radii.empty() || input.dimension == 2, "discs (radii) are 2D only");
  const geometry::Box3& w = input.window;
  for (int axis = 0; axis < input.dimension; ++axis)
    require(std::isfinite(w.min()[axis]) && std::isfinite(w.max()[axis]) &&
                w.max()[axis] > w.min()[axis],
            "the window is empty or not finite along axis " + std::to_string(axis));
  geometry::Scene scene;
  scene.dimension = input.dimension;
  scene.window = w;
  if (input.dimension == 2) scene.window.min().z() = scene.window.max().z() = 0.0;
  scene.units = input.units;
  int categories = 1;
  for (int c : input.categories) {
    require(c >= 0, "category " + std::to_string(c) + " is negative");
    categories = std::max(categories, c + 1);
  }
  require(
      input.category_names.empty() || static_cast<int>(input.category_names.size()) >= categories,
      std::to_string(input.category_names.size()) + " category names for " +
          std::to_string(categories) + " categories");
  for (int c = 0; c < categories; ++c)
    scene.category_index(input.category_names.empty() ? std::to_string(c)
                                                      : input.category_names[c]);
  if (input.radii.empty()) scene.shapes.push_back(geometry::Shape{geometry::PointShape{}, "point"});
  std::map<double, int> shape_of_radius;
  for (std::size_t i = 0; i < n; ++i) {
    geometry::Element e;
    e.position = input.positions[i];
    if (input.dimension == 2) e.position.z() = 0.0;
    for (int axis = 0; axis < input.dimension; ++axis)
      require(std::isfinite(e.position[axis]) && e.position[axis] >= w.min()[axis] &&
                  e.position[axis] <= w.max()[axis],
              "position " + std::to_string(i) + " is not finite or lies outside the window");
    e.category = input.categories.empty() ? 0 : input.categories[i];
    if (!input.radii.empty()) {
      const double r = input.radii[i];
      require(std::isfinite(r) && r > 0, "radius " + std::to_string(i) + " is not positive");
      const auto [it, added] = shape_of_radius.emplace(r, static_cast<int>(scene.shapes.size()));
      if (added) scene.shapes.push_back(disc_shape(r));
      e.shape = it->second;
    }
    scene.elements.push_back(e);
  }
  return scene;
}

}  // namespace shapeproc::io
