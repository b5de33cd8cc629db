// Element neighbourhoods and their distance, as Ma et al. 2011 define them (§3.2, eq. 1): the one
// definition the neighbourhood metric (Davison et al. 2018, eq. 5) and the neighbourhood-EM
// synthesis method (compare/neighbourhood_em) share.
//
// The neighbourhood n(s) of an element or sample s holds the others whose positions lie within
// the radius r of s's (minimum image on a torus), as offsets p(s') − p(s). Each carries a key
// (what a partner must share: the metric's category, the EM's sample id) and an attribute q (the
// EM's category and shape class). The distance of an output neighbourhood n(o) to an exemplar
// neighbourhood n(e) is
//     |n(o) − n(e)| = Σ_{o' ∈ n(o)} min(|p̂(o') − p̂(e')|² + α [q(o') ≠ q(e')], r²),
// where o' is paired with an exemplar e' of the same key by Ma's greedy rule (the closest
// remaining pair first, by position); an o' left without a partner closer than r costs r².
// The cap makes a neighbourhood of radius 2r on the exemplar side as good as Ma's unbounded one.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry {

struct Neighbour {
  Vec3 offset;        // p(e') − p(e), minimum image on a torus
  int key;            // partners share it (-1: pairs with nothing)
  int element;        // index of e' among the index's positions
  int attribute = 0;  // q(e'): pairs whose attributes differ cost α more
};
using Neighbourhood = std::vector<Neighbour>;

// The neighbourhoods of a set of elements, found through a grid (each query visits the cells
// around the centre, not every element).
class NeighbourhoodIndex {
 public:
  // Keys are the elements' categories, renumbered by `category_map` (empty: unchanged).
  NeighbourhoodIndex(const std::vector<Element>& elements, const Domain& domain, double radius,
                     const std::vector<int>& category_map = {});
  // Any points with their keys and attributes (empty: all 0).
  NeighbourhoodIndex(std::vector<Vec3> positions, std::vector<int> keys,
                     std::vector<int> attributes, const Domain& domain, double radius);

  // The points within the radius of point `centre` (itself excluded), in index order.
  Neighbourhood of(std::size_t centre) const;
  // The points within the radius of `position`, except `skip` (-1: none), in index order.
  Neighbourhood around(const Vec3& position, int skip = -1) const;

  double radius() const { return radius_; }

 private:
  std::vector<Vec3> positions_;
  std::vector<int> keys_, attributes_;
  const Domain& domain_;
  double radius_;
  NeighbourGrid grid_;
};

// An exemplar neighbourhood prepared for many pairings (the neighbourhood EM's): its neighbours
// sorted by key, then by cell of a grid of side r/4 over the offsets (row by row, column by
// column), with where each cell's neighbours start, so that the partners an output neighbour may
// pair with first (those nearer than r/4) are one contiguous range per row of cells instead of a
// scan, and with a coarser grid of lower bounds (nearest_bound) that lets a search drop a
// candidate before pairing it. Pairings against it equal those against its neighbours.
class PairingNeighbourhood {
 public:
  static constexpr int kCells = 16;  // per axis, over [−2r, 2r)

  PairingNeighbourhood() = default;
  PairingNeighbourhood(Neighbourhood neighbours, double radius, int dimension);

  const Neighbourhood& neighbours() const { return neighbours_; }
  std::size_t size() const { return neighbours_.size(); }
  const Neighbour& operator[](std::size_t i) const { return neighbours_[i]; }

  // The index range of the neighbours of `key`.
  std::pair<std::size_t, std::size_t> key_range(int key) const;
  // Calls visit(index, squared distance to `offset`) for every neighbour of `key` in the cells
  // up to `reach` cells from `offset`'s: a superset of those within reach · r/4 of it (reach 1:
  // the near partners; 4: every partner nearer than r).
  template <class F>
  void for_each_within(int key, const Vec3& offset, int reach, F&& visit) const {
    const int slot = slot_of(key);
    if (slot < 0) return;
    const Start* start = cell_start_.data() + static_cast<std::size_t>(slot) * (cells_ + 1);
    const int x = axis_cell(offset.x()), y = axis_cell(offset.y());
    const int z = dimension_ == 3 ? axis_cell(offset.z()) : 0;
    const int reach_z = dimension_ == 3 ? reach : 0;
    const int x0 = std::max(x - reach, 0), x1 = std::min(x + reach, kCells - 1) + 1;
    const double ox = offset.x(), oy = offset.y(), oz = offset.z();
    for (int cz = std::max(z - reach_z, 0); cz <= std::min(z + reach_z, kCells - 1); ++cz) {
      for (int cy = std::max(y - reach, 0); cy <= std::min(y + reach, kCells - 1); ++cy) {
        const int row = (cz * kCells + cy) * kCells;
        for (int i = start[row + x0]; i < start[row + x1]; ++i) {
          const auto j = static_cast<std::size_t>(i);
          const double dx = xyz_[3 * j] - ox, dy = xyz_[3 * j + 1] - oy, dz = xyz_[3 * j + 2] - oz;
          visit(j, dx * dx + dy * dy + dz * dz);
        }
      }
    }
  }
  int attribute(std::size_t i) const { return attributes_[i]; }

  // A lower bound of output neighbour o's term of eq. 1 against this neighbourhood, pair costs
  // capped at `cap`: min(cap, the squared distance from the cell of a fixed grid over [−r, r)^dim
  // holding o to the nearest neighbour of o's key here). Greedy pairing gives no neighbour a
  // partner nearer than its nearest.
  double nearest_bound(const Neighbour& o, double cap) const;

 private:
  // The index of `key` among the distinct keys, -1 when no neighbour has it.
  int slot_of(int key) const {
    return key >= 0 && static_cast<std::size_t>(key) < slots_.size()
               ? slots_[static_cast<std::size_t>(key)]
               : -1;
  }
  int axis_cell(double x) const;
  void build_lower_bound_grid();

  using Start = std::uint16_t;  // neighbourhoods hold fewer than 65,536 neighbours

  Neighbourhood neighbours_;  // sorted by key, then cell (z, y, x)
  // The same neighbours packed for the pairing's scans: offsets (x, y, z), attributes.
  std::vector<double> xyz_;
  std::vector<int> attributes_;
  std::vector<int> keys_, distinct_keys_;
  std::vector<int> slots_;  // per key up to the largest: its index in distinct_keys_, or -1
  // Per distinct key, where each cell's neighbours start (cells_ + 1 entries).
  std::vector<Start> cell_start_;
  // Per distinct key, per cell of the bound's grid over [−r, r) (16 cells an axis in 2D, 8 in
  // 3D): the squared distance from the cell to the nearest neighbour of the key, rounded down to
  // a float, at most r².
  std::vector<float> nearest_;
  int bound_cells_ = 0;
  int cells_ = 0;
  double per_cell_ = 1.0;  // 1 / the cell side
  int dimension_ = 2;
  double radius_ = 1.0;  // r (the bound's grid covers [−r, r))
};

// The greedy pairing of Ma et al.: (index in `output`, index in `exemplar`) pairs of one key,
// closest first, each used once, none at r or farther.
std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const Neighbourhood& exemplar, double radius);

std::vector<std::pair<int, int>> match_neighbourhoods(const Neighbourhood& output,
                                                      const PairingNeighbourhood& exemplar,
                                                      double radius);

// |n(o) − n(e)| of eq. 1, with the greedy pairing and attribute weight `alpha`. A search that
// only needs distances below `bound` may pass it: a neighbourhood shown to be at least that far
// (by the sum of each neighbour's nearest candidate) returns that lower bound, unpaired. With
// `pairs`, a completed pairing is also stored there (as match_neighbourhoods gives it; left empty
// when the bound stops the pairing).
double neighbourhood_distance(const Neighbourhood& output, const Neighbourhood& exemplar,
                              double radius, double alpha = 0.0,
                              double bound = std::numeric_limits<double>::infinity());
double neighbourhood_distance(const Neighbourhood& output, const PairingNeighbourhood& exemplar,
                              double radius, double alpha = 0.0,
                              double bound = std::numeric_limits<double>::infinity(),
                              std::vector<std::pair<int, int>>* pairs = nullptr);

// The cost of one pair of eq. 1: min(|Δp̂|² + α [q ≠ q'], r²).
inline double pair_cost(const Neighbour& output, const Neighbour& exemplar, double radius,
                        double alpha) {
  const double c = (output.offset - exemplar.offset).squaredNorm() +
                   (output.attribute != exemplar.attribute ? alpha : 0.0);
  return c < radius * radius ? c : radius * radius;
}

}  // namespace shapeproc::geometry
