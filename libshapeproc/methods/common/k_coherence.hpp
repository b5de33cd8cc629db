// k-coherence search for irregular samples (Ma et al. 2011, §4.2, after Tong et al. 2002 and
// Han et al. 2006). Once per exemplar, every exemplar sample gets a similarity set: the k samples
// of its key whose neighbourhoods are nearest to its own by eq. 1 (itself first). At run time the
// candidates of an output sample are the similarity sets of the exemplar samples its neighbours'
// matches pair it with (the offsets come from the recorded pairs), and of its own match.
#pragma once

#include <vector>

#include "libshapeproc/methods/common/em_exemplar.hpp"

namespace shapeproc::methods {

struct SimilaritySets {
  int k = 0;
  std::vector<std::vector<int>> sets;  // per exemplar sample, nearest first
};

// The similarity sets by brute force over each key's samples, with attribute weight `alpha`.
SimilaritySets build_similarity_sets(const EmExemplar& exemplar, int k, double alpha);

// Collects into `out` (cleared) the candidates of an output sample whose own match is `match`
// (-1: none) and whose neighbours' pairings matched it to `votes`: the union of their similarity
// sets, each once. `seen` is scratch of the exemplar's sample count, all false on entry and on
// return.
void gather_candidates(const SimilaritySets& sets, int match, const std::vector<int>& votes,
                       std::vector<char>& seen, std::vector<int>& out);

}  // namespace shapeproc::methods
