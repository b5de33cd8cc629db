// Bounding-volume hierarchy of axis-aligned boxes over primitives (segments in 2D, triangles in
// 3D, mass points), and the dual-tree search for the closest pair of primitives of two shapes.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace shapeproc::geometry {

template <int D>
struct BoxTree {
  using Vec = Eigen::Matrix<double, D, 1>;
  using Box = Eigen::AlignedBox<double, D>;

  struct Node {
    Box box;
    int first = 0;  // children are nodes[first] and nodes[first + 1] for inner nodes;
    int count = 0;  // for leaves (count > 0) primitives order[first .. first + count)
  };
  std::vector<Node> nodes;  // nodes[0] is the root (absent when there is no primitive)
  std::vector<int> order;   // primitive indices, grouped by leaf

  bool empty() const { return nodes.empty(); }

  // Calls `visit(i)` for each primitive i whose box (of `boxes`, as built) intersects `query`.
  template <class Visit>
  void for_each_intersecting(const Box& query, const std::vector<Box>& boxes, Visit&& visit) const {
    for_each_intersecting_while(query, boxes, [&visit](int i) {
      visit(i);
      return true;
    });
  }

  // The same, stopping as soon as `visit(i)` returns false; returns whether it went through.
  template <class Visit>
  bool for_each_intersecting_while(const Box& query, const std::vector<Box>& boxes,
                                   Visit&& visit) const {
    if (nodes.empty()) return true;
    std::vector<int> stack = {0};
    while (!stack.empty()) {
      const Node& node = nodes[static_cast<std::size_t>(stack.back())];
      stack.pop_back();
      if (!node.box.intersects(query)) continue;
      if (node.count > 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const int i = order[static_cast<std::size_t>(k)];
          if (boxes[static_cast<std::size_t>(i)].intersects(query) && !visit(i)) return false;
        }
      } else {
        stack.push_back(node.first);
        stack.push_back(node.first + 1);
      }
    }
    return true;
  }

  // Builds the tree by median splits along the longest axis of the centres' box.
  static BoxTree build(const std::vector<Box>& boxes, int leaf_size = 4) {
    BoxTree tree;
    if (boxes.empty()) return tree;
    tree.order.resize(boxes.size());
    std::iota(tree.order.begin(), tree.order.end(), 0);
    tree.nodes.reserve(2 * boxes.size() / static_cast<std::size_t>(leaf_size) + 2);
    tree.nodes.emplace_back();
    tree.split(0, 0, static_cast<int>(boxes.size()), boxes, leaf_size);
    return tree;
  }

 private:
  void split(int node, int begin, int end, const std::vector<Box>& boxes, int leaf_size) {
    Box box, centres;
    for (int i = begin; i < end; ++i) {
      box.extend(boxes[order[i]]);
      centres.extend(boxes[order[i]].center());
    }
    nodes[node].box = box;
    if (end - begin <= leaf_size) {
      nodes[node].first = begin;
      nodes[node].count = end - begin;
      return;
    }
    int axis = 0;
    (centres.max() - centres.min()).maxCoeff(&axis);
    const int middle = begin + (end - begin) / 2;
    std::nth_element(
        order.begin() + begin, order.begin() + middle, order.begin() + end,
        [&](int a, int b) { return boxes[a].center()[axis] < boxes[b].center()[axis]; });
    const int first = static_cast<int>(nodes.size());
    nodes[node].first = first;
    nodes[node].count = 0;
    nodes.emplace_back();
    nodes.emplace_back();
    split(first, begin, middle, boxes, leaf_size);
    split(first + 1, middle, end, boxes, leaf_size);
  }
};

// The identity bound of closest_pair_squared_distance: the exact minimum is searched.
struct ExactMinimum {
  double operator()(double best) const { return best; }
};

// Smallest `squared_distance(i, j)` over primitives i of `a` and j of `b`, where `b` is moved by
// `offset` (boxes of b are compared translated). Branch and bound on box distances; returns
// `squared_cutoff` when nothing is closer, and stops early once a pair at distance 0 is found.
// `squared_distance(i, j, bound)` must return the true squared distance of the two primitives
// (b's one translated), or anything not below `bound` when that distance is not below it.
//
// `prune(best)` (≤ best, not decreasing in best) lets callers that only need to know an interval
// stop early: pairs of boxes at least prune(best) apart are skipped, so the true minimum lies in
// [prune(result), result].
template <int D, class PrimitiveSquaredDistance, class Prune = ExactMinimum>
double closest_pair_squared_distance(const BoxTree<D>& a, const BoxTree<D>& b,
                                     const typename BoxTree<D>::Vec& offset, double squared_cutoff,
                                     PrimitiveSquaredDistance&& squared_distance,
                                     Prune&& prune = Prune{}) {
  if (a.empty() || b.empty()) return squared_cutoff;
  double best = squared_cutoff;
  struct Pending {
    int na, nb;
    double lower;  // squared box distance
  };
  // Depth-first with an explicit stack (on the stack frame: a depth-first search of two
  // balanced trees holds at most one pending pair per level), children visited nearest first.
  constexpr int kCapacity = 128;
  Pending stack[kCapacity];
  int top = 0;
  auto box_distance2 = [&](int na, int nb) {
    return a.nodes[na].box.squaredExteriorDistance(b.nodes[nb].box.translated(offset));
  };
  stack[top++] = {0, 0, box_distance2(0, 0)};
  double bound = prune(best);
  while (top > 0) {
    const Pending p = stack[--top];
    if (p.lower >= bound) continue;
    const auto& node_a = a.nodes[p.na];
    const auto& node_b = b.nodes[p.nb];
    if (node_a.count > 0 && node_b.count > 0) {
      for (int i = node_a.first; i < node_a.first + node_a.count; ++i) {
        for (int j = node_b.first; j < node_b.first + node_b.count; ++j) {
          const double d = squared_distance(a.order[i], b.order[j], bound);
          if (d < best) {
            best = d;
            if (best <= 0.0) return 0.0;
            bound = prune(best);
          }
        }
      }
      continue;
    }
    // Split the node with the larger box (or the only inner one).
    const bool split_a =
        node_b.count > 0 ||
        (node_a.count == 0 && node_a.box.sizes().squaredNorm() >= node_b.box.sizes().squaredNorm());
    Pending first, second;
    if (split_a) {
      first = {node_a.first, p.nb, box_distance2(node_a.first, p.nb)};
      second = {node_a.first + 1, p.nb, box_distance2(node_a.first + 1, p.nb)};
    } else {
      first = {p.na, node_b.first, box_distance2(p.na, node_b.first)};
      second = {p.na, node_b.first + 1, box_distance2(p.na, node_b.first + 1)};
    }
    if (first.lower < second.lower) std::swap(first, second);
    if (top + 2 > kCapacity)
      throw std::length_error("closest_pair_squared_distance: trees too deep");
    stack[top++] = first;   // farther one below
    stack[top++] = second;  // nearer one on top
  }
  return best;
}

// The same with `distance(i, j)` returning plain distances, and the result a distance
// (sqrt of a rounded square gives the value back exactly, so nothing is lost).
template <int D, class PrimitiveDistance>
double closest_pair_distance(const BoxTree<D>& a, const BoxTree<D>& b,
                             const typename BoxTree<D>::Vec& offset, double cutoff,
                             PrimitiveDistance&& distance) {
  return std::sqrt(
      closest_pair_squared_distance<D>(a, b, offset, cutoff * cutoff, [&](int i, int j, double) {
        const double d = distance(i, j);
        return d * d;
      }));
}

}  // namespace shapeproc::geometry
