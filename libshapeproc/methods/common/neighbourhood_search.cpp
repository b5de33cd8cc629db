#include "libshapeproc/methods/common/neighbourhood_search.hpp"

#include <cmath>
#include <limits>

#include "libshapeproc/geometry/element_neighbourhood.hpp"

namespace shapeproc::methods {

double inside(const geometry::Domain& domain, const Vec3& x) {
  if (domain.periodic()) return 1.0;
  if (!domain.contains(x)) return 0.0;
  if (const geometry::Raster* mask = domain.mask())
    return static_cast<double>(mask->sample(domain.box(), geometry::Vec2(x.x(), x.y())));
  return 1.0;
}

namespace {

// λ c(so, si) of eq. 6.
double domain_term(const EmExemplar& exemplar, const geometry::Domain& domain,
                   const SearchSettings& settings, const Vec3& centre, int candidate) {
  if (settings.lambda <= 0.0 || domain.periodic()) return 0.0;
  double sum = 0.0;
  for (const geometry::Neighbour& n : exemplar.near[static_cast<std::size_t>(candidate)]) {
    const Vec3 offset =
        settings.orientation ? settings.orientation->turn(n.offset, centre) : n.offset;
    const double miss = 1.0 - inside(domain, centre + offset);
    sum += miss * miss;
  }
  return settings.lambda * sum;
}

}  // namespace

SearchResult search(const EmExemplar& exemplar, const OutputSamples& output,
                    const geometry::Domain& domain, const SearchSettings& settings,
                    const SearchResult& previous) {
  const ElementSamples& samples = output.samples;
  const std::size_t n = samples.size();
  const double r = exemplar.radius;
  std::vector<Vec3> positions = samples.positions;
  for (Vec3& p : positions) p = domain.wrap(p);
  const geometry::NeighbourhoodIndex index(positions, samples.key, output.attribute, domain, r);

  SearchResult result;
  result.match.assign(n, -1);
  result.cost.assign(n, 0.0);
  result.votes.assign(n, {});
  if (previous.votes.size() == n)
    for (std::size_t s = 0; s < n; ++s) result.votes[s].reserve(previous.votes[s].size() + 4);
  result.predictions.reserve(previous.predictions.size() + n);  // about as many as the last
  std::vector<char> seen(exemplar.samples.size(), 0);
  std::vector<int> candidates;
  std::vector<std::pair<int, int>> trial, pairs;  // a candidate's pairing, the best one's
  for (std::size_t c = 0; c < n; ++c) {
    geometry::Neighbourhood hood = index.of(c);
    if (settings.orientation && !settings.orientation->empty()) {
      for (geometry::Neighbour& nb : hood)
        nb.offset = settings.orientation->turn(nb.offset, positions[c], true);
    }
    const int before = previous.match.empty() ? -1 : previous.match[c];
    switch (settings.rule) {
      case SearchRule::brute_force:
        candidates = exemplar.samples_with_key(samples.key[c]);
        break;
      case SearchRule::fixed:
        candidates.assign(1, before);
        break;
      case SearchRule::k_coherence:
        gather_candidates(*settings.sets, before,
                          previous.votes.empty() ? std::vector<int>{} : previous.votes[c], seen,
                          candidates);
        if (candidates.empty()) candidates = exemplar.samples_with_key(samples.key[c]);
        break;
    }
    double best = std::numeric_limits<double>::infinity();
    int chosen = -1;
    pairs.clear();
    for (const int m : candidates) {
      if (m < 0) continue;
      const double attribute =
          output.attribute[c] != exemplar.sample_attribute[static_cast<std::size_t>(m)]
              ? settings.alpha
              : 0.0;
      // Candidates that cannot beat the best so far stop at a lower bound (ties still compare).
      const double extra = attribute + domain_term(exemplar, domain, settings, positions[c], m);
      if (extra > best) continue;
      const double cost =
          extra + geometry::neighbourhood_distance(
                      hood, exemplar.wide[static_cast<std::size_t>(m)], r, settings.alpha,
                      std::nextafter(best - extra, std::numeric_limits<double>::infinity()),
                      &trial);
      if (cost < best || (cost == best && m < chosen)) {
        best = cost;
        chosen = m;
        std::swap(pairs, trial);
      }
    }
    result.match[c] = chosen;
    result.cost[c] = best;
    result.energy += best;
    if (chosen < 0) continue;
    // The pairing's predictions and votes.
    const geometry::PairingNeighbourhood& partner = exemplar.wide[static_cast<std::size_t>(chosen)];
    result.votes[c].push_back(chosen);
    for (const auto& [a, b] : pairs) {
      const geometry::Neighbour& o = hood[static_cast<std::size_t>(a)];
      const geometry::Neighbour& e = partner[static_cast<std::size_t>(b)];
      const Vec3 offset =
          settings.orientation ? settings.orientation->turn(e.offset, positions[c]) : e.offset;
      result.predictions.push_back({static_cast<int>(c), o.element, offset});
      result.votes[static_cast<std::size_t>(o.element)].push_back(e.element);
    }
  }
  return result;
}

}  // namespace shapeproc::methods
