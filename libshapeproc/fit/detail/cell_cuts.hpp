// The boundaries that cut a 2D quadrature cell (distance level sets and sector boundaries of
// each neighbour), the pieces they leave, and which band of a neighbour a piece lies in.
#pragma once

#include <cstdint>
#include <vector>

#include "libshapeproc/fit/detail/convex_polygon.hpp"

namespace shapeproc::fit {

// One boundary inside the cell, with the convex region C = ∩ sides on one side of it. A distance
// cut is a level set d = `breakpoint` of one neighbour, for the axes in `axes` (C holds the
// distances below it when `inside_below`, else those at or above it); a sector cut is where the
// neighbour's direction enters the sector of `other_axis` (C is that side).
struct PlaneCut {
  bool sector;
  double breakpoint;
  bool inside_below;
  int other_axis;
  std::uint64_t axes;
  int first_side, side_count;  // into the cell's list of half-planes
};

// A neighbour whose boundaries cross the cell: its centre's axis and exact distance, and its
// cuts (sector cuts first, then distance cuts by ascending breakpoint).
struct PlaneNeighbour {
  int category;
  int axis;
  double distance;
  int first_cut, cut_count;
};

// A piece of the cell and the cuts whose region C holds it.
struct Piece {
  Polygon polygon;
  std::uint64_t inside = 0;
};

// Whether bit `cut` of `inside` is set; cuts past the 64th are never recorded (the cell keeps the
// centre's side of them), so they hold nothing.
inline bool holds(std::uint64_t inside, int cut) {
  return cut >= 0 && cut < 64 && ((inside >> cut) & 1u) != 0;
}

// The axis of neighbour `n` for a piece inside the cuts `inside`: the sector cut's axis that
// holds it, else the neighbour's centre axis.
int piece_axis(const PlaneNeighbour& n, const std::vector<PlaneCut>& cuts, std::uint64_t inside);

// A distance of the piece's interval between `axis`'s thresholds: with the cuts of that axis at
// b_0 < … < b_m-1, a piece below k of them lies in [b_{m-k-1}, b_{m-k}).
double piece_distance(const PlaneNeighbour& n, const std::vector<PlaneCut>& cuts,
                      std::uint64_t inside, int axis);

}  // namespace shapeproc::fit
