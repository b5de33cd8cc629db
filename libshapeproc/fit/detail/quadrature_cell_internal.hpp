// The two cell integrators behind integrate_cell (quadrature_cell.hpp): 2D cells cut into convex
// pieces (quadrature_cell_plane.cpp), 3D cells as balls cut at estimated distances
// (quadrature_cell_ball.cpp).
#pragma once

#include <vector>

#include "libshapeproc/fit/quadrature_cell.hpp"

namespace shapeproc::fit {

// `too_curved`: whether a level set crossing the cell curves with a radius below the cell's
// half-diagonal (a closed curve within a few cells, which chords cannot follow).
std::vector<CellPart> integrate_cell_plane(const CellContext& context,
                                           const geometry::Element& dummy,
                                           const geometry::Vec3& size, bool* uniform,
                                           bool* too_curved, CornerCache* cache);

std::vector<CellPart> integrate_cell_ball(const CellContext& context,
                                          const geometry::Element& dummy,
                                          const geometry::Vec3& size, bool* uniform);

// Radius of the disc (2D) or ball (3D) of the given measure.
double cell_radius(int dimension, double measure);

}  // namespace shapeproc::fit
