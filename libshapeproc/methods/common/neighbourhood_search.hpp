// The search step of the neighbourhood EM (Ma et al. 2011, §4.2 and §5): for every output sample
// so, the exemplar sample si of its key whose neighbourhood is most similar,
//     argmin_si |n(so) − n(si)|² + λ c(so, si),
// eq. 1 plus the domain-shape term of eq. 6: c(so, si) = Σ_{s'i ∈ n(si)} (1 − c(x))², c the
// output domain's inside function (1 inside the box and the mask, 0 outside; always 1 on a
// torus) read at the exemplar neighbours shifted to so, x = p(so) + o(so)(p(s'i) − p(si)).
// Offsets are compared in the orientation field's local frame (eq. 7).
//
// Besides the matches it records what the assignment step needs: from each centre's greedy
// pairing, the predicted offset of every paired neighbour (eq. 3) and the exemplar sample each
// output sample was paired with (its votes, eq. 5, and its k-coherence sources).
#pragma once

#include <vector>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/k_coherence.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"
#include "libshapeproc/methods/common/output_samples.hpp"

namespace shapeproc::methods {

enum class SearchRule {
  k_coherence,  // candidates from the similarity sets (the default)
  brute_force,  // every exemplar sample of the key
  fixed,        // only the previous match: the energy of the current matches
};

struct SearchSettings {
  SearchRule rule = SearchRule::k_coherence;
  double alpha = 0.0;   // attribute weight of eq. 1, in squared length units
  double lambda = 0.0;  // weight of the domain term (eq. 6), in squared length units
  const SimilaritySets* sets = nullptr;           // for k_coherence
  const OrientationField* orientation = nullptr;  // may be null
};

// p(neighbour) − p(centre) ≈ offset, one term of eq. 4.
struct Prediction {
  int centre = 0, neighbour = 0;
  Vec3 offset = Vec3::Zero();
  double weight = 1.0;  // its weight in E_p (Davison et al.'s eq. 4; Ma et al.: 1)
};

struct SearchResult {
  std::vector<int> match;    // per output sample: its exemplar sample
  std::vector<double> cost;  // per output sample: its term of eq. 2
  double energy = 0.0;       // eq. 2: the sum of the costs
  std::vector<Prediction> predictions;
  std::vector<std::vector<int>> votes;  // per output sample: the exemplar samples paired with it
};

// The inside function c of eq. 6 at `x`.
double inside(const geometry::Domain& domain, const Vec3& x);

// One search over every output sample. `previous` holds the last search's matches and votes
// (k_coherence, fixed; for the first search: each sample's copy source as its match).
SearchResult search(const EmExemplar& exemplar, const OutputSamples& output,
                    const geometry::Domain& domain, const SearchSettings& settings,
                    const SearchResult& previous);

}  // namespace shapeproc::methods
