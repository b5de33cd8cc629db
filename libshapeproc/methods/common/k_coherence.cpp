#include "libshapeproc/methods/common/k_coherence.hpp"

#include <algorithm>
#include <utility>

namespace shapeproc::methods {

SimilaritySets build_similarity_sets(const EmExemplar& exemplar, int k, double alpha) {
  SimilaritySets out;
  out.k = k;
  out.sets.resize(exemplar.samples.size());
  std::vector<std::pair<double, int>> ranked;
  for (std::size_t a = 0; a < exemplar.samples.size(); ++a) {
    ranked.clear();
    for (const int b : exemplar.samples_with_key(exemplar.samples.key[a])) {
      const double d = static_cast<std::size_t>(b) == a
                           ? -1.0  // itself first, whatever ties
                           : geometry::neighbourhood_distance(
                                 exemplar.near[a], exemplar.wide[static_cast<std::size_t>(b)],
                                 exemplar.radius, alpha);
      ranked.emplace_back(d, b);
    }
    const std::size_t keep = std::min<std::size_t>(ranked.size(), static_cast<std::size_t>(k));
    std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(keep),
                      ranked.end());
    for (std::size_t i = 0; i < keep; ++i) out.sets[a].push_back(ranked[i].second);
  }
  return out;
}

void gather_candidates(const SimilaritySets& sets, int match, const std::vector<int>& votes,
                       std::vector<char>& seen, std::vector<int>& out) {
  out.clear();
  auto add_set = [&](int sample) {
    if (sample < 0) return;
    for (const int c : sets.sets[static_cast<std::size_t>(sample)]) {
      if (seen[static_cast<std::size_t>(c)]) continue;
      seen[static_cast<std::size_t>(c)] = 1;
      out.push_back(c);
    }
  };
  add_set(match);
  for (const int v : votes) add_set(v);
  for (const int c : out) seen[static_cast<std::size_t>(c)] = 0;
}

}  // namespace shapeproc::methods
