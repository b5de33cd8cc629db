#include "libshapeproc/methods/ijiri2008/detail/growth_graph.hpp"

#include <algorithm>
#include <limits>

#include "libshapeproc/methods/common/neighbourhood_search.hpp"

namespace shapeproc::methods {

namespace {

double cross(const Vec3& a, const Vec3& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether segments p0p1 and q0q1 cross at a point inside both (touching ends does not count).
bool segments_cross(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 r = p1 - p0, s = q1 - q0;
  const double d1 = cross(r, q0 - p0), d2 = cross(r, q1 - p0);
  const double d3 = cross(s, p0 - q0), d4 = cross(s, p1 - q0);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

}  // namespace

GrowthGraph::GrowthGraph(const geometry::Domain& domain, double reach)
    : domain_(domain),
      reach_(reach),
      grid_(domain.box(), domain.dimension(), 2.0 * reach, domain.periodic()) {}

bool GrowthGraph::in_domain(const Vec3& p) const {
  return domain_.periodic() || inside(domain_, p) >= 0.5;
}

int GrowthGraph::add(GrowthNode node) {
  node.position = domain_.wrap(node.position);
  const auto n = static_cast<int>(nodes_.size());
  grid_.insert(n, node.position);
  nodes_.push_back(node);
  edges_.emplace_back();
  return n;
}

void GrowthGraph::remove(int n) {
  GrowthNode& gone = node(n);
  if (!gone.alive) return;
  gone.alive = false;
  grid_.remove(n, gone.position);
  for (const GrowthEdge& e : edges_[static_cast<std::size_t>(n)]) {
    auto& back = edges_[static_cast<std::size_t>(e.node)];
    back.erase(
        std::remove_if(back.begin(), back.end(), [n](const GrowthEdge& b) { return b.node == n; }),
        back.end());
  }
  edges_[static_cast<std::size_t>(n)].clear();
}

void GrowthGraph::move(int n, const Vec3& position) {
  GrowthNode& moved = node(n);
  grid_.remove(n, moved.position);
  moved.position = domain_.wrap(position);
  grid_.insert(n, moved.position);
}

Vec3 GrowthGraph::offset(int a, int b) const {
  return domain_.minimum_image(node(b).position - node(a).position);
}

bool GrowthGraph::connected(int a, int b) const {
  const auto& list = edges(a);
  return std::any_of(list.begin(), list.end(), [b](const GrowthEdge& e) { return e.node == b; });
}

void GrowthGraph::connect(int a, int b, const Vec3& a_to_b, const Vec3& b_to_a) {
  if (a == b) return;
  if (connected(a, b)) {
    set_desired(a, b, a_to_b);
    set_desired(b, a, b_to_a);
    return;
  }
  edges_[static_cast<std::size_t>(a)].push_back({b, a_to_b});
  edges_[static_cast<std::size_t>(b)].push_back({a, b_to_a});
}

void GrowthGraph::set_desired(int a, int b, const Vec3& a_to_b) {
  for (GrowthEdge& e : edges_[static_cast<std::size_t>(a)])
    if (e.node == b) e.desired = a_to_b;
}

int GrowthGraph::nearest_within(const Vec3& p, double distance, int skip) const {
  int best = -1;
  double best_distance = distance;
  grid_.for_each_candidate(p, [&](int n) {
    if (n == skip) return;
    const double d = domain_.minimum_image(node(n).position - p).norm();
    if (d <= best_distance) {
      if (d == best_distance && best >= 0 && n > best) return;
      best_distance = d;
      best = n;
    }
  });
  return best;
}

std::vector<int> GrowthGraph::within(const Vec3& p, double distance) const {
  std::vector<int> out;
  grid_.for_each_candidate(p, [&](int n) {
    if (domain_.minimum_image(node(n).position - p).norm() <= distance) out.push_back(n);
  });
  std::sort(out.begin(), out.end());
  return out;
}

bool GrowthGraph::crosses(int a, const Vec3& to, int b) const {
  const Vec3 p0 = node(a).position, p1 = p0 + to;
  const Vec3 middle = p0 + 0.5 * to;
  bool found = false;
  grid_.for_each_candidate(domain_.wrap(middle), [&](int u) {
    if (found || u == a || u == b) return;
    const Vec3 q0 = middle + domain_.minimum_image(node(u).position - middle);
    for (const GrowthEdge& e : edges(u)) {
      if (e.node == a || e.node == b) continue;
      const Vec3 q1 = q0 + offset(u, e.node);
      if (segments_cross(p0, p1, q0, q1)) {
        found = true;
        return;
      }
    }
  });
  return found;
}

}  // namespace shapeproc::methods
