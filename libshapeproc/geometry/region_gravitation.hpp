// Gravitation between 2D regions as a double boundary integral (exact for polygonal proxies).
//
// With φ(x, y) = 1/|y − x|, the kernel is (y − x)/|y − x|^3 = ∇_x φ, and in 2D
// div_y((y − x)/|y − x|) = 1/|y − x|. Two applications of the divergence theorem turn the force
// between uniform regions A and B into
//   F(A, B) = ∮_∂A ∮_∂B n_A(x) [(y − x)·n_B(y)] / |y − x| ds_y ds_x,
// whose integrand is bounded (|(y − x)·n_B| ≤ |y − x|), so touching, interlocking and even
// overlapping regions are handled without any singularity. For a straight edge j of ∂B,
// (y − x)·n_j is constant in y and ∫_edge ds_y / |y − x| has a closed form (a difference of
// asinh): edge pairs near each other relative to their lengths use it with Gauss–Legendre
// quadrature along edge i; pairs apart use a two-point Gauss rule on both edges (no logarithm,
// four edges of B at a time on vector registers). Low-order rules for edge pairs far apart err by
// up to a percent of the force on coarse polygons (terms cancel around closed outlines), so
// regions whose circles are apart use multipole expansions instead (below): relative error about
// 1e-5, at a cost that does not grow with the edge counts.
// Without them (no pair table), regions far apart (centroid distance above 5 times the sum of
// their radii) use the second-order far-field expansion (far_field_force in gravitation.hpp).
#pragma once

#include <array>
#include <complex>
#include <vector>

#include "libshapeproc/geometry/edge_cluster.hpp"
#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

// Multipole expansions. With complex coordinates, Legendre's expansion of the kernel's potential
// reads, for |y| < |x|,
//   1/|x − y| = (1/|x|) Σ_{k,l ≥ 0} α_k α_l (y/x)^k (ȳ/x̄)^l,   α_k = C(2k, k) / 4^k,
// (P_n(cos φ) = Σ_{k+l=n} α_k α_l e^{i(k−l)φ}), and the terms of total order n = k + l are at most
// (|y|/|x|)^n. So the potential Φ_B(x) = ∫_B dA_y / |y − x| of a region follows from its complex
// moments M_kl = ∫_B z^k z̄^l dA (z about the centroid), and the mutual potential of two regions
// from one table per pair of shapes (PairExpansion), whose gradient is the force.
constexpr int kMomentOrder = 24;
// Index of (k, l), k + l ≤ kMomentOrder, in the triangular tables: by total order, then l.
constexpr int moment_index(int k, int l) { return (k + l) * (k + l + 1) / 2 + l; }
constexpr int kMomentCount = moment_index(0, kMomentOrder) + 1;

// The boundary of a region's mass: edges with outward unit normals. A point element is a unit
// point mass (no edges).
struct MassBoundary2 {
  std::vector<Vec2> start, end, normal;
  std::vector<Vec2> unit;      // (end − start)/length, zero for an empty edge (set by finish())
  std::vector<double> length;  // |end − start| (set by finish())
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
  Eigen::Matrix2d moments = Eigen::Matrix2d::Zero();  // ∫ (x − c)(x − c)^T dA
  double radius = 0.0;                                // of the edges around the centroid
  bool point = false;
  // M_kl = ∫ z^k z̄^l dA about the centroid (moment_index layout; a point mass has M_00 = 1 only).
  std::vector<std::complex<double>> complex_moments;
  // The edges as the other side of an edge pair sees them (set by finish()), one entry per
  // non-empty edge in arrays of doubles, padded with inert entries to a multiple of 4 so that
  // the loop over them runs on vector registers: the two Gauss points, the midpoint, the normal,
  // n·start, a quarter of the length, the length, and the edge's index (-1 for padding).
  struct EdgeRule {
    enum Column { y0x, y0y, y1x, y1y, mx, my, nx, ny, c, quarter, length, kColumns };
    std::array<std::vector<double>, kColumns> columns;
    std::vector<int> edge;
    const double* operator[](Column k) const { return columns[static_cast<std::size_t>(k)].data(); }
  } rule;
  // The rule's entries in clusters of nearby edges (each a run of whole groups of 4 entries):
  // an edge far from a cluster sees the cluster's expansion instead of its edges.
  std::vector<EdgeCluster> clusters;

  // Adds an edge with its outward normal (the side away from the mass), updating area and
  // centroid; call finish() after the last edge.
  void add_edge(const Vec2& a, const Vec2& b, const Vec2& outward_normal);
  void finish();
};

// The mutual-potential table of two regions: U(R) = ∫_A ∫_B dA dA / |x − y| =
// (1/|R|) Σ_{k+l ≤ p} G_kl R^{−k} R̄^{−l}, R = c_A − c_B, converging for |R| > r_A + r_B with
// terms of total order n at most ((r_A + r_B)/|R|)^n.
struct PairExpansion {
  std::vector<std::complex<double>> g;  // G_kl, moment_index layout
  // Σ_l (2l + 1) |G_{n−l,l}| per total order n: the force's order-n terms are at most this
  // over |R|^{n+2}.
  std::vector<double> order_bound;
};
PairExpansion pair_expansion(const MassBoundary2& a, const MassBoundary2& b);

// A bound on |F − F_0| / |F_0| for every centroid distance |R| ≥ `distance`, where F_0 is the
// expansion's first term (along the line of centroids) and `radii` = r_A + r_B: the sum of the
// higher orders' bounds plus the truncated tail's. Infinity unless radii/distance < 0.9. The
// direction of F is then within asin of it of the line of centroids.
double monopole_deviation(const PairExpansion& pair, double radii, double distance);

// F(A, B) with B moved by `offset`. Regions whose circles about their centroids are far apart
// relative to their radii use the pair's expansion (when given; else the second-order far field
// beyond 5 times the radii); edges of A well outside B's circle use B's expansion of Φ_B; the
// rest the edge-pair integrals. Expansions and quadratures are truncated for a relative error
// of the potentials below about 1e-6.
Vec2 gravitation_force(const MassBoundary2& a, const MassBoundary2& b, const Vec2& offset,
                       const PairExpansion* pair = nullptr);
// The edge-pair boundary integral alone (the reference the expansions are tested against).
Vec2 gravitation_force_edges(const MassBoundary2& a, const MassBoundary2& b, const Vec2& offset);

// The 3D analogue for solids bounded by closed triangle meshes: in 3D div_y((y − x)/|y − x|) is
// 2/|y − x|, so F(A, B) = ½ ∮_∂A ∮_∂B n_A(x) [(y − x)·n_B(y)] / |y − x| dS_y dS_x, again with a
// bounded integrand. Both surface integrals use symmetric triangle rules (1 point for triangle
// pairs far apart relative to their sizes, 3 points, or 3 points on each quarter when near).
struct MassSurface3 {
  std::vector<std::array<Vec3, 3>> triangles;  // oriented outwards
  std::vector<Vec3> normal;                    // unit outward normals
  std::vector<double> area;
  std::vector<Vec3> centre;  // of each triangle
  std::vector<double> size;  // each triangle's longest edge
  // Each triangle's quadrature points for near pairs: the degree-2 rule's 3 and the 12 of that
  // rule on its four midpoint sub-triangles.
  std::vector<std::array<Vec3, 3>> points3;
  std::vector<std::array<Vec3, 12>> points12;
  double volume = 0.0;
  Vec3 centroid = Vec3::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();  // ∫ (x − c)(x − c)^T dV
  double radius = 0.0;

  // From a closed mesh; flips the orientation when the signed volume is negative.
  static MassSurface3 from_closed_mesh(const std::vector<Vec3>& vertices,
                                       const std::vector<std::array<int, 3>>& triangles);
};

Vec3 gravitation_force(const MassSurface3& a, const MassSurface3& b, const Vec3& offset);

}  // namespace shapeproc::geometry
