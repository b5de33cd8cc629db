// Element arrangements by seed-and-grow (Ijiri et al. 2008), the second growth method compared:
// the exemplar's connectivity (delaunay_connectivity.hpp) gives each inner element a ring of
// neighbours; the output grows from seeds outwards, one seed at a time, nearest the first seeds
// first. Each step:
// 1. picks the seed nearest the initial seeds, or a seed of higher priority within 5 l of it
//    (priorities by symbol id, §5.1; l the exemplar's mean edge length);
// 2. finds the reference element whose ring best matches the seed's partial ring (ring_matching:
//    cyclic matchings, eq. 2, the rotation mode of §5.3) and puts a copy of it there;
// 3. overlays the reference ring (turned by the match's angle): its neighbours not paired with
//    the seed's become new seeds with their symbol ids, unless (§5.4, Fig. 6)
//    - an element or seed lies within l_short (half the shortest reference edge): the edge goes
//      to it instead;
//    - the new edge would make an angle with the seed's other edges below half the reference
//      ring's angle at that neighbour: seed and edge are dropped;
//    - the new edge would cross an edge: seed and edge are dropped;
//    then joins consecutive ring members; where two are farther apart than l_long (1.5 times
//    their distance in the reference ring), an extra seed without symbol id goes between them on
//    the bisector, as far out as the two on average;
// 4. relaxes the rings near the step (ring_relaxation, eq. 5), the first element held.
// With an overlap test, steps 2 and 4 skip what would make elements overlap.
// Growth ends when no seed is left; the rings are then relaxed over the whole output. A seed
// whose partial ring is larger than every reference ring of its symbol (it is surrounded) is
// dropped; the paper's "simply ignore such reference elements" leaves it nothing to match.
//
// The paper's spray tool maps to seeds read from a file, its boundary tool to a domain mask
// (growth stops where the mask ends), its flow field tool to an orientation field (a constant
// angle or a grey-level map).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"
#include "libshapeproc/methods/ijiri2008/delaunay_connectivity.hpp"
#include "libshapeproc/methods/ijiri2008/ring_matching.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::methods {

struct SeedGrowthOptions {
  RotationMode rotation = RotationMode::none;
  OrientationField field;  // for RotationMode::flow_field
  double w1 = 1.0, w2 = 1.0, w3 = 100.0;
  bool relax = true;
  int relax_hops = 2, relax_sweeps = 2, final_sweeps = 20;
  std::vector<EdgeFlip> flips;
  std::vector<Vec3> seeds;    // empty: one seed at the domain's centre
  std::vector<int> priority;  // per exemplar category; empty: all alike
  // Overlap test, an option the paper does not have: a copy whose shape would overlap an element
  // already placed is passed over for the next best match, and the relaxation makes no move
  // that overlaps. Turned copies are then turned in steps of 0.5 degrees, so that the shapes
  // tested (kept per step) are the shapes drawn.
  bool exact_overlap = false;
  // Or, as region growing's default: bounding circles of half each exemplar element's nearest
  // ring distance (the exemplar itself then has no overlap).
  bool circle_overlap = false;
};

const char* to_string(RotationMode mode);
RotationMode parse_rotation_mode(const std::string& text);  // throws core::ArgumentError

// What seed-and-grow learns from the exemplar.
struct SeedGrowthExemplar {
  geometry::Scene scene;
  geometry::Domain domain;  // the exemplar's window, a torus for a tile
  Connectivity connectivity;
  std::vector<int> symbol;                  // per element
  std::vector<ReferenceRing> references;    // the elements with closed rings
  std::vector<std::vector<int>> by_symbol;  // reference indices per symbol
  std::vector<int> all;                     // every reference index
  double longest_edge = 0.0;
  double density = 0.0;               // elements per unit area
  std::vector<double> shape_radius;   // per shape: its bounding circle
  std::vector<double> circle_radius;  // per element: half its nearest ring distance  // per shape:
                                      // its bounding circle
};

// A seamless tile (torus) of one or two elements is repeated 2 × 2 first. Throws
// core::ArgumentError for a 3D exemplar, fewer than 3 elements (after that), bad flips, or an
// exemplar where no element has a closed ring.
SeedGrowthExemplar analyse_seed_growth_exemplar(const geometry::Scene& exemplar,
                                                geometry::Boundary boundary,
                                                const std::vector<EdgeFlip>& flips);

class SeedAndGrow : public synthesis::Synthesizer {
 public:
  SeedAndGrow(const geometry::Scene& exemplar, geometry::Boundary exemplar_boundary,
              geometry::Domain domain, SeedGrowthOptions options);

  std::string method() const override { return "seed-and-grow"; }
  synthesis::SynthesisResult synthesize(core::Random& random,
                                        const synthesis::ChainControl& control) const override;

  const SeedGrowthExemplar& exemplar() const { return exemplar_; }
  std::vector<std::pair<std::string, std::string>> record_options() const;

 private:
  SeedGrowthExemplar exemplar_;
  geometry::Domain domain_;
  SeedGrowthOptions options_;
};

}  // namespace shapeproc::methods
