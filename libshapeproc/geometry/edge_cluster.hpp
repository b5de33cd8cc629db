// Clusters of nearby boundary edges, and the far field of their share of a region's potential.
//
// A region B's potential Φ_B(x) = ∫_B dA / |y − x| is, by the divergence theorem, a sum over its
// boundary edges j of ∫_edge_j n_j·(y − x) / |y − x| ds_y (n_j the outward normal). Seen from a
// point x far from a cluster of edges (centre c, radius ρ), write y − x = d + u with d = c − x and
// u = y − c, and expand 1/|d + u| in u (Legendre's series, D = |d|, p = d·u, q = |u|²):
//   1/|d + u| = 1/D − p/D³ + (3p² − D²q)/(2D⁵) − (5p³ − 3D²pq)/(2D⁷) + O(|u|⁴/D⁵).
// The cluster's share is then a fixed combination of its normal-weighted moments
// Σ_j n_j ∫_edge_j u^α ds for the monomials u^α of degree at most 3, with an error below a small
// multiple of the cluster's edge length times (ρ/D)⁴.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// Monomials u^α of degree ≤ 3, in the order 1, x, y, xx, xy, yy, xxx, xxy, xyy, yyy.
constexpr int kClusterMonomials = 10;

struct EdgeCluster {
  std::size_t begin = 0, end = 0;  // the cluster's run of entries in the edge table that owns it
  Vec2 centre = Vec2::Zero();
  double radius = 0.0;  // of the edges' end points around the centre
  // moments[k][α] = Σ_j n_jk ∫_edge_j u^α ds, u = y − centre.
  std::array<std::array<double, kClusterMonomials>, 2> moments{};

  // Adds edge (a, b) with unit normal n to the moments (the centre must be set first).
  void add_edge(const Vec2& a, const Vec2& b, const Vec2& n);
  // Σ_j ∫_edge_j n_j·(y − x) / |y − x| ds_y at x, by the expansion: for x at least about four
  // radii from the centre.
  double potential(const Vec2& x) const;
};

// Splits the edges (indices into start/end) into groups of at most `size` nearby edges by median
// splits of their midpoints along the longer side of their box; the groups come out in the
// order of the splits.
std::vector<std::vector<int>> group_nearby_edges(const std::vector<Vec2>& start,
                                                 const std::vector<Vec2>& end,
                                                 std::vector<int> edges, std::size_t size);

}  // namespace shapeproc::geometry
