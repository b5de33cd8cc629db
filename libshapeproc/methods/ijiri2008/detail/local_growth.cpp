#include "libshapeproc/methods/ijiri2008/detail/local_growth.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/geometry/overlap_depth.hpp"
#include "libshapeproc/methods/common/element_reconstruction.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"

namespace shapeproc::methods {

namespace {

// The smaller angle between two directions, in [0, π].
double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.x() * b.x() + a.y() * b.y());
}

constexpr double kTurnStep = core::kPi / 360.0;  // 0.5 degrees

double snapped(const Growth& g, double angle) {
  return g.options.exact_overlap ? std::round(angle / kTurnStep) * kTurnStep : angle;
}

const geometry::Proxy2& proxy_of(Growth& g, int shape, double angle) {
  const auto step = static_cast<long>(std::lround(angle / kTurnStep)) % 720;
  const std::pair<int, long> key{shape, step < 0 ? step + 720 : step};
  auto found = g.proxies.find(key);
  if (found != g.proxies.end()) return found->second;
  geometry::ProxyOptions options;
  options.tolerance = geometry::kOutlineTolerance;  // as `stats` judges collisions
  const geometry::Shape& drawn = g.exemplar.scene.shapes[static_cast<std::size_t>(shape)];
  Similarity turn_only;
  turn_only.linear = Eigen::AngleAxisd(static_cast<double>(key.second) * kTurnStep, Vec3::UnitZ())
                         .toRotationMatrix();
  return g.proxies
      .emplace(key, geometry::make_proxy2(key.second == 0 ? drawn : map_shape(drawn, turn_only),
                                          options))
      .first->second;
}

// Whether a copy of exemplar element `source` turned by `angle` at `p` would overlap an element
// other than `skip`.
bool overlaps(Growth& g, int source, double angle, const Vec3& p, int skip) {
  if (g.options.circle_overlap) {
    const double r = g.exemplar.circle_radius[static_cast<std::size_t>(source)];
    for (const int o : g.graph.within(g.graph.domain().wrap(p), r + g.largest_circle)) {
      const GrowthNode& other = g.graph.node(o);
      if (o == skip || other.seed()) continue;
      const double reach = r + g.exemplar.circle_radius[static_cast<std::size_t>(other.source)];
      if (g.graph.domain().minimum_image(other.position - p).squaredNorm() < reach * reach)
        return true;
    }
    return false;
  }
  const int shape = g.exemplar.scene.elements[static_cast<std::size_t>(source)].shape;
  const double radius = g.exemplar.shape_radius[static_cast<std::size_t>(shape)];
  for (const int o : g.graph.within(g.graph.domain().wrap(p), radius + g.largest_radius)) {
    const GrowthNode& other = g.graph.node(o);
    if (o == skip || other.seed()) continue;
    const int other_shape = g.exemplar.scene.elements[static_cast<std::size_t>(other.source)].shape;
    const Vec3 offset = g.graph.domain().minimum_image(other.position - p);
    const double reach = radius + g.exemplar.shape_radius[static_cast<std::size_t>(other_shape)];
    if (offset.squaredNorm() >= reach * reach) continue;
    if (geometry::overlap_depth(proxy_of(g, shape, angle), proxy_of(g, other_shape, other.angle),
                                geometry::Vec2(offset.x(), offset.y())) > 0)
      return true;
  }
  return false;
}

// Step 2: the seed's partial ring, and the reference that matches it best.
RingMatch match_seed(Growth& g, int s, std::vector<int>& ring, core::Random& random) {
  std::vector<TargetNeighbour> target;
  for (const GrowthEdge& e : g.graph.edges(s)) {
    const GrowthNode& n = g.graph.node(e.node);
    target.push_back({g.graph.offset(s, e.node), n.symbol, n.source});
  }
  const std::vector<int> order = partial_ring_order(target);
  std::vector<TargetNeighbour> ordered;
  ring.clear();
  for (const int i : order) {
    ordered.push_back(target[static_cast<std::size_t>(i)]);
    ring.push_back(g.graph.edges(s)[static_cast<std::size_t>(i)].node);
  }
  const int symbol = g.graph.node(s).symbol;
  const std::vector<int>& candidates =
      symbol >= 0 ? g.exemplar.by_symbol[static_cast<std::size_t>(symbol)] : g.exemplar.all;
  const double field = g.options.rotation == RotationMode::flow_field
                           ? g.options.field.angle_at(g.graph.node(s).position)
                           : 0.0;
  MatchFilter accept;
  if (g.options.exact_overlap || g.options.circle_overlap) {
    const Vec3 p = g.graph.node(s).position;
    accept = [&g, p, s](const ReferenceRing& reference, double angle) {
      return !overlaps(g, reference.element, snapped(g, angle), p, s);
    };
  }
  return best_match(ordered, g.exemplar.references, candidates, g.options.rotation, field,
                    g.weights, random, accept);
}

// The smallest angle between direction `d` and an edge of node s.
double smallest_edge_angle(const Growth& g, int s, const Vec3& d) {
  double smallest = core::kPi;
  for (const GrowthEdge& e : g.graph.edges(s))
    smallest = std::min(smallest, angle_between(d, g.graph.offset(s, e.node)));
  return smallest;
}

// Step 3a: the node for reference neighbour j of the ring laid at s (a new seed, an existing
// node within l_short, or -1 when a heuristic drops it).
int place_ring_member(Growth& g, int s, const ReferenceRing& ref, std::size_t j, double angle) {
  const std::size_t m = ref.offset.size();
  const Vec3 want = turn_about_z(ref.offset[j], angle);
  const Vec3 q = g.graph.node(s).position + want;
  if (!g.graph.in_domain(q)) {
    ++g.counters.outside;
    return -1;
  }
  if (const int near = g.graph.nearest_within(g.graph.domain().wrap(q), g.l_short, s); near >= 0) {
    ++g.counters.merged;
    if (!g.graph.connected(s, near)) {
      if (g.graph.crosses(s, g.graph.offset(s, near), near)) return -1;
      g.graph.connect(s, near, want, g.graph.offset(near, s));
    } else {
      g.graph.set_desired(s, near, want);
    }
    return near;
  }
  const double original = std::min(angle_between(ref.offset[j], ref.offset[(j + m - 1) % m]),
                                   angle_between(ref.offset[j], ref.offset[(j + 1) % m]));
  if (smallest_edge_angle(g, s, want) < 0.5 * original) {
    ++g.counters.angle;
    return -1;
  }
  if (g.graph.crosses(s, want)) {
    ++g.counters.crossing;
    return -1;
  }
  GrowthNode seed;
  seed.position = q;
  seed.symbol = ref.neighbour_symbol[j];
  const int n = g.graph.add(seed);
  g.graph.connect(s, n, want, -want);
  g.push_seed(n);
  return n;
}

// Step 3b: consecutive ring members joined, with an extra seed where they lie too far apart.
void join_ring(Growth& g, int s, const ReferenceRing& ref, const std::vector<int>& slot) {
  const std::size_t m = ref.offset.size();
  for (std::size_t j = 0; j < m; ++j) {
    const int a = slot[j], b = slot[(j + 1) % m];
    if (a < 0 || b < 0 || a == b || a == s || b == s || g.graph.connected(a, b)) continue;
    const Vec3 sa = g.graph.offset(s, a), sb = g.graph.offset(s, b);
    const double original = (ref.offset[(j + 1) % m] - ref.offset[j]).norm();
    if ((sb - sa).norm() <= 1.5 * original) {
      if (!g.graph.crosses(a, sb - sa, b)) g.graph.connect(a, b);
      continue;
    }
    // An extra seed on the bisector, as far out as a and b on average (Fig. 6e).
    const Vec3 bisector = (sa.normalized() + sb.normalized()).normalized();
    if (!bisector.allFinite()) continue;
    const Vec3 at = 0.5 * (sa.norm() + sb.norm()) * bisector;
    const Vec3 q = g.graph.node(s).position + at;
    if (!g.graph.in_domain(q) || g.graph.nearest_within(g.graph.domain().wrap(q), g.l_short) >= 0 ||
        g.graph.crosses(s, at))
      continue;
    GrowthNode seed;
    seed.position = q;
    const int x = g.graph.add(seed);
    g.graph.connect(s, x);
    if (!g.graph.crosses(a, g.graph.offset(a, x), x)) g.graph.connect(a, x);
    if (!g.graph.crosses(b, g.graph.offset(b, x), x)) g.graph.connect(x, b);
    g.push_seed(x);
    ++g.counters.extra;
  }
}

}  // namespace

// Step 1: the next seed to grow, nearest the origins, or a seed of higher priority near it.
int next_seed(Growth& g) {
  while (!g.queue.empty()) {
    const int s = g.queue.top().second;
    g.queue.pop();
    const GrowthNode& n = g.graph.node(s);
    if (!n.alive || !n.seed()) continue;
    if (g.symbol_priority.empty()) return s;
    int best = s;
    for (const int o : g.graph.within(n.position, g.neighbourhood)) {
      const GrowthNode& other = g.graph.node(o);
      if (other.seed() && g.priority(o) > g.priority(best)) best = o;
    }
    if (best != s) g.queue.emplace(g.queue.empty() ? 0.0 : g.queue.top().first, s);
    return best;
  }
  return -1;
}

// With exact overlaps, the relaxation's moves must not make elements overlap.
MoveFilter move_filter(Growth& g) {
  if (!g.options.exact_overlap && !g.options.circle_overlap) return {};
  return [&g](int n, const Vec3& p) {
    const GrowthNode& node = g.graph.node(n);
    return node.seed() || !overlaps(g, node.source, node.angle, p, n);
  };
}

// One growth step at seed s; false when the seed had nothing to match and was dropped.
bool grow(Growth& g, int s, core::Random& random) {
  std::vector<int> ring;
  const RingMatch match = match_seed(g, s, ring, random);
  if (match.reference < 0) {
    g.graph.remove(s);
    ++g.counters.dropped;
    return false;
  }
  const ReferenceRing& ref = g.exemplar.references[static_cast<std::size_t>(match.reference)];
  GrowthNode& node = g.graph.node(s);
  node.source = ref.element;
  node.symbol = ref.symbol;
  node.angle = snapped(g, match.angle);
  ++g.elements;
  const std::size_t m = ref.offset.size();
  std::vector<int> slot(m, -1);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const std::size_t j = (static_cast<std::size_t>(match.shift) + i) % m;
    slot[j] = ring[i];
    g.graph.set_desired(s, ring[i], turn_about_z(ref.offset[j], match.angle));
  }
  for (std::size_t i = ring.size(); i < m; ++i) {
    const std::size_t j = (static_cast<std::size_t>(match.shift) + i) % m;
    slot[j] = place_ring_member(g, s, ref, j, match.angle);
  }
  join_ring(g, s, ref, slot);
  if (g.options.relax)
    relax_rings(g.graph, graph_neighbourhood(g.graph, s, g.options.relax_hops),
                g.options.relax_sweeps, move_filter(g));
  return true;
}

}  // namespace shapeproc::methods
