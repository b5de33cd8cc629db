// The connectivity of an exemplar's elements (Ijiri et al. 2008, §4): the Delaunay triangulation
// of their reference positions, less its skewed triangles (an angle above 2π/3, which Delaunay
// makes along the border), with the user's edge flips applied. An edge is kept while it belongs to
// at least one kept triangle.
//
// Each element's ring is its neighbours along kept edges in counter-clockwise order (in the
// scene's coordinates: with SVG's y axis down, clockwise on screen), with their offsets. A ring
// is closed when every two consecutive neighbours form a kept triangle with the element; elements
// whose rings are open lie on the border of the exemplar and are not used as references.
//
// On a torus (a seamless tile) the tile is triangulated with its eight periodic images around it,
// so that every ring closes across the seam; a flip then applies to every image of the edge.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::methods {

using geometry::Vec3;

struct Ring {
  std::vector<int> neighbour;  // element indices, counter-clockwise
  std::vector<Vec3> offset;    // neighbour's position minus the element's (minimum image)
  bool closed = false;
};

struct Connectivity {
  std::vector<Ring> rings;                 // per element
  std::vector<std::pair<int, int>> edges;  // i < j, each once (on a torus: once per pair)
  double shortest_edge = 0.0, mean_edge = 0.0;
};

// Every edge once, as (element, offset to the other end): from the rings, so that an edge across
// a torus seam keeps its offset.
std::vector<std::pair<int, Vec3>> ring_edges(const Connectivity& connectivity);

// An edge flip a user asks for: the edge between elements `a` and `b` (exemplar order) becomes
// the other diagonal of the two kept triangles it borders.
struct EdgeFlip {
  int a = 0, b = 0;
};

// The connectivity of `positions` (2D, z ignored) on `domain` (its box is the exemplar's window;
// a torus wraps). Throws core::ArgumentError for fewer than 3 positions, a flip of an edge that
// is not there or lies on the border, or a flip whose quadrilateral is not convex.
Connectivity delaunay_connectivity(const std::vector<Vec3>& positions,
                                   const geometry::Domain& domain,
                                   const std::vector<EdgeFlip>& flips = {});

}  // namespace shapeproc::methods
