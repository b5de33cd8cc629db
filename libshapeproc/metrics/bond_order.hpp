// Long-range order (docs/metrics.md): does an arrangement keep one lattice orientation across the
// window, as a grid does and a random packing does not? The bond-orientational order parameter
// of n-fold symmetry (Steinhardt, Nelson and Ronchetti 1983; Halperin and Nelson's ψ6),
//     ψ_n(j) = (1/n) Σ_{k among j's n nearest} exp(i n θ_jk),
// θ_jk the angle of the bond from element j to its neighbour k (reference positions, minimum
// image on a torus; in an open window only elements farther from the edge than their n-th
// neighbour are centres). Its global magnitude |⟨ψ_n⟩| over all elements is 1 for a perfect lattice
// of that symmetry, falls as positions jitter or grains turn, and is about 1/√N for a Poisson
// pattern; the local mean ⟨|ψ_n(j)|⟩ keeps each neighbourhood's order without asking that the
// orientation hold across the window (about 0.3 to 0.4 for Poisson). Planar: 3D scenes are
// measured on their x–y projection.
#pragma once

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::metrics {

struct BondOrder {
  double global4 = 0.0, global6 = 0.0;  // |⟨ψ4⟩|, |⟨ψ6⟩|
  double local4 = 0.0, local6 = 0.0;    // ⟨|ψ4|⟩, ⟨|ψ6|⟩
  // The long-range order of the stronger symmetry: max(|⟨ψ4⟩|, |⟨ψ6⟩|).
  double order() const { return global4 > global6 ? global4 : global6; }
  int symmetry() const { return global4 > global6 ? 4 : 6; }
};

// A torus of fewer than 7 elements is taken as a seamless tile and repeated until it has 7 (ψ6
// needs 6 neighbours); an open window of fewer than 7 has no measure (0). Throws
// std::invalid_argument when the scene's window is empty.
BondOrder bond_order(const geometry::Scene& scene, geometry::Boundary boundary);

}  // namespace shapeproc::metrics
