#include "libshapeproc/sample/cell_layout.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::sample {

std::optional<CellLayout> CellLayout::plan(const geometry::Domain& domain, double side) {
  const int dimension = domain.dimension();
  const geometry::Vec3 sizes = domain.box().sizes();
  Eigen::Vector3i per_axis = Eigen::Vector3i::Ones();
  for (int axis = 0; axis < dimension; ++axis) {
    const double cells = side > 0 ? std::floor(sizes[axis] / side) : 0.0;
    int n = static_cast<int>(std::min(cells, 1e6));
    if (domain.periodic()) {
      n -= n % 2;
      if (n < 4) return std::nullopt;
    } else if (n < 2) {
      return std::nullopt;
    }
    per_axis[axis] = n;
  }
  return CellLayout(domain, per_axis);
}

CellLayout::CellLayout(const geometry::Domain& domain, const Eigen::Vector3i& per_axis)
    : box_(domain.box()), dimension_(domain.dimension()), periodic_(domain.periodic()) {
  for (int axis = 0; axis < dimension_; ++axis) {
    side_[axis] = box_.sizes()[axis] / per_axis[axis];
    // An open domain's shifted grid has a partial cell at each end: one more along the axis.
    per_axis_[axis] = per_axis[axis] + (periodic_ ? 0 : 1);
  }
  total_ = per_axis_.prod();
}

void CellLayout::set_offset(const geometry::Vec3& offset) { offset_ = offset; }

Eigen::Vector3i CellLayout::index_of(int cell) const {
  return {cell % per_axis_.x(), (cell / per_axis_.x()) % per_axis_.y(),
          cell / (per_axis_.x() * per_axis_.y())};
}

int CellLayout::cell_at(Eigen::Vector3i index) const {
  for (int axis = 0; axis < 3; ++axis) {
    const int n = per_axis_[axis];
    if (index[axis] >= 0 && index[axis] < n) continue;
    if (!periodic_ || axis >= dimension_) return -1;
    index[axis] = ((index[axis] % n) + n) % n;
  }
  return (index.z() * per_axis_.y() + index.y()) * per_axis_.x() + index.x();
}

int CellLayout::colour(int cell) const {
  const Eigen::Vector3i index = index_of(cell);
  int colour = 0;
  for (int axis = 0; axis < dimension_; ++axis) colour |= (index[axis] & 1) << axis;
  return colour;
}

int CellLayout::cell_of(const geometry::Vec3& position) const {
  Eigen::Vector3i index = Eigen::Vector3i::Zero();
  for (int axis = 0; axis < dimension_; ++axis) {
    double t = position[axis] - box_.min()[axis] - offset_[axis];
    if (periodic_) {
      const double period = box_.sizes()[axis];
      t -= period * std::floor(t / period);
    } else {
      t += side_[axis];  // the partial cell before the offset is cell 0
    }
    index[axis] = std::clamp(static_cast<int>(std::floor(t / side_[axis])), 0, per_axis_[axis] - 1);
  }
  return cell_at(index);
}

geometry::Box3 CellLayout::box(int cell) const {
  const Eigen::Vector3i index = index_of(cell);
  geometry::Vec3 low = geometry::Vec3::Zero(), high = geometry::Vec3::Zero();
  for (int axis = 0; axis < dimension_; ++axis) {
    const double start =
        box_.min()[axis] + offset_[axis] + (index[axis] - (periodic_ ? 0 : 1)) * side_[axis];
    low[axis] = start;
    high[axis] = start + side_[axis];
    if (!periodic_) {
      low[axis] = std::clamp(low[axis], box_.min()[axis], box_.max()[axis]);
      high[axis] = std::clamp(high[axis], box_.min()[axis], box_.max()[axis]);
    }
  }
  return {low, high};
}

std::vector<int> CellLayout::around(int cell) const {
  const Eigen::Vector3i centre = index_of(cell);
  const int reach_z = dimension_ == 3 ? 1 : 0;
  std::vector<int> out;
  for (int dz = -reach_z; dz <= reach_z; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int other = cell_at(centre + Eigen::Vector3i(dx, dy, dz));
        if (other < 0 || other == cell) continue;
        if (std::find(out.begin(), out.end(), other) == out.end()) out.push_back(other);
      }
  return out;
}

geometry::Vec3 CellLayout::image_near(const geometry::Vec3& position,
                                      const geometry::Vec3& near) const {
  if (!periodic_) return position;
  geometry::Vec3 out = position;
  for (int axis = 0; axis < dimension_; ++axis) {
    const double period = box_.sizes()[axis];
    out[axis] -= period * std::round((out[axis] - near[axis]) / period);
  }
  return out;
}

}  // namespace shapeproc::sample
