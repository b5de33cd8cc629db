// Finding the best matching element (Ijiri et al. 2008, §5.2, §5.3): a seed's partial ring of
// neighbours is compared with every reference element's ring by the cyclic matchings f_k, which
// pair the seed's neighbours, in counter-clockwise order from the first after the widest gap,
// with the reference neighbours k, k + 1, ... (no skipping, no flipping). A matching's error is
// eq. 2,
//   Σ_(i,j)∈f  w1 |t_i − R r_j| / l + w2 [symbol_i ≠ symbol_j] + w3 [sub-id_i = the reference],
// where l is the exemplar's mean edge length (so that w1 = 1 weighs a miss of one edge like one
// wrong symbol; the paper leaves the unit open) and R the rotation of the mode:
// - none: the identity;
// - best: per matching, the rotation that best lays the reference offsets on the seed's (eq. 4,
//   solved in least squares as in the shape matching the paper cites);
// - flow field: the field's angle at the seed, the same for every matching.
// References with fewer neighbours than the seed has are skipped, as the paper does.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/types.hpp"

namespace shapeproc::methods {

using geometry::Vec3;

enum class RotationMode { none, best, flow_field };

// A neighbour of the seed being grown: its offset from the seed, its symbol id (-1: a seed
// without one, which matches any) and sub-id (the exemplar element it copies; -1 for a seed).
struct TargetNeighbour {
  Vec3 offset = Vec3::Zero();
  int symbol = -1;
  int sub_id = -1;
};

// A reference element: its symbol id, and its closed ring, counter-clockwise.
struct ReferenceRing {
  int element = 0;  // its sub-id
  int symbol = 0;
  std::vector<Vec3> offset;
  std::vector<int> neighbour;         // sub-ids
  std::vector<int> neighbour_symbol;  // symbol ids
};

struct MatchWeights {
  double distance = 1.0, symbol = 1.0, sub_id = 100.0;  // w1, w2, w3
  double unit = 1.0;                                    // l: distances are divided by it
};

struct RingMatch {
  double error = std::numeric_limits<double>::infinity();
  int reference = -1;  // index into the references searched
  int shift = 0;       // f_shift: target i ↔ reference neighbour (shift + i) mod size
  double angle = 0.0;  // R, radians
};

// The order in which a partial ring is matched: counter-clockwise by angle, starting at the
// neighbour after the widest angular gap (the border of what has grown).
std::vector<int> partial_ring_order(const std::vector<TargetNeighbour>& target);

// The rotation angle that best lays reference offsets (shift + i) onto target offsets i.
double best_rotation(const std::vector<TargetNeighbour>& target, const ReferenceRing& reference,
                     int shift);

// Eq. 2 for matching f_shift with the reference turned by `angle`.
double matching_error(const std::vector<TargetNeighbour>& target, const ReferenceRing& reference,
                      int shift, double angle, const MatchWeights& weights);

// Eq. 1 and 3: the best matching over the references listed in `candidates` (indices into
// `references`). `target` is already in partial_ring_order. Exact ties are broken by `random`
// (the first seed, with no neighbour, ties every reference). `accept`, when given, is asked
// about a matching before it becomes the best (e.g. whether its copy would overlap), and a
// refused one is passed over. No usable reference: error ∞.
using MatchFilter = std::function<bool(const ReferenceRing& reference, double angle)>;
RingMatch best_match(const std::vector<TargetNeighbour>& target,
                     const std::vector<ReferenceRing>& references,
                     const std::vector<int>& candidates, RotationMode mode, double field_angle,
                     const MatchWeights& weights, core::Random& random,
                     const MatchFilter& accept = {});

}  // namespace shapeproc::methods
