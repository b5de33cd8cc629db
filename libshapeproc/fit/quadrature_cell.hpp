// One dummy point of the quadrature, integrated over its cell with boundary-aware weights.
//
// The conditional intensity of a dummy (shape s at u) is piecewise constant in u: it jumps where
// the distance to a neighbour crosses a threshold δ_k or where the relative orientation crosses a
// sector boundary. A plain midpoint rule weighs each cell by its centre's value, an O(h) error
// along every such boundary.
//
// 2D: every neighbour whose boundaries may cross the cell gets local models from samples at the
// cell's centre and corners: the distance as d + g·p + ½κ(t·p)² (a distance field grows linearly
// along its gradient, so one curvature κ across it suffices), the direction as turning about a
// pole (exact for directions between centres: sector boundaries are then rays). The cell is cut
// along each modelled boundary (a level set as a few area-balanced chords, a sector boundary as
// a line), nearest neighbours first, into convex pieces; each piece takes the bands of its side
// and pieces in a hard core are dropped. Corner samples are shared between the cells that meet
// at a corner (CornerCache).
//
// 3D: the cell (taken as the ball of the same measure) is cut at the estimated distance
// |d(u) − δ| of each boundary, and several crossings combine as independent cuts.
//
// Cheap bounds on d and the boxes' direction cone skip exact measurements wherever no boundary
// can cross the cell.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/neighbour_grid.hpp"
#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

struct CellPart {
  double fraction = 1.0;                    // of the cell's measure
  std::vector<std::pair<int, int>> counts;  // (θ index, count), sorted
};

struct CellContext {
  const model::Interaction* interaction;
  const geometry::PairMeasurer* measurer;
  const std::vector<geometry::Element>* data;
  const geometry::NeighbourGrid* grid;
  int dimension = 2;
  geometry::Vec3 period = geometry::Vec3::Zero();  // window sizes when periodic, else 0
  // 2D: cell corners lie on the lattice origin + (i, j)·lattice_step, so that cells meeting at
  // a corner can share its samples through a CornerCache (0: no lattice). `top_corner` is the
  // half-diagonal of the unrefined cells (0: each cell's own), which fixes the samples' cut-off.
  geometry::Vec3 lattice_origin = geometry::Vec3::Zero();
  geometry::Vec3 lattice_step = geometry::Vec3::Zero();
  double top_corner = 0.0;
};

// Distances and directions of one neighbour measured at a cell corner (2D), kept for the other
// cells that meet there. One per thread; the results do not depend on it. An open-addressing
// table whose clear() is one increment (a block of rows clears it thousands of times).
class CornerCache {
 public:
  struct Key {
    int shape, neighbour;
    long x, y;
    int image_x, image_y;
    bool operator==(const Key& o) const {
      return shape == o.shape && neighbour == o.neighbour && x == o.x && y == o.y &&
             image_x == o.image_x && image_y == o.image_y;
    }
  };
  // The value stored under `key` (distances and angles apart), measure() the first time.
  template <class Measure>
  double distance(const Key& key, Measure&& measure) {
    return lookup(key, 0, measure);
  }
  template <class Measure>
  double angle(const Key& key, Measure&& measure) {
    return lookup(key, 1, measure);
  }
  void clear() {
    if (++generation_ == 0) {  // wrapped around: no slot may look used
      std::fill(slots_.begin(), slots_.end(), Slot{});
      generation_ = 1;
    }
    size_ = 0;
  }
  std::size_t size() const { return size_; }

 private:
  struct Slot {
    Key key;
    int kind;
    unsigned generation = 0;  // the slot is used when it equals the table's
    double value;
  };
  static std::size_t hash(const Key& k, int kind) {
    std::size_t h = std::hash<long>()(k.x * 1000003L + k.y);
    h ^= std::hash<long>()((static_cast<long>(k.shape) << 40) ^
                           (static_cast<long>(k.neighbour) << 8) ^ ((k.image_x + 2) << 4) ^
                           (k.image_y + 2) ^ (static_cast<long>(kind) << 60)) +
         0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h * 0x9e3779b97f4a7c15ULL;
  }
  template <class Measure>
  double lookup(const Key& key, int kind, Measure& measure) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = (hash(key, kind) >> 20) & mask;; i = (i + 1) & mask) {
      Slot& slot = slots_[i];
      if (slot.generation != generation_) {
        slot = {key, kind, generation_, measure()};
        ++size_;
        return slot.value;
      }
      if (slot.kind == kind && slot.key == key) return slot.value;
    }
  }
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(std::max<std::size_t>(1024, 2 * old.size()), Slot{});
    const unsigned previous = generation_;
    ++generation_;  // every new slot is free (generation 0 is never current)
    size_ = 0;
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.generation != previous) continue;
      std::size_t i = (hash(slot.key, slot.kind) >> 20) & mask;
      while (slots_[i].generation == generation_) i = (i + 1) & mask;
      slots_[i] = slot;
      slots_[i].generation = generation_;
      ++size_;
    }
  }
  std::vector<Slot> slots_;
  std::size_t size_ = 0;
  unsigned generation_ = 1;
};

// Parts of the rectangular (box) cell of extents `size` around `dummy` with λ > 0 (hard-core
// parts dropped; an empty result when the whole cell is hard core). `uniform` tells whether no
// boundary crosses the cell, so that the result is exact.
std::vector<CellPart> integrate_cell(const CellContext& context, const geometry::Element& dummy,
                                     const geometry::Vec3& size, bool* uniform = nullptr,
                                     CornerCache* cache = nullptr);

// integrate_cell, refined: a cell that is not uniform is split into 2^dim sub-cells, down to
// `depth` levels; the finest cells use the cut estimate. Fractions are of the top cell.
std::vector<CellPart> integrate_cell_adaptive(const CellContext& context,
                                              const geometry::Element& dummy,
                                              const geometry::Vec3& size, int depth,
                                              CornerCache* cache = nullptr);

// Fraction of a disc (2D) or ball (3D) of the given measure lying beyond a plane at distance
// x ≥ 0 from its centre.
double cut_fraction(int dimension, double cell_measure, double x);

}  // namespace shapeproc::fit
