// Davison's example palette (Davison et al. 2018, §4.1 and §5.5): several exemplars, each analysed
// on its own (its spacing, neighbourhood radius, bounding radii, similarity sets and free space),
// joined into one growth exemplar whose elements keep their own exemplar's parameters. Exemplars
// of different scales then grow together in one output, each element's neighbourhood measured
// with its own radius.
//
// The parts' elements, shapes, categories and samples follow one another in that order; a part's
// categories and shape classes are renumbered after the previous parts', so that elements of two
// exemplars never share an attribute (a category name met twice gets its part's number: "dots #2").
#pragma once

#include <vector>

#include "libshapeproc/methods/davison2018/growth_state.hpp"

namespace shapeproc::methods {

// Joins analysed exemplars (analyse_growth_exemplar) into one palette. They must agree on the
// dimension and on the overlap test; throws core::ArgumentError where they do not.
GrowthExemplar merge_palette(std::vector<GrowthExemplar> parts);

}  // namespace shapeproc::methods
