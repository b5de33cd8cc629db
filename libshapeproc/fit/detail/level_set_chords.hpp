// A distance level set across a 2D quadrature cell as area-balanced chords (quadrature_cell.hpp).
//
// Near the cell the distance to a neighbour is modelled as the distance field of a circle: with ξ
// along the gradient and η across it, d(p) = d + s·(√((1 + kξ)² + (kη)²) − 1)/k, exact for
// point and disc neighbours (k = 1/d) and for straight edges (k = 0). Its level sets are circles
// about one centre, so the level set d = b is the arc ξ = L − (1 − √(1 − k_b²η²))/k_b with
// L = (b − d)/s and k_b = k/(1 + kL). Each chord joins two points of the arc and is moved towards
// it by the circular segment's area over its length, so the areas between them cancel; the
// convex side of the level set is the intersection of the chords' half-planes. The chords span
// the part of the arc that lies in the cell: balanced over the cell's whole diagonal instead, a
// chord through a cell narrower across the gradient misplaces the level set towards the convex
// side, which shrank every disc of a Strauss range by about h²/(24 r²) (docs/fit.md).
#pragma once

#include <vector>

#include "libshapeproc/fit/detail/convex_polygon.hpp"

namespace shapeproc::fit {

struct LevelSet {
  double nx, ny;     // the unit gradient (ξ axis); η is it turned a quarter turn anticlockwise
  double level;      // ξ where the level set crosses η = 0
  double curvature;  // k_b, signed: positive when the side below (towards −ξ) is convex
};

// The circle field through a cell: the centre's distance d, unit gradient, slope and curvature.
struct CircleField {
  double nx, ny, slope, curvature;
};

// The circle field with the centre's distance d through the distances d_i at the points q_i
// around it, by least squares (Levenberg–Marquardt from `start`, the linear fit's gradient with no
// curvature), its curvature within ±max_curvature.
CircleField fitted_circle_field(const Point2* q, const double* at, int count, double d,
                                const CircleField& start, double max_curvature);

// The level set of threshold b for the circle field of the centre's d, slope, gradient and
// curvature; its curvature clamped to ±max_curvature.
LevelSet level_set_at(double nx, double ny, double slope, double curvature, double d, double b,
                      double max_curvature);

// Appends the half-planes of the chords of `set` across the cell with half-sides hx, hy to
// `sides` (each n·p ≤ c on the convex side) and returns how many: 1, 2 or 4 after the arc's
// sagitta over its span against the cell's side.
int append_level_chords(const LevelSet& set, double hx, double hy, std::vector<HalfPlane>& sides);

}  // namespace shapeproc::fit
