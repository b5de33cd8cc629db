// Relative orientation by gravitation (paper §4, after Matsakis & Wendling's force histograms):
// the direction of F(a, b) = ∫_a ∫_b (y − x) / |y − x|^3 dm(x) dm(y) between two shapes' masses.
//
// Each shape's mass is represented by weighted cubature points (midpoint rule on a grid over its
// filled region, see proxy.hpp), and the double sum is evaluated with a Barnes–Hut dual-tree
// scheme: two clusters interact through their centres of mass when (r_a + r_b) < θ |c_b − c_a|,
// otherwise the larger one is opened; leaf-leaf interactions are summed exactly. Point pairs that
// coincide (overlapping shapes on the same grid) are skipped: their contributions cancel in pairs.
#pragma once

#include <cmath>
#include <vector>

#include "libshapeproc/geometry/box_tree.hpp"
#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::geometry {

template <int D>
struct MassModel {
  using Vec = Eigen::Matrix<double, D, 1>;
  std::vector<Vec> points;
  std::vector<double> weights;
  // Barnes–Hut tree over the points, with per node centre of mass, mass and radius (an upper
  // bound of the distance from the centre of mass to any point of the node).
  BoxTree<D> tree;
  std::vector<Vec> node_centre;
  std::vector<double> node_mass;
  std::vector<double> node_radius;

  double total_mass() const { return node_mass.empty() ? 0.0 : node_mass[0]; }
  Vec centre_of_mass() const { return node_centre.empty() ? Vec::Zero().eval() : node_centre[0]; }
};
using MassModel2 = MassModel<2>;
using MassModel3 = MassModel<3>;

// Builds the tree of a set of weighted points (weights > 0).
MassModel2 make_mass_model(std::vector<Vec2> points, std::vector<double> weights);
MassModel3 make_mass_model(std::vector<Vec3> points, std::vector<double> weights);

// Far-field gravitation between two masses from their moments: mass m, centroid, and second
// moments Q = ∫ (x − c)(x − c)^T dm about the centroid. Taylor expansion of the kernel
// K(r) = r/|r|^3 about R = c_b − c_a to second order (first-order terms vanish about centroids):
//   F ≈ m_a m_b K(R) + ½ (m_b Q_a + m_a Q_b) : ∇∇K(R),
//   (M : ∇∇K)_i = −3 (2 (M R)_i + tr(M) R_i) / |R|^5 + 15 R_i (R·M R) / |R|^7.
// The error is O((r/|R|)^3) relative, r the masses' radii.
template <int D>
Eigen::Matrix<double, D, 1> far_field_force(double mass_a,
                                            const Eigen::Matrix<double, D, D>& moments_a,
                                            double mass_b,
                                            const Eigen::Matrix<double, D, D>& moments_b,
                                            const Eigen::Matrix<double, D, 1>& between) {
  const double r2 = between.squaredNorm();
  const double r = std::sqrt(r2);
  const double r3 = r2 * r, r5 = r3 * r2, r7 = r5 * r2;
  const Eigen::Matrix<double, D, D> m = 0.5 * (mass_b * moments_a + mass_a * moments_b);
  const Eigen::Matrix<double, D, 1> mr = m * between;
  return (mass_a * mass_b / r3) * between - (3.0 / r5) * (2.0 * mr + m.trace() * between) +
         (15.0 * between.dot(mr) / r7) * between;
}

// F(a, b) with b moved by `offset`. theta is the Barnes–Hut opening parameter (0 = exact sum).
// (2D regions use the exact boundary integral of region_gravitation.hpp instead.)
Vec3 gravitation_force(const MassModel3& a, const MassModel3& b, const Vec3& offset, double theta);

// The exact double sum over all point pairs (the reference for tests and for tiny models).
Vec2 gravitation_force_direct(const MassModel2& a, const MassModel2& b, const Vec2& offset);
Vec3 gravitation_force_direct(const MassModel3& a, const MassModel3& b, const Vec3& offset);

}  // namespace shapeproc::geometry
