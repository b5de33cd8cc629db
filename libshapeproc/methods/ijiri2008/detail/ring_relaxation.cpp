#include "libshapeproc/methods/ijiri2008/detail/ring_relaxation.hpp"

#include <algorithm>

namespace shapeproc::methods {

std::vector<int> graph_neighbourhood(const GrowthGraph& graph, int centre, int hops) {
  std::vector<int> out{centre}, frontier{centre};
  for (int hop = 0; hop < hops; ++hop) {
    std::vector<int> next;
    for (const int n : frontier)
      for (const GrowthEdge& e : graph.edges(n))
        if (std::find(out.begin(), out.end(), e.node) == out.end()) {
          out.push_back(e.node);
          next.push_back(e.node);
        }
    frontier = std::move(next);
  }
  return out;
}

double relax_rings(GrowthGraph& graph, const std::vector<int>& nodes, int sweeps,
                   const MoveFilter& allowed) {
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (const int k : nodes) {
      const GrowthNode& node = graph.node(k);
      if (!node.alive || node.fixed || graph.edges(k).empty()) continue;
      // Terms k→j want x_k = x_j − r_kj, terms j→k want x_k = x_j + r_jk.
      Vec3 shift = Vec3::Zero();
      for (const GrowthEdge& e : graph.edges(k)) {
        const Vec3 d = graph.offset(k, e.node);
        Vec3 back = -d;
        for (const GrowthEdge& b : graph.edges(e.node))
          if (b.node == k) back = b.desired;
        shift += 2.0 * d - e.desired + back;
      }
      shift /= 2.0 * static_cast<double>(graph.edges(k).size());
      const Vec3 target = node.position + shift;
      if (graph.in_domain(target) && (!allowed || allowed(k, target))) graph.move(k, target);
    }
  }
  double energy = 0.0;
  for (const int k : nodes)
    for (const GrowthEdge& e : graph.edges(k))
      energy += (graph.offset(k, e.node) - e.desired).squaredNorm();
  return energy;
}

}  // namespace shapeproc::methods
