#include "libshapeproc/methods/davison2018/region_growing.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/geometry/element_neighbourhood.hpp"
#include "libshapeproc/methods/common/element_reconstruction.hpp"
#include "libshapeproc/methods/common/position_assignment.hpp"
#include "libshapeproc/methods/davison2018/density_calibration.hpp"

namespace shapeproc::methods {

namespace {

constexpr int kAttempts = 2;

// Per palette exemplar: the pairing threshold of generation, twice its mean bounding radius,
// and the most elements a copy's neighbourhood may hold (density_calibration.hpp; infinite: no
// limit).
struct Settings {
  std::vector<double> threshold;
  std::vector<double> most_neighbours;
};

// The growing output, its horizon and what one chain needs.
struct Growth {
  const GrowthExemplar& exemplar;
  const geometry::Domain& domain;
  const GrowthOptions& options;
  Settings settings;
  GrowthState state;
  std::vector<int> horizon;
  std::vector<char> in_horizon;
  std::vector<int> attempts;  // per element: rounds it was abandoned as a seed
  std::vector<char> seen;     // gather_candidates' scratch, one per exemplar element
  long long abandoned = 0, rounds = 0;
  std::vector<Vec3> origin;  // per element: where the exemplar patch it was copied in began
  long long patches = 0;     // patches begun (initial ones included)
  // Per element: whether an element arrived within the largest neighbourhood radius of it since
  // the last optimisation (its neighbourhood grew).
  std::vector<char> grown;
  double reach = 0.0;  // the largest neighbourhood radius
};

// Adds an element copied in the patch begun at `origin`.
int add_element(Growth& g, int source, const Vec3& p, const Vec3& origin) {
  const int e = g.state.add(source, p);
  if (static_cast<std::size_t>(e) >= g.origin.size())
    g.origin.resize(static_cast<std::size_t>(e) + 1, Vec3::Zero());
  g.origin[static_cast<std::size_t>(e)] = origin;
  return e;
}

// The measure of a ball of palette exemplar `part`'s neighbourhood radius (its first element's).
double neighbourhood_measure(const GrowthExemplar& exemplar, std::size_t part, int dimension) {
  double r = 0.0;
  for (std::size_t s = 0; s < exemplar.part.size(); ++s)
    if (static_cast<std::size_t>(exemplar.part[s]) == part) {
      r = exemplar.reach[s];
      break;
    }
  return geometry::ball_measure(r, dimension);
}

// The candidates of element e: co(source) ∪ co(match), each once (k-coherence's gathering).
std::vector<int> candidates_of(Growth& g, int e) {
  std::vector<int> out;
  gather_candidates(g.exemplar.sets, g.state.source(e), {g.state.match(e)}, g.seen, out);
  return out;
}

// Whether seed s's patch reaches beyond the patch radius (GrowthOptions::patch_radius).
bool patch_full(const Growth& g, int s) {
  if (!(g.options.patch_radius > 0)) return false;
  const Vec3 from =
      g.domain.minimum_image(g.state.position(s) - g.origin[static_cast<std::size_t>(s)]);
  return from.norm() > g.options.patch_radius * g.exemplar.reach_of(g.state.source(s));
}

// Seed s's candidates: k-coherence's; once its patch is full, every exemplar sample of its key
// but the images of its own (k-coherence's sets of a seamless tile hold mostly those).
std::vector<int> generation_candidates(Growth& g, int s) {
  if (!patch_full(g, s)) return candidates_of(g, s);
  const EmExemplar& em = g.exemplar.em;
  const int own = g.state.source(s);
  std::vector<int> out;
  for (const int m : em.samples_with_key(em.samples.key[static_cast<std::size_t>(own)]))
    if (!em.same_place(m, own)) out.push_back(m);
  return out;
}

// Eq. 1 between element e's neighbourhood and exemplar element m's; a neighbourhood shown to be
// at least `bound` away returns a lower bound (see neighbourhood_distance).
double distance_to(const Growth& g, int e, const geometry::Neighbourhood& hood, int m,
                   std::vector<std::pair<int, int>>* pairs = nullptr,
                   double bound = std::numeric_limits<double>::infinity()) {
  const EmExemplar& em = g.exemplar.em;
  const double alpha = g.options.alpha * g.exemplar.spacing_of(m) * g.exemplar.spacing_of(m);
  const double centre = em.sample_attribute[static_cast<std::size_t>(g.state.source(e))] !=
                                em.sample_attribute[static_cast<std::size_t>(m)]
                            ? alpha
                            : 0.0;
  return centre + geometry::neighbourhood_distance(hood, em.wide[static_cast<std::size_t>(m)],
                                                   g.exemplar.reach_of(m), alpha, bound, pairs);
}

// Marks the elements whose neighbourhood element e's arrival changed (e itself included).
void mark_grown_near(Growth& g, int e) {
  g.grown.resize(g.state.size(), 0);
  g.grown[static_cast<std::size_t>(e)] = 1;
  for (const int o : g.state.elements_within(g.state.position(e), g.reach))
    g.grown[static_cast<std::size_t>(o)] = 1;
}

bool grown_near(const Growth& g, int e) {
  return static_cast<std::size_t>(e) >= g.grown.size() || g.grown[static_cast<std::size_t>(e)];
}

void push_horizon(Growth& g, int e) {
  if (static_cast<std::size_t>(e) >= g.in_horizon.size()) {
    g.in_horizon.resize(static_cast<std::size_t>(e) + 1, 0);
    g.attempts.resize(static_cast<std::size_t>(e) + 1, 0);
  }
  if (g.in_horizon[static_cast<std::size_t>(e)]) return;
  g.in_horizon[static_cast<std::size_t>(e)] = 1;
  g.horizon.push_back(e);
}

// Step 0: exemplar `part`'s most surrounded element and its neighbours, at `centre`.
void place_initial_patch(Growth& g, core::Random& random, int part, const Vec3& centre) {
  const EmExemplar& em = g.exemplar.em;
  std::vector<int> best;
  std::size_t most = 0;
  for (std::size_t s = 0; s < em.near.size(); ++s) {
    if (g.exemplar.part[s] != part) continue;
    if (em.near[s].size() > most) best.clear();
    if (em.near[s].size() >= most) {
      most = em.near[s].size();
      best.push_back(static_cast<int>(s));
    }
  }
  const int c = best[random.index(best.size())];
  if (!g.state.in_domain(centre) || g.state.collides(c, centre)) return;
  push_horizon(g, add_element(g, c, centre, centre));
  ++g.patches;
  for (const geometry::Neighbour& n : em.near[static_cast<std::size_t>(c)]) {
    const Vec3 p = centre + n.offset;
    if (g.state.in_domain(p) && !g.state.collides(n.element, p))
      push_horizon(g, add_element(g, n.element, p, centre));
  }
}

// Step 1: the elements that can still make something.
void prune_horizon(Growth& g) {
  std::vector<int> kept;
  for (const int h : g.horizon) {
    if (g.state.free_point_within(g.state.position(h), g.exemplar.reach_of(g.state.source(h))))
      kept.push_back(h);
    else
      g.in_horizon[static_cast<std::size_t>(h)] = 0;
  }
  g.horizon = std::move(kept);
}

// Step 2: seeds apart from each other.
std::vector<int> select_seeds(const Growth& g, core::Random& random) {
  std::vector<int> order = g.horizon;
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[random.index(i)]);
  const auto reach = [&](int e) { return g.exemplar.reach_of(g.state.source(e)); };
  std::vector<int> seeds;
  std::vector<char> seed(g.state.size(), 0);
  const double apart = g.options.seed_separation *
                       *std::max_element(g.exemplar.reach.begin(), g.exemplar.reach.end());
  for (const int h : order) {
    // Separations are at most the largest neighbourhood radius: the seeds to check are near.
    bool free = true;
    for (const int s : g.state.elements_within(g.state.position(h), apart)) {
      if (!seed[static_cast<std::size_t>(s)]) continue;
      free = free && g.domain.minimum_image(g.state.position(s) - g.state.position(h)).norm() >=
                         g.options.seed_separation * std::max(reach(s), reach(h));
    }
    if (!free) continue;
    seeds.push_back(h);
    seed[static_cast<std::size_t>(h)] = 1;
  }
  return seeds;
}

// Whether a copy of exemplar element `element` at p, made for candidate m after `before` copies,
// would break the density calibration's limit: its neighbourhood, with it and the copies before
// it, may hold at most `most`; its elements are counted only until they break it.
bool crowded(const Growth& g, int m, int element, const Vec3& p, std::size_t before) {
  const std::size_t part = static_cast<std::size_t>(g.exemplar.part[static_cast<std::size_t>(m)]);
  const double most = g.settings.most_neighbours[part];
  if (!std::isfinite(most)) return false;
  const double room = most - static_cast<double>(before) - 1.0;
  const std::size_t breaking = room < 0.0 ? 0 : static_cast<std::size_t>(std::floor(room)) + 1;
  return g.state.count_within(p, g.exemplar.reach_of(element), breaking) >= breaking;
}

// The copies candidate m would make around seed s: its right-partial pairs on free space.
std::vector<std::pair<int, Vec3>> copies_of(const Growth& g, int s,
                                            const geometry::Neighbourhood& hood, int m) {
  const geometry::Neighbourhood& near = g.exemplar.em.near[static_cast<std::size_t>(m)];
  std::vector<char> paired(near.size(), 0);
  const double threshold =
      g.settings.threshold[static_cast<std::size_t>(g.exemplar.part[static_cast<std::size_t>(m)])];
  for (const auto& [a, b] : geometry::match_neighbourhoods(hood, near, threshold))
    paired[static_cast<std::size_t>(b)] = 1;
  std::vector<std::pair<int, Vec3>> out;
  for (std::size_t i = 0; i < near.size(); ++i) {
    if (paired[i]) continue;
    const Vec3 p = g.domain.wrap(g.state.position(s) + near[i].offset);
    const double r = g.exemplar.radius[static_cast<std::size_t>(near[i].element)];
    // The limit first: inside a grown region it is what refuses nearly every copy.
    if (!g.state.in_domain(p) || crowded(g, m, near[i].element, p, out.size()) ||
        !g.state.on_free_point(p, r) || g.state.collides(near[i].element, p))
      continue;
    bool clash = false;  // with the copies before it (bounding circles)
    for (const auto& [e, q] : out) {
      if (g.exemplar.exact) break;  // one exemplar neighbourhood's shapes do not overlap
      const double reach = r + g.exemplar.radius[static_cast<std::size_t>(e)];
      clash = clash || g.domain.minimum_image(q - p).squaredNorm() < reach * reach;
    }
    if (!clash) out.emplace_back(near[i].element, p);
  }
  return out;
}

// Step 3: one seed's generation. Returns how many elements it added.
int generate(Growth& g, int s) {
  const geometry::Neighbourhood hood = g.state.neighbourhood(s);
  // Copies first, until a candidate has some: a seed none of whose candidates can copy anything
  // makes nothing whichever ranks first, and most seeds inside a grown region are such (the
  // density's limit); copies cost less than the ranking's distances.
  const std::vector<int> candidates = generation_candidates(g, s);
  std::vector<std::optional<std::vector<std::pair<int, Vec3>>>> copies(candidates.size());
  bool any = false;
  for (std::size_t i = 0; i < candidates.size() && !any; ++i) {
    copies[i] = copies_of(g, s, hood, candidates[i]);
    any = !copies[i]->empty();
  }
  if (!any) return 0;
  // A candidate is a bad suggestion beyond c times the best distance; that distance is 0 where
  // the seed's neighbourhood is an exact copy, so (tolerance d̄)² per neighbour is added. The
  // limit only falls as candidates come, so each is measured only as far as it.
  const double spacing = g.exemplar.spacing_of(g.state.source(s));
  const double slack = static_cast<double>(std::max<std::size_t>(hood.size(), 1)) *
                       g.options.tolerance * g.options.tolerance * spacing * spacing;
  double limit = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, int>> ranked;
  for (const int m : candidates) {
    const double cost = distance_to(g, s, hood, m, nullptr, limit);
    ranked.emplace_back(cost, m);
    limit = std::min(limit, g.options.ratio * cost + slack);
  }
  std::sort(ranked.begin(), ranked.end());
  for (const auto& [cost, m] : ranked) {
    if (cost > limit) break;
    const auto i = static_cast<std::size_t>(std::find(candidates.begin(), candidates.end(), m) -
                                            candidates.begin());
    if (!copies[i]) copies[i] = copies_of(g, s, hood, m);
    if (copies[i]->empty()) continue;
    g.state.set_match(s, m);
    // Its own element continues its patch; any other begins one here.
    const bool continues = g.exemplar.em.same_place(m, g.state.source(s));
    const Vec3 origin = continues ? g.origin[static_cast<std::size_t>(s)] : g.state.position(s);
    if (!continues) ++g.patches;
    for (const auto& [e, p] : *copies[i]) {
      const int added = add_element(g, e, p, origin);
      push_horizon(g, added);
      mark_grown_near(g, added);
    }
    return static_cast<int>(copies[i]->size());
  }
  return 0;
}

// Davison's eq. 4: each prediction of one neighbourhood weighted by a Gaussian of its predicted
// move, fitted to all the neighbourhood's predicted moves.
void gaussian_weights(std::vector<Prediction>& predictions, const std::vector<Vec3>& moves,
                      double scale2) {
  if (moves.size() < 2) return;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& d : moves) mean += d;
  mean /= static_cast<double>(moves.size());
  Eigen::Matrix3d c = 1e-4 * scale2 * Eigen::Matrix3d::Identity();
  for (const Vec3& d : moves) c += (d - mean) * (d - mean).transpose() / double(moves.size());
  const Eigen::Matrix3d inverse = c.inverse();
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const Vec3 d = moves[i] - mean;
    predictions[predictions.size() - moves.size() + i].weight *=
        std::exp(-0.5 * d.dot(inverse * d));
  }
}

// Step 4: least squares over the horizon and the elements near it.
double optimise(Growth& g) {
  std::vector<int> local(g.state.size(), -1);
  std::vector<int> unknowns;
  std::vector<double> anchors;
  const auto enter = [&](int e, double anchor) {
    int& slot = local[static_cast<std::size_t>(e)];
    if (slot < 0) {
      slot = static_cast<int>(unknowns.size());
      unknowns.push_back(e);
      anchors.push_back(anchor);
    } else {
      anchors[static_cast<std::size_t>(slot)] =
          std::min(anchors[static_cast<std::size_t>(slot)], anchor);
    }
  };
  // Only where the output grew since the last optimisation: elsewhere the horizon already sits
  // where its last solve put it.
  std::vector<int> grown;
  for (const int h : g.horizon)
    if (grown_near(g, h)) grown.push_back(h);
  for (const int h : grown) enter(h, 0.0);
  for (const int h : grown)
    for (const int o :
         g.state.elements_within(g.state.position(h), g.exemplar.reach_of(g.state.source(h))))
      enter(o, g.options.anchor_weight);
  const std::size_t movable = unknowns.size();
  std::vector<Prediction> predictions;
  double energy = 0.0;
  std::vector<std::pair<int, int>> pairs, best_pairs;
  for (std::size_t u = 0; u < movable; ++u) {
    const int e = unknowns[u];
    const geometry::Neighbourhood hood = g.state.neighbourhood(e);
    double best = std::numeric_limits<double>::infinity();
    int chosen = g.state.match(e);
    // Horizon elements whose neighbourhood grew search their candidates; the others keep their
    // match.
    const bool search = g.in_horizon[static_cast<std::size_t>(e)] && grown_near(g, e);
    const std::vector<int> candidates =
        search ? candidates_of(g, e) : std::vector<int>{g.state.match(e)};
    for (const int m : candidates) {
      const double cost = distance_to(
          g, e, hood, m, &pairs, std::nextafter(best, std::numeric_limits<double>::infinity()));
      if (cost < best) {
        best = cost;
        chosen = m;
        std::swap(pairs, best_pairs);
      }
    }
    energy += best;
    g.state.set_match(e, chosen);
    const geometry::PairingNeighbourhood& partner =
        g.exemplar.em.wide[static_cast<std::size_t>(chosen)];
    std::vector<Vec3> moves;
    for (const auto& [a, b] : best_pairs) {
      const geometry::Neighbour& o = hood[static_cast<std::size_t>(a)];
      const Vec3& offset = partner[static_cast<std::size_t>(b)].offset;
      enter(o.element, 1e6);  // a neighbour beyond: it holds its place
      const bool frozen = !g.in_horizon[static_cast<std::size_t>(o.element)];
      predictions.push_back({static_cast<int>(u), local[static_cast<std::size_t>(o.element)],
                             offset, frozen ? g.options.frozen_weight : 1.0});
      moves.push_back(offset - o.offset);
    }
    const double spacing = g.exemplar.spacing_of(g.state.source(e));
    gaussian_weights(predictions, moves, spacing * spacing);
  }
  std::fill(g.grown.begin(), g.grown.end(), 0);
  std::vector<Vec3> positions;
  for (const int e : unknowns) positions.push_back(g.state.position(e));
  const std::vector<Vec3> d = solve_positions(positions, predictions, g.domain, anchors);
  for (std::size_t u = 0; u < movable; ++u) {
    // Moves below a thousandth of the spacing are not worth making; a move out of the domain or
    // onto another element is not taken.
    const int e = unknowns[u];
    if (d[u].norm() <= 1e-3 * g.exemplar.spacing_of(g.state.source(e))) continue;
    const Vec3 to = positions[u] + d[u];
    if (g.state.in_domain(to) && !g.state.collides(g.state.source(e), to, e)) g.state.move(e, to);
  }
  return energy;
}

}  // namespace

RegionGrowing::RegionGrowing(const geometry::Scene& exemplar, geometry::Boundary exemplar_boundary,
                             geometry::Domain domain, GrowthOptions options)
    : RegionGrowing(std::vector<GrowthSource>{{exemplar, exemplar_boundary}}, std::move(domain),
                    options) {}

RegionGrowing::RegionGrowing(const std::vector<GrowthSource>& palette, geometry::Domain domain,
                             GrowthOptions options)
    : exemplar_(analyse_growth_palette(palette, options, domain.dimension())),
      domain_(std::move(domain)),
      options_(options) {}

std::vector<std::pair<std::string, std::string>> RegionGrowing::record_options() const {
  const auto number = [](double v) { return core::format_number(v); };
  // Per palette exemplar: its neighbourhood radius, the first sample of each part giving it.
  std::string radii;
  for (std::size_t s = 0, part = 0; s < exemplar_.part.size(); ++s) {
    if (static_cast<std::size_t>(exemplar_.part[s]) != part) continue;
    radii += (part++ ? "," : "") + number(exemplar_.reach[s]);
  }
  return {{"growth.palette", std::to_string(exemplar_.parts())},
          {"growth.neighbourhood_rings", number(options_.rings)},
          {"growth.radius", radii},
          {"growth.k", std::to_string(options_.k)},
          {"growth.alpha", number(options_.alpha)},
          {"growth.ratio", number(options_.ratio)},
          {"growth.bounding_radius",
           options_.bounding_radius > 0 ? number(options_.bounding_radius) : "auto"},
          {"growth.optimise", options_.optimise ? "yes" : "no"},
          {"growth.patch_radius", number(options_.patch_radius)},
          {"growth.overlap", exemplar_.exact ? "shapes" : "circles"}};
}

namespace {

// Algorithm 1 over `domain` until the horizon is empty: the grown output, its trace appended to
// `trace` (may be null).
Growth grow(const GrowthExemplar& exemplar, const geometry::Domain& domain,
            const GrowthOptions& options, double crowding, core::Random& random,
            const synthesis::ChainControl& control, std::vector<synthesis::TracePoint>* trace) {
  Growth g{exemplar,
           domain,
           options,
           {},
           GrowthState(exemplar, domain),
           {},
           {},
           {},
           std::vector<char>(exemplar.em.samples.size(), 0),
           0,
           0,
           {},
           0,
           {},
           *std::max_element(exemplar.reach.begin(), exemplar.reach.end())};
  const std::size_t parts = exemplar.parts();
  std::vector<double> sum(parts, 0.0), count(parts, 0.0);
  for (std::size_t s = 0; s < exemplar.radius.size(); ++s) {
    sum[static_cast<std::size_t>(exemplar.part[s])] += exemplar.radius[s];
    count[static_cast<std::size_t>(exemplar.part[s])] += 1.0;
  }
  double expected = 0.0;
  for (std::size_t p = 0; p < parts; ++p) {
    g.settings.threshold.push_back(2.0 * sum[p] / count[p]);
    g.settings.most_neighbours.push_back(crowding * exemplar.part_density[p] *
                                         neighbourhood_measure(exemplar, p, domain.dimension()));
    expected += exemplar.part_density[p] * domain.measure() / static_cast<double>(parts);
  }
  // One initial patch per palette exemplar, spread along the domain's longest axis.
  const geometry::Box3& box = domain.box();
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  for (std::size_t p = 0; p < parts; ++p) {
    Vec3 centre = box.center();
    centre[axis] = box.min()[axis] +
                   (static_cast<double>(p) + 0.5) / static_cast<double>(parts) * box.sizes()[axis];
    place_initial_patch(g, random, static_cast<int>(p), centre);
  }
  for (;;) {
    if (control.cancelled()) throw core::Cancelled();
    prune_horizon(g);
    if (g.horizon.empty()) break;
    int made = 0;
    const std::vector<int> seeds = select_seeds(g, random);
    for (const int s : seeds) {
      const int n = generate(g, s);
      made += n;
      if (n > 0) continue;
      // An abandoned seed leaves the horizon after kAttempts tries (its free space stays for
      // the others); when a whole round makes nothing, all its seeds leave.
      ++g.abandoned;
      if (++g.attempts[static_cast<std::size_t>(s)] >= kAttempts)
        g.in_horizon[static_cast<std::size_t>(s)] = 0;
    }
    if (made == 0)
      for (const int s : seeds) g.in_horizon[static_cast<std::size_t>(s)] = 0;
    g.horizon.erase(
        std::remove_if(g.horizon.begin(), g.horizon.end(),
                       [&](int h) { return !g.in_horizon[static_cast<std::size_t>(h)]; }),
        g.horizon.end());
    ++g.rounds;
    const double energy = options.optimise && made > 0 ? optimise(g) : 0.0;
    if (trace) trace->push_back({g.rounds, static_cast<int>(g.state.size()), energy});
    if (control.progress)
      control.progress(static_cast<long long>(g.state.size()), static_cast<long long>(expected));
  }
  return g;
}

}  // namespace

synthesis::SynthesisResult RegionGrowing::synthesize(core::Random& random,
                                                     const synthesis::ChainControl& control) const {
  // The neighbourhoods' limit, from pilot growths on small tori (density_calibration.hpp).
  synthesis::ChainControl quiet;
  quiet.cancel = control.cancel;
  const DensityCalibration calibration = calibrate_density(
      exemplar_, options_, domain_, random,
      [&](double crowding, const geometry::Domain& where, core::Random& r) {
        return grow(exemplar_, where, options_, crowding, r, quiet, nullptr).state.size();
      });
  synthesis::SynthesisResult result;
  const Growth g =
      grow(exemplar_, domain_, options_, calibration.crowding, random, control, &result.trace);

  OutputSamples output;
  for (std::size_t e = 0; e < g.state.size(); ++e)
    output.add(exemplar_.em, g.state.source(static_cast<int>(e)),
               g.state.position(static_cast<int>(e)));
  result.scene =
      reconstruct(exemplar_.em, output, domain_, OrientationField{}, Reconstruction::rigid);
  result.record.set_domain(domain_);
  result.record.options = record_options();
  result.record.options.emplace_back(
      "growth.crowding",
      std::isfinite(calibration.crowding) ? core::format_number(calibration.crowding) : "none");
  result.record.iterations = std::to_string(g.rounds);
  result.record.steps = g.rounds;
  result.record.stationary = true;
  result.counters = {{"rounds", std::to_string(g.rounds)},
                     {"seeds abandoned", std::to_string(g.abandoned)},
                     {"patches", std::to_string(g.patches)},
                     {"free-space points left", std::to_string(g.state.free_points())},
                     {"neighbourhood limit", calibration.summary()}};
  return result;
}

}  // namespace shapeproc::methods
