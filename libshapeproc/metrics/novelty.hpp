// Novelty (docs/metrics.md#novelty): is an output a new arrangement, or the exemplar repeated?
// A copy keeps every element where the exemplar, tiled with its window as the period, has one of
// the same size; a new arrangement keeps the exemplar's statistics but not its placements. The
// measures, each against the same measure of a random placement of the output's own elements
// (its chance level):
//
//   copy share        the share of output elements within τ of a same-size element of the tiled
//                     exemplar under the best single translation t* (τ a quarter of the
//                     exemplar's mean spacing (|W|/n)^(1/dim));
//   patch copy share  the share of output elements that are copies under t* together with their
//                     k (default 4) nearest output neighbours: a copied neighbourhood, not a
//                     coincidence of one element (a new arrangement on the exemplar's own grid
//                     keeps many single copies and few patches);
//   largest patch     the largest set of output elements, connected through nearest-neighbour
//                     links, that are copied neighbourhoods under one translation (any
//                     translation, not only t*: a method that pastes pieces of the exemplar at
//                     several offsets is caught piece by piece), as a share of the output;
//   repetition        the share of output elements with a same-size output element within τ of
//                     their position moved by a period vector of the exemplar (each side of its
//                     window), counting only positions that fall inside the output: 1 for the
//                     exemplar tiled, about the density times the disc of radius τ for a random
//                     placement.
//
// An exemplar whose elements of one size are all equivalent under translation (every translation
// from one element to another of the same size maps the tiled exemplar onto itself: a perfect
// lattice, possibly with a basis of several kinds, as a chequerboard of two shapes) has one local
// arrangement only, so that every faithful output repeats it: `lattice_exemplar` says so, and the
// verdict shows these measures without judging them.
#pragma once

#include <cstdint>

#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::metrics {

struct NoveltyOptions {
  double tolerance = 0.0;  // τ; 0: a quarter of the exemplar's mean spacing
  int neighbours = 4;      // k of the patch test
  // Two shapes are the same (as drawn, turn included) when geometry::size_distance is at most
  // this (about 5% apart in radius and in area) and their bounding boxes' sides agree (within
  // about 20% of each side counted from a quarter of the radius).
  double size_tolerance = 0.1;
  int chance_draws = 4;  // random placements averaged for the chance levels
  std::uint64_t seed = 1;
  // Output elements whose pairings with exemplar elements give the candidate translations of
  // t*, and the output elements each candidate is first scored on (the best 8 are then scored on
  // all): 0: every element.
  int anchors = 48;
  int screening = 96;
};

struct CopyMeasures {
  double copy = 0.0;           // copy share
  double patch = 0.0;          // patch copy share
  double largest_patch = 0.0;  // largest copied patch, share of the output
  double repetition = 0.0;     // share repeated at the exemplar's period vectors
};

struct Novelty {
  int elements = 0;
  double tolerance = 0.0;                               // τ, in the scenes' units
  geometry::Vec3 translation = geometry::Vec3::Zero();  // t*: output = exemplar + t*
  CopyMeasures output;
  CopyMeasures chance;  // the mean over random placements of the output's elements
  // Every same-size element of the exemplar is equivalent to every other under translation: its
  // own repeat is the only arrangement that keeps every neighbourhood (see above).
  bool lattice_exemplar = false;
  // The output repeats the exemplar: its copied neighbourhoods stand well above chance (patch
  // copy share more than kPatchExcess above its chance level, or a largest copied patch over
  // kLargestPatch of the output), and the exemplar is no lattice.
  bool repeats_exemplar = false;
};

inline constexpr double kPatchExcess = 0.3;
inline constexpr double kLargestPatch = 0.3;

// The exemplar is one period of its tiling: its window is the period, whatever its boundary. The
// output's boundary decides whether its neighbours and repeats wrap. Throws core::ArgumentError for
// an empty scene, an empty window or scenes of different dimensions.
Novelty measure_novelty(const geometry::Scene& exemplar, const geometry::Scene& output,
                        geometry::Boundary output_boundary, const NoveltyOptions& options = {});

// Whether every same-size element of the exemplar is equivalent to every other under translation
// within `tolerance` (0: a quarter of the mean spacing) on the exemplar's tiling.
bool is_lattice_exemplar(const geometry::Scene& exemplar, double tolerance = 0.0,
                         double size_tolerance = 0.1);

}  // namespace shapeproc::metrics
