#include "tools/python/arrays.hpp"

#include <stdexcept>
#include <string>

namespace shapeproc::python {

py::array_t<double> positions_array(const geometry::Scene& scene) {
  const auto n = static_cast<py::ssize_t>(scene.elements.size());
  const py::ssize_t dim = scene.dimension;
  py::array_t<double> out({n, dim});
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t k = 0; k < dim; ++k)
      view(i, k) = scene.elements[static_cast<std::size_t>(i)].position[k];
  return out;
}

py::array_t<int> categories_array(const geometry::Scene& scene) {
  py::array_t<int> out(static_cast<py::ssize_t>(scene.elements.size()));
  auto view = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < scene.elements.size(); ++i)
    view(static_cast<py::ssize_t>(i)) = scene.elements[i].category;
  return out;
}

py::array_t<double> window_array(const geometry::Scene& scene) {
  const py::ssize_t dim = scene.dimension;
  py::array_t<double> out({py::ssize_t{2}, dim});
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t k = 0; k < dim; ++k) {
    view(0, k) = scene.window.min()[k];
    view(1, k) = scene.window.max()[k];
  }
  return out;
}

py::array_t<double> vector_array(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  auto view = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) view(static_cast<py::ssize_t>(i)) = values[i];
  return out;
}

std::vector<geometry::Vec3> positions_from(const py::array_t<double>& array, int& dimension) {
  if (array.ndim() != 2 || (array.shape(1) != 2 && array.shape(1) != 3))
    throw std::invalid_argument("positions: expected an (n, 2) or (n, 3) array");
  dimension = static_cast<int>(array.shape(1));
  const auto view = array.unchecked<2>();
  std::vector<geometry::Vec3> out(static_cast<std::size_t>(array.shape(0)), geometry::Vec3::Zero());
  for (py::ssize_t i = 0; i < array.shape(0); ++i)
    for (int k = 0; k < dimension; ++k) out[static_cast<std::size_t>(i)][k] = view(i, k);
  return out;
}

geometry::Box3 window_from(const py::array_t<double>& array, int dimension) {
  geometry::Box3 box(geometry::Vec3::Zero(), geometry::Vec3::Zero());
  if (array.ndim() == 2 && array.shape(0) == 2 && array.shape(1) == dimension) {
    const auto view = array.unchecked<2>();
    for (int k = 0; k < dimension; ++k) {
      box.min()[k] = view(0, k);
      box.max()[k] = view(1, k);
    }
    return box;
  }
  if (array.ndim() == 1 && array.shape(0) == 2 * dimension) {
    const auto view = array.unchecked<1>();
    for (int k = 0; k < dimension; ++k) {
      box.min()[k] = view(2 * k);
      box.max()[k] = view(2 * k + 1);
    }
    return box;
  }
  throw std::invalid_argument("window: expected a (2, " + std::to_string(dimension) +
                              ") array or [xmin, xmax, ymin, ymax" +
                              (dimension == 3 ? ", zmin, zmax]" : "]"));
}

}  // namespace shapeproc::python
