// The arrangement Ijiri et al.'s local growth builds (2008, §5): elements and seeds joined by
// edges. An element copies a reference element of the exemplar (its sub-id) turned by an angle;
// a seed is a place where an element may grow, with or without a symbol id. Every directed edge
// a→b carries the offset a's ring shape wants b at, which the relaxation of §5.5 pulls towards:
// the reference ring's (turned) for an element's ring neighbours, the offset when the edge was
// made for everything else ("their current neighbouring shapes").
//
// Nodes are indexed by a grid on the domain's torus or in its box; offsets are minimum images.
#pragma once

#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"

namespace shapeproc::methods {

using geometry::Vec3;

struct GrowthNode {
  Vec3 position = Vec3::Zero();
  int symbol = -1;     // -1: none (a seed that may become anything)
  int source = -1;     // the reference element copied; -1 while a seed
  double angle = 0.0;  // the turn of the copy, radians
  bool alive = true;
  bool fixed = false;  // held by the relaxation
  bool seed() const { return source < 0; }
};

struct GrowthEdge {
  int node = 0;
  Vec3 desired = Vec3::Zero();  // where this node's ring wants `node`, relative to it
};

class GrowthGraph {
 public:
  // `reach`: the longest edge the graph will hold; queries are exact up to it.
  GrowthGraph(const geometry::Domain& domain, double reach);

  std::size_t size() const { return nodes_.size(); }
  const GrowthNode& node(int n) const { return nodes_[static_cast<std::size_t>(n)]; }
  GrowthNode& node(int n) { return nodes_[static_cast<std::size_t>(n)]; }
  const std::vector<GrowthEdge>& edges(int n) const { return edges_[static_cast<std::size_t>(n)]; }
  const geometry::Domain& domain() const { return domain_; }

  // Whether `p` is where nodes may be: anywhere on a torus, else in the box and the mask.
  bool in_domain(const Vec3& p) const;

  int add(GrowthNode node);  // its position wrapped
  void remove(int n);        // with its edges
  void move(int n, const Vec3& position);

  // x_b − x_a, minimum image.
  Vec3 offset(int a, int b) const;
  bool connected(int a, int b) const;
  // Joins a and b, a's ring wanting b at `a_to_b` and b's wanting a at `b_to_a`.
  void connect(int a, int b, const Vec3& a_to_b, const Vec3& b_to_a);
  // Joins a and b where they are now.
  void connect(int a, int b) { connect(a, b, offset(a, b), offset(b, a)); }
  void set_desired(int a, int b, const Vec3& a_to_b);

  // The nearest live node within `distance` (≤ reach) of `p`, other than `skip`; -1 if none.
  int nearest_within(const Vec3& p, double distance, int skip = -1) const;
  // Live nodes within `distance` (≤ reach) of `p`.
  std::vector<int> within(const Vec3& p, double distance) const;
  // Whether the segment from node a to the point a + `to` properly crosses an edge that has
  // neither a nor `b` (-1: none) as an end.
  bool crosses(int a, const Vec3& to, int b = -1) const;

 private:
  geometry::Domain domain_;
  double reach_;
  geometry::NeighbourGrid grid_;
  std::vector<GrowthNode> nodes_;
  std::vector<std::vector<GrowthEdge>> edges_;
};

}  // namespace shapeproc::methods
