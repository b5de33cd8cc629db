// Discrete element textures by region growing (Davison et al. 2018), the second comparison
// method: from a central patch of the exemplar, seeds on the growing front copy the exemplar
// elements their best-matching neighbourhoods have and they lack, onto free-space points
// (free_space.hpp), and the front is then relaxed by weighted least squares (Algorithm 1).
//
// Each round:
// 1. prune the horizon (the front): an element stays while a free-space point lies within its
//    neighbourhood radius, where it could still make something;
// 2. pick seeds from the horizon in random order, each at least `seed_separation` neighbourhood
//    radii from the seeds already picked;
// 3. generate: for each seed s, its candidates co(s) (k-coherence on the exemplar element s was
//    copied from and on its current match) are ranked by the neighbourhood distance of eq. 1;
//    the best that can generate copies its right-partial pairs (exemplar neighbours left without
//    a partner within twice the mean bounding radius) that fall on a free-space point, inside
//    the domain and clear of every element's bounding circle. When the best candidate cannot
//    generate, the first that can is taken only if its distance is at most `ratio` (Davison's c)
//    times the best's plus (tolerance d̄)² per neighbour (an exact copy's best distance is 0,
//    and no other candidate is within any multiple of it); otherwise the seed is abandoned for
//    the round, and when a whole round makes nothing, its seeds leave the horizon (each
//    candidate's copies are found before the ranking: a seed none of whose candidates can copy
//    anything is abandoned without it, with the same outcome);
// 4. optimise where the output grew: every horizon element that an element arrived within the
//    largest neighbourhood radius of since the last optimisation, and every element within a
//    neighbourhood radius of one, takes its best match (a search over its candidates for those
//    horizon elements; the others keep theirs), whose full pairs predict its neighbours'
//    offsets; positions minimise the
//    predictions' squared errors weighted by Davison's eq. 4 (a Gaussian of the predicted moves
//    of each neighbourhood), with predictions onto older elements weighted `frozen_weight` and
//    older elements held by `anchor_weight`; elements farther out do not move;
// 5. free-space points of the moved elements are made again, and every point an element
//    overlaps is removed.
// Growth stops when the horizon is empty.
//
// Where the paper is vague we say what we chose: the bad-suggestion test keeps a generating
// candidate whose distance is at most c times the best candidate's (the paper's ratio is written
// upside down); the horizon is pruned by free points within the neighbourhood radius (with the
// bounding radius the paper names, no element of a sparse exemplar would ever stay); bounding
// radii default to each exemplar element's half nearest distance, capped by its shape's bounding
// circle, so that the exemplar itself has no overlap.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/methods/davison2018/growth_analysis.hpp"
#include "libshapeproc/methods/davison2018/growth_state.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::methods {

class RegionGrowing : public synthesis::Synthesizer {
 public:
  RegionGrowing(const geometry::Scene& exemplar, geometry::Boundary exemplar_boundary,
                geometry::Domain domain, GrowthOptions options);
  // Davison's example palette: each exemplar grows from its own initial patch (spread along the
  // domain's longest axis) with its own per-element parameters, and the regions meet where they
  // run into each other. Throws core::ArgumentError for an exemplar of another dimension.
  RegionGrowing(const std::vector<GrowthSource>& palette, geometry::Domain domain,
                GrowthOptions options);

  std::string method() const override { return "region-growing"; }
  synthesis::SynthesisResult synthesize(core::Random& random,
                                        const synthesis::ChainControl& control) const override;

  const GrowthExemplar& exemplar() const { return exemplar_; }
  std::vector<std::pair<std::string, std::string>> record_options() const;

 private:
  GrowthExemplar exemplar_;
  geometry::Domain domain_;
  GrowthOptions options_;
};

}  // namespace shapeproc::methods
