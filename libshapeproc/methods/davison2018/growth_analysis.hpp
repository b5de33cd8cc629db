// What region growing (Davison et al. 2018) learns from its exemplars before growing: its
// options, and each exemplar's analysis (the EM's neighbourhoods of single-sample elements,
// similarity sets, bounding radii and free space), with Davison's per-element parameters, alone
// or joined into a palette (growth_palette.hpp).
//
// Bounding radii default to each exemplar element's half nearest distance, capped by its shape's
// bounding circle, so that the exemplar itself has no overlap.
#pragma once

#include <optional>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/methods/davison2018/growth_state.hpp"

namespace shapeproc::methods {

struct GrowthOptions {
  double rings = 2.0;      // neighbourhood radius r̄ = (rings + 1/2) d̄, as the EM's
  int k = 5;               // similarity set size (Davison: 3 to 5)
  double alpha = 1.0;      // attribute mismatch weight, in d̄²
  double ratio = 2.0;      // c, the bad-suggestion ratio (> 1)
  double tolerance = 1.0;  // added to c × best: (tolerance d̄)² per neighbour
  double seed_separation = 0.75;
  double cluster_eps = 0.25;     // DBSCAN radius of free-space vectors, in d̄
  int cluster_min_points = 2;    // DBSCAN core size
  double bounding_radius = 0.0;  // > 0: every element's bounding radius (units of the exemplar)
  // A copy's neighbourhood limited to c times the exemplar's mean count, c chosen by pilot
  // growths until the output's density is the exemplar's (density_calibration.hpp); false: no
  // limit, as the paper.
  bool calibrate_density = true;
  bool optimise = true;
  // Overlap test: true, the shapes themselves (the signed shape distance below 0; touching
  // allowed), which no published growth method has; false, bounding circles (spheres), as the
  // paper; empty, the shapes unless the exemplar is a lattice (metrics::is_lattice_exemplar; a
  // palette: unless every exemplar is). Circles of half each element's nearest distance hold a
  // lattice's spacing, but on an irregular exemplar they forbid its own close pairs and the
  // output's nearest distances come out too wide (dots-random: W1 0.40 against 0.11).
  std::optional<bool> exact_overlap;
  double frozen_weight = 0.1, anchor_weight = 100.0;
  // Diversity: a seed extends the exemplar patch it was copied in (its candidate is its own
  // exemplar element, or one of its images a tile period away) only while it lies within this many
  // neighbourhood radii of where that patch began; beyond, its own element is not a candidate and
  // the best other one starts a new patch. Without it a seamless tile grows into the tile repeated.
  // 0: off (the paper).
  double patch_radius = 1.5;
};

// The exemplar analysed for growth (single-sample elements); throws core::ArgumentError for bad
// options or an exemplar of fewer than 2 elements.
GrowthExemplar analyse_growth_exemplar(const geometry::Scene& exemplar, geometry::Boundary boundary,
                                       const GrowthOptions& options);

// One exemplar of a palette, with its own parameters where they differ from the options'.
struct GrowthSource {
  geometry::Scene scene;
  geometry::Boundary boundary = geometry::Boundary::open;
  double rings = 0.0;             // > 0: its neighbourhood in rings of its own spacing
  double bounding_radius = -1.0;  // >= 0: its elements' bounding radius (0: automatic)
};

// The exemplars of a palette analysed each on its own and joined (growth_palette.hpp); a single
// exemplar as analyse_growth_exemplar gives it. Throws core::ArgumentError for an empty palette,
// an exemplar of another dimension than `dimension`, or bad options.
GrowthExemplar analyse_growth_palette(const std::vector<GrowthSource>& sources,
                                      const GrowthOptions& options, int dimension);

}  // namespace shapeproc::methods
