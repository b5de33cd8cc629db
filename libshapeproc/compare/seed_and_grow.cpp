#include "libshapeproc/compare/seed_and_grow.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>

#include "libshapeproc/compare/element_reconstruction.hpp"
#include "libshapeproc/compare/em_exemplar.hpp"
#include "libshapeproc/compare/growth_graph.hpp"
#include "libshapeproc/compare/ring_relaxation.hpp"
#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/geometry/overlap_depth.hpp"
#include "libshapeproc/geometry/proxy.hpp"

namespace shapeproc::compare {

namespace {

Vec3 turn(const Vec3& v, double angle) {
  if (angle == 0.0) return v;
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), 0.0};
}

// The smaller angle between two directions, in [0, π].
double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.x() * b.x() + a.y() * b.y());
}

struct Counters {
  long long steps = 0, merged = 0, angle = 0, crossing = 0, outside = 0, extra = 0, dropped = 0;
};

// The growing arrangement and what one chain needs.
struct Growth {
  const SeedGrowthExemplar& exemplar;
  const SeedGrowthOptions& options;
  GrowthGraph graph;
  MatchWeights weights;
  double l_short = 0.0, neighbourhood = 0.0;
  std::vector<int> symbol_priority;  // per symbol
  int lowest_priority = 0;
  std::vector<Vec3> origins;  // the initial seeds
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  Counters counters;
  long long elements = 0;
  // With exact overlaps: proxies per (shape, turn step), made when first needed.
  std::map<std::pair<int, long>, geometry::Proxy2> proxies;
  double largest_radius = 0.0;

  int priority(int node) const {
    const int s = graph.node(node).symbol;
    return s < 0 || symbol_priority.empty() ? lowest_priority
                                            : symbol_priority[static_cast<std::size_t>(s)];
  }
  void push_seed(int node) {
    double key = std::numeric_limits<double>::infinity();
    for (const Vec3& o : origins)
      key = std::min(key, graph.domain().minimum_image(graph.node(node).position - o).norm());
    queue.emplace(key, node);
  }
};

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
  options.tolerance = 0.002;  // as close to the drawn outlines as `stats` judges collisions
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
  if (g.options.exact_overlap) {
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
  const Vec3 want = turn(ref.offset[j], angle);
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

// With exact overlaps, the relaxation's moves must not make elements overlap.
MoveFilter move_filter(Growth& g) {
  if (!g.options.exact_overlap) return {};
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
    g.graph.set_desired(s, ring[i], turn(ref.offset[j], match.angle));
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

// The longest distance the graph is asked about: edges up to l_long, and with exact overlaps
// two bounding circles.
double graph_reach(const SeedGrowthExemplar& ex, const SeedGrowthOptions& o) {
  double reach = 1.6 * ex.longest_edge;
  if (o.exact_overlap)
    for (const double r : ex.shape_radius) reach = std::max(reach, 2.0 * r);
  return reach;
}

void check_options(const SeedGrowthOptions& o) {
  if (!(o.w1 >= 0 && o.w2 >= 0 && o.w3 >= 0 && std::isfinite(o.w1 + o.w2 + o.w3)))
    throw core::ArgumentError("--weights", "the weights must be finite and >= 0");
  if (o.relax_hops < 0 || o.relax_sweeps < 0 || o.final_sweeps < 0)
    throw core::ArgumentError("seed-and-grow", "relaxation counts must be >= 0");
}

}  // namespace

const char* to_string(RotationMode mode) {
  switch (mode) {
    case RotationMode::none:
      return "none";
    case RotationMode::best:
      return "best";
    case RotationMode::flow_field:
      return "flow-field";
  }
  return "none";
}

RotationMode parse_rotation_mode(const std::string& text) {
  if (text == "none") return RotationMode::none;
  if (text == "best") return RotationMode::best;
  if (text == "flow-field") return RotationMode::flow_field;
  throw core::ArgumentError("--rotation", "expected none, best or flow-field, got '" + text + "'");
}

SeedGrowthExemplar analyse_seed_growth_exemplar(const geometry::Scene& exemplar,
                                                geometry::Boundary boundary,
                                                const std::vector<EdgeFlip>& flips) {
  if (exemplar.dimension != 2)
    throw core::ArgumentError("seed-and-grow", "Ijiri's growth is for 2D exemplars");
  if (exemplar.elements.size() < 3)
    throw core::ArgumentError("seed-and-grow", "the exemplar needs at least 3 elements");
  SeedGrowthExemplar ex{
      exemplar, geometry::Domain(exemplar.window, 2, boundary), {}, {}, {}, {}, {}, 0.0, 0.0, {}};
  std::vector<Vec3> positions;
  for (const geometry::Element& e : exemplar.elements)
    positions.push_back(ex.domain.wrap(e.position));
  ex.connectivity = delaunay_connectivity(positions, ex.domain, flips);
  ex.symbol = classify_elements(exemplar).attribute;
  const int symbols = *std::max_element(ex.symbol.begin(), ex.symbol.end()) + 1;
  ex.by_symbol.resize(static_cast<std::size_t>(symbols));
  for (std::size_t e = 0; e < positions.size(); ++e) {
    const Ring& ring = ex.connectivity.rings[e];
    for (const Vec3& o : ring.offset) ex.longest_edge = std::max(ex.longest_edge, o.norm());
    if (!ring.closed) continue;
    ReferenceRing ref;
    ref.element = static_cast<int>(e);
    ref.symbol = ex.symbol[e];
    ref.offset = ring.offset;
    ref.neighbour = ring.neighbour;
    for (const int n : ring.neighbour)
      ref.neighbour_symbol.push_back(ex.symbol[static_cast<std::size_t>(n)]);
    const auto index = static_cast<int>(ex.references.size());
    ex.by_symbol[static_cast<std::size_t>(ref.symbol)].push_back(index);
    ex.all.push_back(index);
    ex.references.push_back(std::move(ref));
  }
  if (ex.references.empty())
    throw core::ArgumentError("seed-and-grow",
                              "no element of the exemplar is surrounded by others (every ring is "
                              "open): there is nothing to grow from");
  ex.density = static_cast<double>(positions.size()) / ex.domain.measure();
  for (const geometry::Shape& shape : exemplar.shapes)
    ex.shape_radius.push_back(0.5 * geometry::bounding_box(shape).sizes().norm());
  return ex;
}

SeedAndGrow::SeedAndGrow(const geometry::Scene& exemplar, geometry::Boundary exemplar_boundary,
                         geometry::Domain domain, SeedGrowthOptions options)
    : exemplar_(analyse_seed_growth_exemplar(exemplar, exemplar_boundary, options.flips)),
      domain_(std::move(domain)),
      options_(std::move(options)) {
  check_options(options_);
  if (domain_.dimension() != 2)
    throw core::ArgumentError("seed-and-grow", "Ijiri's growth makes 2D outputs");
  for (const Vec3& s : options_.seeds)
    if (!domain_.periodic() && !domain_.contains(s))
      throw core::ArgumentError("--seeds", "the seed (" + core::format_number(s.x()) + ", " +
                                               core::format_number(s.y()) +
                                               ") lies outside the output");
  if (!options_.priority.empty() && options_.priority.size() != exemplar_.scene.categories.size())
    throw core::ArgumentError("--priority", "expected one priority per exemplar category");
}

std::vector<std::pair<std::string, std::string>> SeedAndGrow::record_options() const {
  using core::format_number;
  const auto number = [](double v) { return format_number(v); };
  std::string priority = "none";
  if (!options_.priority.empty()) {
    priority.clear();
    for (std::size_t c = 0; c < options_.priority.size(); ++c)
      priority += (c ? "," : "") + exemplar_.scene.categories[c].name + "=" +
                  std::to_string(options_.priority[c]);
  }
  return {
      {"ijiri.rotation", to_string(options_.rotation)},
      {"ijiri.orientation_field", options_.field.describe()},
      {"ijiri.weights",
       number(options_.w1) + "," + number(options_.w2) + "," + number(options_.w3)},
      {"ijiri.relax", options_.relax ? "yes" : "no"},
      {"ijiri.edge_flips", std::to_string(options_.flips.size())},
      {"ijiri.seeds", options_.seeds.empty() ? "centre" : std::to_string(options_.seeds.size())},
      {"ijiri.priority", priority},
      {"ijiri.references", std::to_string(exemplar_.references.size())},
      {"ijiri.mean_edge", number(exemplar_.connectivity.mean_edge)}};
}

synthesis::SynthesisResult SeedAndGrow::synthesize(core::Random& random,
                                                   const synthesis::ChainControl& control) const {
  const double l = exemplar_.connectivity.mean_edge;
  Growth g{exemplar_,
           options_,
           GrowthGraph(domain_, graph_reach(exemplar_, options_)),
           {},
           0.5 * exemplar_.connectivity.shortest_edge,
           5.0 * l,
           {},
           0,
           {},
           {},
           {},
           0,
           {},
           0.0};
  g.weights = {options_.w1, options_.w2, options_.w3, l};
  for (const double r : exemplar_.shape_radius) g.largest_radius = std::max(g.largest_radius, r);
  g.neighbourhood = std::min(5.0 * l, 3.2 * exemplar_.longest_edge);
  if (!options_.priority.empty()) {
    g.symbol_priority.assign(exemplar_.by_symbol.size(), 0);
    for (std::size_t e = 0; e < exemplar_.symbol.size(); ++e)
      g.symbol_priority[static_cast<std::size_t>(exemplar_.symbol[e])] =
          options_.priority[static_cast<std::size_t>(exemplar_.scene.elements[e].category)];
    g.lowest_priority = *std::min_element(options_.priority.begin(), options_.priority.end());
  }
  g.origins = options_.seeds;
  if (g.origins.empty()) g.origins.push_back(domain_.box().center());
  for (const Vec3& o : g.origins) {
    GrowthNode seed;
    seed.position = o;
    g.push_seed(g.graph.add(seed));
  }
  const double expected = exemplar_.density * domain_.measure();
  const auto limit = static_cast<long long>(4.0 * expected) + 1000;
  synthesis::SynthesisResult result;
  bool first = true;
  for (int s = next_seed(g); s >= 0; s = next_seed(g)) {
    if (control.cancelled()) throw core::Cancelled();
    if (!grow(g, s, random)) continue;
    if (first) g.graph.node(s).fixed = true;
    first = false;
    if (++g.counters.steps % 256 == 0) {
      result.trace.push_back({g.counters.steps, static_cast<int>(g.elements), 0.0});
      if (control.progress) control.progress(g.elements, static_cast<long long>(expected));
    }
    if (g.elements > limit) break;
  }
  std::vector<int> all;
  for (std::size_t n = 0; n < g.graph.size(); ++n)
    if (g.graph.node(static_cast<int>(n)).alive) all.push_back(static_cast<int>(n));
  const double energy =
      options_.relax ? relax_rings(g.graph, all, options_.final_sweeps, move_filter(g)) : 0.0;
  result.trace.push_back({g.counters.steps, static_cast<int>(g.elements), energy});

  geometry::Scene& scene = result.scene;
  scene.dimension = 2;
  scene.window = domain_.box();
  scene.units = exemplar_.scene.units;
  scene.categories = exemplar_.scene.categories;
  scene.shapes = exemplar_.scene.shapes;
  for (const int n : all) {
    const GrowthNode& node = g.graph.node(n);
    if (node.seed()) continue;
    const geometry::Element& source =
        exemplar_.scene.elements[static_cast<std::size_t>(node.source)];
    if (node.angle == 0.0) {
      scene.elements.push_back({source.shape, source.category, node.position});
      continue;
    }
    Similarity placement;
    placement.linear = Eigen::AngleAxisd(node.angle, Vec3::UnitZ()).toRotationMatrix();
    placement.translation = node.position;
    geometry::add_element(
        scene, map_shape(exemplar_.scene.shapes[static_cast<std::size_t>(source.shape)], placement),
        source.category);
    scene.elements.back().position = domain_.wrap(scene.elements.back().position);
  }
  result.record.set_domain(domain_);
  result.record.options = record_options();
  result.record.iterations = std::to_string(g.counters.steps);
  result.record.steps = g.counters.steps;
  result.record.stationary = true;
  const auto count = [](long long v) { return std::to_string(v); };
  result.counters = {{"growth steps", count(g.counters.steps)},
                     {"seeds merged (l_short)", count(g.counters.merged)},
                     {"seeds dropped by the angle test", count(g.counters.angle)},
                     {"seeds dropped by edge crossings", count(g.counters.crossing)},
                     {"seeds outside the domain", count(g.counters.outside)},
                     {"extra seeds (l_long)", count(g.counters.extra)},
                     {options_.exact_overlap ? "seeds left without a match that fits"
                                             : "seeds left without a match",
                      count(g.counters.dropped)}};
  if (g.elements > limit)
    result.counters.emplace_back("stopped", "at " + count(limit) + " elements (4x the expected)");
  return result;
}

}  // namespace shapeproc::compare
