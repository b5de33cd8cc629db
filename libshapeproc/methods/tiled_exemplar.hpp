// The exemplar repeated: the baseline every synthesis method is compared with (`synthesize
// --method tile`, the `tile` row of `compare`). It tiles the exemplar over the output domain by
// whole windows (geometry::tile_over) and keeps the elements whose reference positions fall in
// it. It matches the exemplar's statistics as well as anything can and has no novelty at all: a
// method must come near it on fidelity while it scores far below it on the copy measures
// (metrics/novelty.hpp).
#pragma once

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::methods {

class TiledExemplar : public synthesis::Synthesizer {
 public:
  // Throws core::ArgumentError for an empty exemplar or a domain of another dimension.
  TiledExemplar(geometry::Scene exemplar, geometry::Domain domain);

  std::string method() const override { return "tile"; }
  // The same output for every seed: the generator is not used.
  synthesis::SynthesisResult synthesize(core::Random& random,
                                        const synthesis::ChainControl& control) const override;

 private:
  geometry::Scene exemplar_;
  geometry::Domain domain_;
};

}  // namespace shapeproc::methods
