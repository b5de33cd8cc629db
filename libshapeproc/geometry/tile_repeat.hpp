// A seamless tile as a fitting exemplar. On the tile's own torus an element's periodic images are
// the element itself, and pair counting by the nearest image never sees them: a tile of one
// element has no neighbours, and ranges over half the tile miss images. Repeated k × k on a torus
// k times as large, the same drawing holds each image as an element of its own, so the nearest
// image counts them up to half the repeat's side.
#pragma once

#include <cstddef>
#include <vector>

#include "libshapeproc/geometry/scene.hpp"

namespace shapeproc::geometry {

// The scene's elements copied `times` × `times` (2D: along x and y; 3D also along z), each copy
// moved by whole windows, on a window `times` as large along each axis from the same corner.
Scene repeat_tile(const Scene& tile, int times);

// The tile repeated as often as needed for its smallest side to reach `reach` (unchanged when it
// does): a neighbourhood of radius R on a torus sees every image once when the side is >= 2R.
Scene repeat_to_reach(const Scene& tile, double reach);

// The tile's elements repeated by whole windows over `region` (2D: along x and y; 3D also z), those
// whose reference positions lie in it (half-open: [min, max) along each axis): the drawing
// continued as the seamless repeat it is, e.g. a sampler's start on an output domain (the chain
// then moves, removes and adds elements).
std::vector<Element> tile_over(const Scene& tile, const Box3& region);

// Repeats along each side (at least `at_least`) for a torus on which pairs of elements whose
// outlines are up to `range` apart are seen once, by their nearest image: the smallest side at
// least twice the range plus the largest shape's extent on either side.
int repeats_to_hold(const Scene& tile, double range, int at_least);

// Repeats along each side that a tile of `elements` elements is fitted with: none from 8
// elements (their interaction ranges stay within half the tile), else 3 (an element's images one
// period away on either side are then two elements; on a repeat of 2 they would be one), and 4 for
// a single element (16 elements to fit from).
int tile_repeats(std::size_t elements);

}  // namespace shapeproc::geometry
