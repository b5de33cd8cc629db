#include "libshapeproc/methods/ma2011/attribute_vote.hpp"

#include <algorithm>
#include <limits>
#include <map>

namespace shapeproc::methods {

std::vector<int> vote_attributes(const EmExemplar& exemplar, const OutputSamples& output,
                                 const SearchResult& search) {
  std::vector<int> chosen = output.source;
  const ElementSamples& samples = output.samples;
  for (std::size_t e = 0; e < output.elements(); ++e) {
    const int count = samples.count_of(static_cast<int>(e));
    std::map<int, int> ballots;  // exemplar element -> votes
    for (int s = samples.first[e]; s < samples.first[e + 1]; ++s) {
      for (const int v : search.votes[static_cast<std::size_t>(s)]) {
        const int element = exemplar.samples.element[static_cast<std::size_t>(v)];
        if (exemplar.samples.count_of(element) == count) ++ballots[element];
      }
    }
    if (ballots.empty()) continue;
    // eq. 5 over the distinct attribute codes of the votes.
    double best_sum = std::numeric_limits<double>::infinity();
    int best_attribute = -1;
    for (const auto& [candidate, unused] : ballots) {
      double sum = 0.0;
      for (const auto& [other, votes] : ballots)
        sum += votes * exemplar.attribute_distance(candidate, other);
      const int code = exemplar.attribute[static_cast<std::size_t>(candidate)];
      if (sum < best_sum || (sum == best_sum && code < best_attribute)) {
        best_sum = sum;
        best_attribute = code;
      }
    }
    // The most voted element with that attribute; the current source wins ties.
    int winner = -1, most = -1;
    for (const auto& [candidate, votes] : ballots) {
      if (exemplar.attribute[static_cast<std::size_t>(candidate)] != best_attribute) continue;
      const bool current = candidate == output.source[e];
      if (votes > most || (votes == most && current)) {
        winner = candidate;
        most = votes;
      }
    }
    chosen[e] = winner;
  }
  return chosen;
}

}  // namespace shapeproc::methods
