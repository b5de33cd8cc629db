// The cells of a domain decomposition (docs/sample.md, "Parallel sampling of one output"): boxes
// at least a given side long along every axis, coloured by the parity of their index along each
// axis (2^d colours), so that two cells of one colour are a whole cell apart and, with cells at
// least the model's reach long, their elements never interact. Each sweep shifts the grid by a
// random offset, so that no cell boundary stays in place.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::sample {

class CellLayout {
 public:
  // The layout of `domain` with cells at least `side` long, or nothing when the domain is too
  // small to cut along any axis. A torus is cut along an axis into an even number of cells, at
  // least 4 (so that a cell and the ring around it never meet their own images), an open domain
  // into at least 2; an axis too short for that is not cut: every cell spans it (a thin slab).
  static std::optional<CellLayout> plan(const geometry::Domain& domain, double side);

  // Shifts the cell boundaries by `offset`, each coordinate in [0, the cell's side).
  void set_offset(const geometry::Vec3& offset);
  const geometry::Vec3& side() const { return side_; }
  const geometry::Vec3& offset() const { return offset_; }
  bool cut(int axis) const { return cut_[static_cast<std::size_t>(axis)]; }
  // Along the torus's axes that are not cut, its period (cells wrap around there); 0 elsewhere.
  geometry::Vec3 spanned_period() const;

  int count() const { return total_; }
  // Cells along each axis (1 along the axes that are not cut), and a cell's index along them:
  // cell numbers run along x first, then y, then z.
  const Eigen::Vector3i& per_axis() const { return per_axis_; }
  Eigen::Vector3i index_of(int cell) const;
  int colours() const { return 1 << dimension_; }
  int colour(int cell) const;
  // The cell holding a reference position of the domain.
  int cell_of(const geometry::Vec3& position) const;
  // The cell's box: on a torus in coordinates continued past the domain's upper edge (the last
  // cell of an axis reaches beyond it by the offset); on an open domain clipped to it (the first
  // and last cells of an axis are partial, and may be empty).
  geometry::Box3 box(int cell) const;
  // The cells around `cell` (3^d − 1, fewer at an open domain's edge), each once.
  std::vector<int> around(int cell) const;
  // `position` moved by whole periods to the image nearest `near` (a torus; unchanged when open).
  geometry::Vec3 image_near(const geometry::Vec3& position, const geometry::Vec3& near) const;

 private:
  CellLayout(const geometry::Domain& domain, const Eigen::Vector3i& per_axis);
  int cell_at(Eigen::Vector3i index) const;  // -1 outside an open domain

  geometry::Box3 box_;
  int dimension_ = 2;
  bool periodic_ = false;
  Eigen::Vector3i per_axis_ = Eigen::Vector3i::Ones();  // cells along each axis
  geometry::Vec3 side_ = geometry::Vec3::Ones();
  geometry::Vec3 offset_ = geometry::Vec3::Zero();
  int total_ = 1;
  std::array<bool, 3> cut_{};
};

}  // namespace shapeproc::sample
