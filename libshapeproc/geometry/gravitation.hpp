// Relative orientation by gravitation (paper §4, after Matsakis & Wendling's force histograms):
// the direction of F(a, b) = ∫_a ∫_b (y − x) / |y − x|^3 dm(x) dm(y) between two shapes' masses.
//
// Each shape's mass is represented by weighted cubature points (midpoint rule on a grid over its
// filled region, see proxy.hpp), and the double sum is evaluated with a Barnes–Hut dual-tree
// scheme: two clusters interact through their centres of mass when (r_a + r_b) < θ |c_b − c_a|,
// otherwise the larger one is opened; leaf-leaf interactions are summed exactly. Point pairs that
// coincide (overlapping shapes on the same grid) are skipped: their contributions cancel in pairs.
#pragma once

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

// F(a, b) with b moved by `offset`. theta is the Barnes–Hut opening parameter (0 = exact sum).
Vec2 gravitation_force(const MassModel2& a, const MassModel2& b, const Vec2& offset, double theta);
Vec3 gravitation_force(const MassModel3& a, const MassModel3& b, const Vec3& offset, double theta);

// The exact double sum over all point pairs (the reference for tests and for tiny models).
Vec2 gravitation_force_direct(const MassModel2& a, const MassModel2& b, const Vec2& offset);
Vec3 gravitation_force_direct(const MassModel3& a, const MassModel3& b, const Vec3& offset);

}  // namespace shapeproc::geometry
