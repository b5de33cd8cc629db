// One dummy point of the quadrature, integrated over its cell with boundary-aware weights.
//
// The conditional intensity of a dummy (shape s at u) is piecewise constant in u: it jumps where
// the distance to a neighbour crosses a threshold δ_k or where the relative orientation crosses a
// sector boundary. A plain midpoint rule weighs each cell by its centre's value, an O(h) error
// along every such boundary. Here a cell that a boundary crosses is split: the distance d(u) to a
// neighbour is 1-Lipschitz in u with gradient norm 1 away from contact, so the boundary d = δ
// lies at about |d(u) − δ| from the centre; the cell (taken as the disc, or ball, of the same
// measure) is cut there, and the two parts carry the statistics of each side. Orientation
// boundaries are cut the same way at distance (angular margin) × |offset|. Several crossings
// combine as independent cuts. Cheap bounds on d and the boxes' direction cone skip exact
// measurements wherever no boundary can cross the cell.
#pragma once

#include <utility>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/model/neighbour_grid.hpp"

namespace shapeproc::fit {

struct CellPart {
  double fraction = 1.0;                    // of the cell's measure
  std::vector<std::pair<int, int>> counts;  // (θ index, count), sorted
};

struct CellContext {
  const model::Interaction* interaction;
  const geometry::PairMeasurer* measurer;
  const std::vector<geometry::Element>* data;
  const model::NeighbourGrid* grid;
  int dimension = 2;
  geometry::Vec3 period = geometry::Vec3::Zero();  // window sizes when periodic, else 0
};

// Parts of the square (cube) cell of side `side` around `dummy` with λ > 0 (hard-core parts
// dropped; an empty result when the whole cell is hard core). `uniform` tells whether no
// boundary can cross the cell at all (tested with the circumscribed radius), so that the
// result is exact.
std::vector<CellPart> integrate_cell(const CellContext& context, const geometry::Element& dummy, double side,
                                     bool* uniform = nullptr);

// integrate_cell, refined: a cell that is not uniform is split into 2^dim sub-cells, down to
// `depth` levels; the finest cells use the cut estimate. Fractions are of the top cell.
std::vector<CellPart> integrate_cell_adaptive(const CellContext& context, const geometry::Element& dummy, double side,
                                              int depth);

// Fraction of a disc (2D) or ball (3D) of the given measure lying beyond a plane at distance
// x ≥ 0 from its centre.
double cut_fraction(int dimension, double cell_measure, double x);

}  // namespace shapeproc::fit
