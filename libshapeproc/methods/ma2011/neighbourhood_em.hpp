// Discrete element textures by neighbourhood EM (Ma et al. 2011), the first comparison method:
// an output initialised from the exemplar (§4.1), then improved by alternating the search step
// (§4.2: each output sample's most similar exemplar neighbourhood, k-coherence by default) and
// the assignment step (§4.3: positions by least squares, attributes by vote), with the domain
// shape term and orientation field of §5, until the energy of eq. 2 stops falling or the
// iteration cap (10, as in the paper) is reached; the elements are then rebuilt from their
// samples.
//
// Each half of the assignment is kept only when it lowers the energy of the matches it came from:
// the positions' move is shortened (halved down to kShortestStep) until it does, and when neither
// the move nor the vote lowers the energy, the chain has converged. With the
// next search free to keep every match, the energy never increases over the iterations, unless
// the interleaved physics solver (off by default) moves elements apart: its moves are kept
// whatever they cost, as an implicit term outside eq. 2.
// The output's element count is the initialisation's: the EM moves elements, it does not add or
// remove them, except that elements it moved outside the domain (eq. 6 is only a soft term) are
// left out of the output (counted in the result's counters).
#pragma once

#include <optional>
#include <string>

#include "libshapeproc/methods/common/element_reconstruction.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/k_coherence.hpp"
#include "libshapeproc/methods/common/neighbourhood_search.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"
#include "libshapeproc/methods/ma2011/em_initialisation.hpp"
#include "libshapeproc/methods/physics/interleaved_physics.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::methods {

inline constexpr double kShortestStep = 1.0 / 16.0;

struct EmOptions {
  double rings = 2.0;  // neighbourhood size
  int k = 5;           // similarity set size
  // Weights of an attribute mismatch (α, eq. 1) and of the domain term (λ, eq. 6), in squared
  // mean nearest distances d̄² (Ma et al. give them in absolute units of the order of d̄).
  double alpha = 1.0, lambda = 1.0;
  SampleOptions samples;
  Initialisation initialisation = Initialisation::patch_copy;
  // Diversity: patch copy never continues a neighbouring cell's exemplar patch (patch_copy.hpp);
  // off, a seamless tile is copied whole.
  bool diverse_patches = true;
  SearchRule search = SearchRule::k_coherence;
  Reconstruction reconstruction = Reconstruction::rigid;
  int iterations = 10;
  // The interleaved physics solver (§5): engine steps after each assignment; 0 = off.
  int physics_steps = 0;
  double tolerance = 1e-3;  // converged when an iteration lowers the energy by less than this share
  OrientationField orientation;
};

class NeighbourhoodEm : public synthesis::Synthesizer {
 public:
  // `exemplar_boundary`: torus for a seamless tile, else open. Throws core::ArgumentError for
  // bad options, an exemplar under 2 elements, or a dimension mismatch with the domain.
  NeighbourhoodEm(const geometry::Scene& exemplar, geometry::Boundary exemplar_boundary,
                  geometry::Domain domain, EmOptions options);

  std::string method() const override { return "neighbourhood-em"; }
  synthesis::SynthesisResult synthesize(core::Random& random,
                                        const synthesis::ChainControl& control) const override;

  const EmExemplar& exemplar() const { return exemplar_; }
  const EmOptions& options() const { return options_; }
  // The options as a record's (key, text) pairs.
  std::vector<std::pair<std::string, std::string>> record_options() const;

 private:
  EmExemplar exemplar_;
  geometry::Domain domain_;
  EmOptions options_;
  SimilaritySets sets_;
  SearchSettings settings_;
  std::optional<InterleavedPhysics> physics_;
};

}  // namespace shapeproc::methods
