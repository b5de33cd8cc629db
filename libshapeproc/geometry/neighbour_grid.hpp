// A uniform grid of element positions for neighbour queries (open or periodic windows).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

class NeighbourGrid {
 public:
  // Cells of at least `cell_size` covering `window`; with `periodic`, queries wrap around.
  NeighbourGrid(const geometry::Box3& window, int dimension, double cell_size, bool periodic);
  // The same, wrapping only along the axes where `periodic_axes` is true.
  NeighbourGrid(const geometry::Box3& window, int dimension, double cell_size,
                const std::array<bool, 3>& periodic_axes);

  void insert(int id, const geometry::Vec3& position);
  void remove(int id, const geometry::Vec3& position);

  // Calls f(id) for every id in the cells around `position` (its cell and the adjacent ones): a
  // superset of the ids within the cell size of `position`, each once. Thread-safe.
  template <class F>
  void for_each_candidate(const geometry::Vec3& position, F&& f) const {
    any_candidate(position, [&f](int id) {
      f(id);
      return false;
    });
  }

  // Whether `test(id)` holds for one of the ids for_each_candidate would visit; visits them in
  // the same order and stops at the first that passes. Thread-safe.
  template <class Test>
  bool any_candidate(const geometry::Vec3& position, Test&& test) const {
    const Eigen::Vector3i centre = cell_of(position);
    const int reach_z = dimension_ == 3 ? 1 : 0;
    std::array<std::size_t, 27> visited{};
    int visited_count = 0;
    for (int dz = -reach_z; dz <= reach_z; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          Eigen::Vector3i c = centre + Eigen::Vector3i(dx, dy, dz);
          if (!wrap(c)) continue;
          const std::size_t index = linear(c);
          if (repeats_ && std::find(visited.begin(), visited.begin() + visited_count, index) !=
                              visited.begin() + visited_count)
            continue;
          visited[static_cast<std::size_t>(visited_count++)] = index;
          for (int id : cells_[index])
            if (test(id)) return true;
        }
    return false;
  }

  // Calls f(id) for every id in the cells that the box of half-side `distance` around `position`
  // meets: a superset of the ids within `distance` of `position`, each once. Thread-safe.
  template <class F>
  void for_each_candidate_within(const geometry::Vec3& position, double distance, F&& f) const {
    any_candidate_within(position, distance, [&f](int id) {
      f(id);
      return false;
    });
  }

  // Whether `test(id)` holds for one of the ids for_each_candidate_within would visit; stops at
  // the first that passes. Thread-safe.
  template <class Test>
  bool any_candidate_within(const geometry::Vec3& position, double distance, Test&& test) const {
    const Eigen::Vector3i centre = cell_of(position);
    std::array<int, 3> low{}, high{};
    for (int axis = 0; axis < 3; ++axis) {
      const auto a = static_cast<std::size_t>(axis);
      const int reach = axis < dimension_ ? static_cast<int>(std::ceil(distance / cell_[axis])) : 0;
      low[a] = centre[axis] - reach;
      high[a] = centre[axis] + reach;
      if (!periodic_[a] || high[a] - low[a] + 1 >= counts_[axis]) {
        // Open, or the range covers the whole period: every cell once, in order.
        low[a] = periodic_[a] ? 0 : std::max(low[a], 0);
        high[a] = periodic_[a] ? counts_[axis] - 1 : std::min(high[a], counts_[axis] - 1);
      }
    }
    const auto cell = [this](int c, int axis) {
      return (c % counts_[axis] + counts_[axis]) % counts_[axis];
    };
    for (int z = low[2]; z <= high[2]; ++z)
      for (int y = low[1]; y <= high[1]; ++y)
        for (int x = low[0]; x <= high[0]; ++x)
          for (int id : cells_[linear({cell(x, 0), cell(y, 1), cell(z, 2)})])
            if (test(id)) return true;
    return false;
  }

 private:
  Eigen::Vector3i cell_of(const geometry::Vec3& p) const;
  bool wrap(Eigen::Vector3i& c) const;
  std::size_t linear(const Eigen::Vector3i& c) const {
    return static_cast<std::size_t>((c.z() * counts_.y() + c.y()) * counts_.x() + c.x());
  }

  geometry::Box3 window_;
  int dimension_;
  std::array<bool, 3> periodic_{};
  bool repeats_ = false;  // a periodic axis of fewer than 3 cells: neighbouring cells repeat
  Eigen::Vector3i counts_;
  geometry::Vec3 cell_;
  std::vector<std::vector<int>> cells_;
};

}  // namespace shapeproc::geometry
