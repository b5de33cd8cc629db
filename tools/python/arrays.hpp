// NumPy views of a scene for the Python module: positions as an (n, dim) float array, categories
// as an (n,) int array, and the reverse for scenes made from arrays.
#pragma once

#include <pybind11/numpy.h>

#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::python {

namespace py = pybind11;

py::array_t<double> positions_array(const geometry::Scene& scene);
py::array_t<int> categories_array(const geometry::Scene& scene);
// The window as a (2, dim) array: its lower corner, then its upper one.
py::array_t<double> window_array(const geometry::Scene& scene);
py::array_t<double> vector_array(const std::vector<double>& values);

// Rows of an (n, 2) or (n, 3) array as positions (z = 0 in 2D); throws std::invalid_argument for
// another shape. Sets `dimension`.
std::vector<geometry::Vec3> positions_from(const py::array_t<double>& array, int& dimension);
// A (2, dim) array, or a flat [xmin, xmax, ymin, ymax(, zmin, zmax)] list, as a box.
geometry::Box3 window_from(const py::array_t<double>& array, int dimension);

}  // namespace shapeproc::python
