// The drawn outlines kept apart. A model's hard cores at 0 or above forbid overlap (overlapping
// shapes are at a negative distance), but on the proxies, which stray from the drawn
// outlines by up to their tolerance (1% of an element's diagonal by default): chords cut inside a
// dot's arc, so two dots whose proxies touch overlap as drawn (Hero random-shapes: proxies 0.031
// apart, outlines overlapping by 0.004). Where two elements' proxies come within that error of
// touching, the guard measures them again on proxies as close to the drawn outlines as collisions
// are judged (geometry::kOutlineTolerance), and an overlap there is a hard-core violation like any
// other. It changes the model's density only on that sliver of configurations, which the exemplar
// (its outlines apart) never visits. Pairs whose hard core is below 0 (the exemplar overlaps or
// nests them) are left to the model.
#pragma once

#include <memory>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::sample {

class OverlapGuard {
 public:
  // `shape_space`: the model's shapes; `proxies`: the model's measurer of them; `interaction`:
  // its thresholds (the guard keeps their breakpoints: it serves any β and γ). The guard is
  // inactive for other distance kinds than the shape distance, for proxies already as fine as
  // the outline tolerance, and where the fine proxies are the model's (polygons: nothing to
  // flatten, nothing the simplification drops at either tolerance).
  OverlapGuard(const model::Interaction& interaction, const geometry::Scene& shape_space,
               const geometry::PairMeasurer& proxies);
  // The guard of `same_shapes` (the same shapes and measurement) for other thresholds: its fine
  // proxies are shared, not built again.
  OverlapGuard(const OverlapGuard& same_shapes, const model::Interaction& interaction);
  ~OverlapGuard();

  bool active() const { return outlines_ != nullptr; }

  // Whether ξ and `other`, whose proxies' distance lies in the interval of the pair's breakpoints
  // that holds `proxy_distance`, with `other` at `offset` from ξ (the image measured), overlap
  // as drawn.
  bool overlaps(const geometry::Element& xi, const geometry::Element& other,
                const geometry::Vec3& offset, double proxy_distance) const;

 private:
  // Per pair of categories (a × categories + b): the pair's breakpoints (Interaction), empty
  // where it does not interact.
  std::vector<std::vector<double>> breakpoints_;
  // Per pair of categories: its hard core is below 0, so overlaps are the model's to judge.
  std::vector<char> overlap_allowed_;
  int categories_ = 0;
  std::shared_ptr<const geometry::PairMeasurer> outlines_;  // null when inactive
  // Per shape: how far its proxy and its fine proxy may stray from the drawn outline together
  // (the sum of their tolerances times its diagonal, with the curves' flattening and a margin).
  std::vector<double> error_;
};

}  // namespace shapeproc::sample
