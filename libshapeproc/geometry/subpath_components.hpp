// Splitting a drawable into its disjoint pieces (for `--split-subpaths`).
#pragma once

#include <vector>

#include "libshapeproc/geometry/shape.hpp"

namespace shapeproc::geometry {

// Groups the subpaths of `drawable` into pieces that do not touch each other. Two subpaths stay
// together when their outlines cross or share a piece of outline (touching at a point does not
// count: squares of a checkerboard are separate pieces), or when one is a hole of the other: it
// lies inside an odd number of closed subpaths and the innermost of those is the other. A dot
// inside a ring's hole (depth 2) is therefore a piece of its own. Each piece keeps the drawable's
// style and fill rule and its subpaths in their original order; pieces come in the order of their
// first subpath.
std::vector<Drawable2> split_disjoint_subpaths(const Drawable2& drawable);

}  // namespace shapeproc::geometry
