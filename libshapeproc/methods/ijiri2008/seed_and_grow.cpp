#include "libshapeproc/methods/ijiri2008/seed_and_grow.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"
#include "libshapeproc/methods/common/element_reconstruction.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/ijiri2008/detail/local_growth.hpp"

namespace shapeproc::methods {

namespace {

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
    throw core::ArgumentError("seed-and-grow", "weights: the weights must be finite and >= 0");
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
  throw core::ArgumentError("seed-and-grow",
                            "rotation: expected none, best or flow-field, got '" + text + "'");
}

SeedGrowthExemplar analyse_seed_growth_exemplar(const geometry::Scene& drawn,
                                                geometry::Boundary boundary,
                                                const std::vector<EdgeFlip>& flips) {
  if (drawn.dimension != 2)
    throw core::ArgumentError("seed-and-grow", "Ijiri's growth is for 2D exemplars");
  // A seamless tile of one or two elements is repeated 2 × 2, its periodic images made elements,
  // so that it can be triangulated (edge flips name the drawn elements, so they need 3).
  const bool small_tile =
      boundary == geometry::Boundary::torus && drawn.elements.size() < 3 && flips.empty();
  const geometry::Scene exemplar = small_tile ? geometry::repeat_tile(drawn, 2) : drawn;
  if (exemplar.elements.size() < 3)
    throw core::ArgumentError("seed-and-grow", "the exemplar needs at least 3 elements");
  SeedGrowthExemplar ex{
      exemplar, geometry::Domain(exemplar.window, 2, boundary), {}, {}, {}, {}, {}, 0.0, 0.0, {},
      {}};
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
  for (std::size_t e = 0; e < positions.size(); ++e) {
    double r = ex.shape_radius[static_cast<std::size_t>(exemplar.elements[e].shape)];
    for (const Vec3& o : ex.connectivity.rings[e].offset) r = std::min(r, 0.5 * o.norm());
    ex.circle_radius.push_back(r);
  }
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
      throw core::ArgumentError("seed-and-grow", "seeds: the seed (" + core::format_number(s.x()) +
                                                     ", " + core::format_number(s.y()) +
                                                     ") lies outside the output");
  if (!options_.priority.empty() && options_.priority.size() != exemplar_.scene.categories.size())
    throw core::ArgumentError("seed-and-grow",
                              "priority: expected one priority per exemplar category");
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
           0.0,
           0.0};
  g.weights = {options_.w1, options_.w2, options_.w3, l};
  for (const double r : exemplar_.shape_radius) g.largest_radius = std::max(g.largest_radius, r);
  for (const double r : exemplar_.circle_radius) g.largest_circle = std::max(g.largest_circle, r);
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
  result.counters = {
      {"growth steps", count(g.counters.steps)},
      {"seeds merged (l_short)", count(g.counters.merged)},
      {"seeds dropped by the angle test", count(g.counters.angle)},
      {"seeds dropped by edge crossings", count(g.counters.crossing)},
      {"seeds outside the domain", count(g.counters.outside)},
      {"extra seeds (l_long)", count(g.counters.extra)},
      {options_.exact_overlap || options_.circle_overlap ? "seeds left without a match that fits"
                                                         : "seeds left without a match",
       count(g.counters.dropped)}};
  if (g.elements > limit)
    result.counters.emplace_back("stopped", "at " + count(limit) + " elements (4x the expected)");
  return result;
}

}  // namespace shapeproc::methods
