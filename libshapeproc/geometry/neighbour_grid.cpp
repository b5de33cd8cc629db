#include "libshapeproc/geometry/neighbour_grid.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::geometry {

NeighbourGrid::NeighbourGrid(const geometry::Box3& window, int dimension, double cell_size,
                             bool periodic)
    : NeighbourGrid(window, dimension, cell_size, {periodic, periodic, periodic}) {}

NeighbourGrid::NeighbourGrid(const geometry::Box3& window, int dimension, double cell_size,
                             const std::array<bool, 3>& periodic_axes)
    : window_(window), dimension_(dimension), periodic_(periodic_axes) {
  const geometry::Vec3 sizes = window.sizes();
  for (int axis = 0; axis < 3; ++axis) {
    const bool used = axis < dimension && sizes[axis] > 0;
    // At most 1024 cells per axis in 2D (a million cells, 24 MB empty; 256 until the
    // million-element outputs, which put several elements in a cell) and 64 in 3D (a 256³ grid of
    // empty cells took 400 MB); a cell never smaller than cell_size.
    const int most = dimension == 3 ? 64 : 1024;
    const int n = used && cell_size > 0
                      ? std::clamp(static_cast<int>(std::floor(sizes[axis] / cell_size)), 1, most)
                      : 1;
    counts_[axis] = n;
    cell_[axis] = used ? sizes[axis] / n : 1.0;
  }
  for (int axis = 0; axis < dimension; ++axis)
    repeats_ = repeats_ || (periodic_[static_cast<std::size_t>(axis)] && counts_[axis] < 3);
  cells_.resize(static_cast<std::size_t>(counts_.prod()));
}

Eigen::Vector3i NeighbourGrid::cell_of(const geometry::Vec3& p) const {
  Eigen::Vector3i c;
  for (int axis = 0; axis < 3; ++axis) {
    const double t = (p[axis] - window_.min()[axis]) / cell_[axis];
    c[axis] = std::clamp(static_cast<int>(std::floor(t)), 0, counts_[axis] - 1);
  }
  return c;
}

bool NeighbourGrid::wrap(Eigen::Vector3i& c) const {
  for (int axis = 0; axis < 3; ++axis) {
    if (c[axis] >= 0 && c[axis] < counts_[axis]) continue;
    if (!periodic_[static_cast<std::size_t>(axis)]) return false;
    c[axis] = ((c[axis] % counts_[axis]) + counts_[axis]) % counts_[axis];
  }
  return true;
}

void NeighbourGrid::insert(int id, const geometry::Vec3& position) {
  cells_[linear(cell_of(position))].push_back(id);
}

void NeighbourGrid::remove(int id, const geometry::Vec3& position) {
  auto& cell = cells_[linear(cell_of(position))];
  const auto it = std::find(cell.begin(), cell.end(), id);
  if (it != cell.end()) {
    *it = cell.back();
    cell.pop_back();
  }
}

}  // namespace shapeproc::geometry
