#include "libshapeproc/geometry/gravitation.hpp"

#include <cmath>

namespace shapeproc::geometry {

namespace {

template <int D>
MassModel<D> build(std::vector<typename MassModel<D>::Vec> points, std::vector<double> weights) {
  using Vec = typename MassModel<D>::Vec;
  using Box = typename BoxTree<D>::Box;
  MassModel<D> model;
  model.points = std::move(points);
  model.weights = std::move(weights);
  std::vector<Box> boxes;
  boxes.reserve(model.points.size());
  for (const Vec& p : model.points) boxes.emplace_back(p, p);
  model.tree = BoxTree<D>::build(boxes, 8);
  const std::size_t n = model.tree.nodes.size();
  model.node_centre.assign(n, Vec::Zero());
  model.node_mass.assign(n, 0.0);
  model.node_radius.assign(n, 0.0);
  // Children always come after their parent: accumulate bottom-up.
  for (std::size_t k = n; k-- > 0;) {
    const auto& node = model.tree.nodes[k];
    Vec weighted = Vec::Zero();
    double mass = 0.0;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const int p = model.tree.order[i];
        weighted += model.weights[p] * model.points[p];
        mass += model.weights[p];
      }
    } else {
      for (int c = node.first; c < node.first + 2; ++c) {
        weighted += model.node_mass[c] * model.node_centre[c];
        mass += model.node_mass[c];
      }
    }
    model.node_mass[k] = mass;
    model.node_centre[k] = mass > 0 ? Vec(weighted / mass) : Vec(node.box.center());
    // Farthest box corner from the centre of mass bounds every point of the node.
    Vec far;
    for (int axis = 0; axis < D; ++axis) {
      far[axis] = std::max(model.node_centre[k][axis] - node.box.min()[axis],
                           node.box.max()[axis] - model.node_centre[k][axis]);
    }
    model.node_radius[k] = far.norm();
  }
  return model;
}

template <int D>
typename MassModel<D>::Vec kernel(const typename MassModel<D>::Vec& from,
                                  const typename MassModel<D>::Vec& to, double weight) {
  using Vec = typename MassModel<D>::Vec;
  const Vec r = to - from;
  const double r2 = r.squaredNorm();
  if (r2 == 0.0) return Vec::Zero();
  return (weight / (r2 * std::sqrt(r2))) * r;
}

template <int D>
typename MassModel<D>::Vec force(const MassModel<D>& a, const MassModel<D>& b,
                                 const typename MassModel<D>::Vec& offset, double theta) {
  using Vec = typename MassModel<D>::Vec;
  Vec total = Vec::Zero();
  if (a.tree.empty() || b.tree.empty()) return total;
  const double theta2 = theta * theta;
  std::vector<std::pair<int, int>> stack;
  stack.reserve(128);
  stack.emplace_back(0, 0);
  while (!stack.empty()) {
    const auto [na, nb] = stack.back();
    stack.pop_back();
    const Vec ca = a.node_centre[na];
    const Vec cb = b.node_centre[nb] + offset;
    const double reach = a.node_radius[na] + b.node_radius[nb];
    const double d2 = (cb - ca).squaredNorm();
    if (reach * reach < theta2 * d2) {
      total += kernel<D>(ca, cb, a.node_mass[na] * b.node_mass[nb]);
      continue;
    }
    const auto& node_a = a.tree.nodes[na];
    const auto& node_b = b.tree.nodes[nb];
    if (node_a.count > 0 && node_b.count > 0) {
      for (int i = node_a.first; i < node_a.first + node_a.count; ++i) {
        const int pa = a.tree.order[i];
        for (int j = node_b.first; j < node_b.first + node_b.count; ++j) {
          const int pb = b.tree.order[j];
          total +=
              kernel<D>(a.points[pa], Vec(b.points[pb] + offset), a.weights[pa] * b.weights[pb]);
        }
      }
      continue;
    }
    const bool open_a =
        node_b.count > 0 || (node_a.count == 0 && a.node_radius[na] >= b.node_radius[nb]);
    if (open_a) {
      stack.emplace_back(node_a.first, nb);
      stack.emplace_back(node_a.first + 1, nb);
    } else {
      stack.emplace_back(na, node_b.first);
      stack.emplace_back(na, node_b.first + 1);
    }
  }
  return total;
}

template <int D>
typename MassModel<D>::Vec force_direct(const MassModel<D>& a, const MassModel<D>& b,
                                        const typename MassModel<D>::Vec& offset) {
  using Vec = typename MassModel<D>::Vec;
  Vec total = Vec::Zero();
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (std::size_t j = 0; j < b.points.size(); ++j) {
      total += kernel<D>(a.points[i], Vec(b.points[j] + offset), a.weights[i] * b.weights[j]);
    }
  }
  return total;
}

}  // namespace

MassModel2 make_mass_model(std::vector<Vec2> points, std::vector<double> weights) {
  return build<2>(std::move(points), std::move(weights));
}
MassModel3 make_mass_model(std::vector<Vec3> points, std::vector<double> weights) {
  return build<3>(std::move(points), std::move(weights));
}
Vec3 gravitation_force(const MassModel3& a, const MassModel3& b, const Vec3& offset, double theta) {
  return force<3>(a, b, offset, theta);
}
Vec2 gravitation_force_direct(const MassModel2& a, const MassModel2& b, const Vec2& offset) {
  return force_direct<2>(a, b, offset);
}
Vec3 gravitation_force_direct(const MassModel3& a, const MassModel3& b, const Vec3& offset) {
  return force_direct<3>(a, b, offset);
}

}  // namespace shapeproc::geometry
