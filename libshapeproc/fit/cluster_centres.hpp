// The clusters of a clustered point pattern and their centres (docs/fit.md, "Clusters"). Points
// grouped around centres (a Thomas or Matérn cluster process: parents, each with a few children
// near it) are not a pairwise process: a γ > 1 strong enough to hold a group together condenses the
// whole domain, and one weak enough to be stable loses the groups. The fit instead adds the
// centres as a hidden category below the points, which are then anchored to them
// (category_layers.hpp): each output places centres, then points around them, and draws the
// points only.
//
// Whether the pattern is clustered, and at what scale, comes from Ripley's K: the Thomas
// process's K(r) = πr² + (1 − exp(−r²/4σ²)) / κ is fitted by minimum contrast to the exemplar's
// estimate K̂ (Diggle 1983), and the pattern is clustered when the excess K̂(2σ) − π(2σ)² is
// above `min_z` standard errors of K̂ under complete spatial randomness (Var K̂(r) ≈ 2πr²|W| / n²)
// and the fitted clusters hold at least `min_cluster_size` points on average. The centres: κ|W|
// of them, seeded where the points are densest (within 2σ), then moved to the means of the
// points nearest them (Lloyd's iterations).
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::fit {

struct ClusterOptions {
  double min_z = 4.0;
  double min_cluster_size = 3.0;
};

struct ClusterFit {
  bool clustered = false;
  double sigma = 0.0;  // the Thomas fit's cluster scale
  double kappa = 0.0;  // its centres per unit area
  double z = 0.0;      // the excess of K̂ at 2σ, in standard errors under randomness
  std::vector<geometry::Vec3> centres;  // when clustered
  std::string note;                     // what was measured and decided
};

// The exemplar's points, of every category pooled; `periodic`: its window is a torus.
ClusterFit find_clusters(const geometry::Scene& exemplar, bool periodic,
                         const ClusterOptions& options = {});

}  // namespace shapeproc::fit
