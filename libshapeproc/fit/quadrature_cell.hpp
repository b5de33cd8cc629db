// One dummy point of the quadrature, integrated over its cell with boundary-aware weights.
//
// The conditional intensity of a dummy (shape s at u) is piecewise constant in u: it jumps where
// the distance to a neighbour crosses a threshold δ_k or where the relative orientation crosses a
// sector boundary. A plain midpoint rule weighs each cell by its centre's value, an O(h) error
// along every such boundary.
//
// 2D: every neighbour whose boundaries may cross the cell gets local models from samples at the
// cell's centre and corners: the distance as the distance field of a circle (level_set_chords.hpp),
// the direction as turning about a pole (exact for directions between centres: sector boundaries
// are then rays). The cell is cut along each modelled boundary (a level set as a few
// area-balanced chords, a sector boundary as a line), nearest neighbours first, into convex
// pieces; each piece takes the bands of its side and pieces in a hard core are dropped. A level
// set curving more tightly than the chords can follow splits the cell into quarters (up to three
// times). Corner samples are shared between the cells that meet at a corner (CornerCache).
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

#include "libshapeproc/fit/corner_cache.hpp"
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
