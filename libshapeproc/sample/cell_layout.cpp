#include "libshapeproc/sample/cell_layout.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::sample {

std::optional<CellLayout> CellLayout::plan(const geometry::Domain& domain, double side) {
  const int dimension = domain.dimension();
  const geometry::Vec3 sizes = domain.box().sizes();
  Eigen::Vector3i per_axis = Eigen::Vector3i::Zero();
  bool any = false;
  for (int axis = 0; axis < dimension; ++axis) {
    const double cells = side > 0 ? std::floor(sizes[axis] / side) : 0.0;
    int n = static_cast<int>(std::min(cells, 1e6));
    if (domain.periodic()) n -= n % 2;
    if (n < (domain.periodic() ? 4 : 2)) n = 0;  // not cut
    per_axis[axis] = n;
    any = any || n > 0;
  }
  if (!any) return std::nullopt;
  return CellLayout(domain, per_axis);
}

CellLayout::CellLayout(const geometry::Domain& domain, const Eigen::Vector3i& per_axis)
    : box_(domain.box()), dimension_(domain.dimension()), periodic_(domain.periodic()) {
  for (int axis = 0; axis < dimension_; ++axis) {
    cut_[static_cast<std::size_t>(axis)] = per_axis[axis] > 0;
    if (!cut(axis)) {
      side_[axis] = box_.sizes()[axis];
      per_axis_[axis] = 1;
      continue;
    }
    side_[axis] = box_.sizes()[axis] / per_axis[axis];
    // An open domain's shifted grid has a partial cell at each end: one more along the axis.
    per_axis_[axis] = per_axis[axis] + (periodic_ ? 0 : 1);
  }
  total_ = per_axis_.prod();
}

void CellLayout::set_offset(const geometry::Vec3& offset) {
  for (int axis = 0; axis < 3; ++axis)
    offset_[axis] = axis < dimension_ && cut(axis) ? offset[axis] : 0.0;
}

geometry::Vec3 CellLayout::spanned_period() const {
  geometry::Vec3 period = geometry::Vec3::Zero();
  for (int axis = 0; axis < dimension_; ++axis)
    if (periodic_ && !cut(axis)) period[axis] = box_.sizes()[axis];
  return period;
}

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
    if (!cut(axis)) continue;  // index 0
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
    if (!cut(axis)) {
      low[axis] = box_.min()[axis];
      high[axis] = box_.max()[axis];
      continue;
    }
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
        const Eigen::Vector3i step(dx, dy, dz);
        bool along_uncut = false;
        for (int axis = 0; axis < dimension_; ++axis) along_uncut |= step[axis] != 0 && !cut(axis);
        if (along_uncut) continue;
        const int other = cell_at(centre + step);
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
    if (!cut(axis)) continue;  // the cell spans the axis and wraps along it itself
    const double period = box_.sizes()[axis];
    out[axis] -= period * std::round((out[axis] - near[axis]) / period);
  }
  return out;
}

}  // namespace shapeproc::sample
