// Elements as a person sees them: connected pieces of ink, optionally on the torus of a seamless
// tile.
//
// The scene's elements are taken apart into subpaths and joined again where their ink meets:
//   - outlines that cross or run together along a piece of positive length (pieces that meet
//     only at a point stay apart: tilings of triangles or squares meeting at corners);
//   - a subpath inside the filled part of a drawable (a hole of its own drawable, or ink over
//     another drawable's fill);
//   - a subpath inside a hole of another piece, i.e. within its outer contour (a dot in a ring's
//     hole, a gear's hub, the details inside an icon's outline), unless `nested_separate`.
// Pieces of different categories stay apart. With `tile`, the window is one period of a seamless
// repeat: every subpath is clipped to it (tiles that draw beyond their viewport rely on that
// clipping) and pieces also meet their neighbours' copies one period away, so an element the border
// cuts is joined into one whole element, counted once per period and drawn unwrapped.
#pragma once

#include <string>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry {

struct VisualOptions {
  bool nested_separate = false;
  bool tile = false;
  // Whether the subpaths of each given element start joined (elements chosen by groups, paths or
  // subpaths, then joined across the tile's border), or only ink decides (`visual`).
  bool keep_elements = false;
};

struct VisualElements {
  Scene scene;
  std::size_t subpaths = 0;        // subpaths the elements were made from
  std::vector<std::string> notes;  // what the grouping met (motifs wrapping around the tile)
};

// The elements of the planar scene `scene` regrouped as connected pieces of ink. Categories of
// the joined pieces are the first piece's; the window is kept.
VisualElements visual_elements(const Scene& scene, const VisualOptions& options);

}  // namespace shapeproc::geometry
