// Initialisation by patch copy (Ma et al. 2011, §4.1): the output is cut into square (cubic)
// cells of the neighbourhood's size 2r, and each cell, in scanline order, receives the whole
// elements of a patch of that size taken from the exemplar (anywhere on a torus, inside the
// window otherwise), turned by the orientation field at the cell's centre.
//
// Ma et al. copy patches at random, which on regular exemplars leaves seams out of phase that the
// EM cannot close. Here, as image quilting picks its blocks, the patch copied is the best of
// kPatchCandidates patches at random places, each also tried moved by the mean offset its seam's
// pairs ask for. A patch's seam cost is eq. 1 on both sides of the seam: its samples'
// neighbourhoods among the elements already placed, and the placed samples' neighbourhoods among
// its own, with r² for every exemplar neighbour that would fall on the other side without a
// partner (eq. 1 alone would let a seam open a gap, or a sparse patch win, for free). Elements
// nearer than half the exemplar's smallest gap to one already placed are left out. On an open
// exemplar, cells are narrowed where needed to leave the patch origin two mean spacings of room
// (a structure repeating every two spacings has each phase within reach); where the room left is
// under r, seam neighbours the exemplar's window cannot show are judged by its pooled offsets.
// An open exemplar that leaves less than a mean spacing of room along every axis is cramped: each
// patch is also tried moved in the output by what those offsets ask (docs/methods.md, "Seams of
// an open exemplar").
#pragma once

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"
#include "libshapeproc/methods/ma2011/em_initialisation.hpp"

namespace shapeproc::methods {

inline constexpr int kPatchCandidates = 16;

// Fills `out` (empty on entry) by patch copy; `alpha` is eq. 1's attribute weight. With
// `diverse`, a cell never takes the exemplar patch that continues a neighbouring cell's (the
// same translation from the exemplar, modulo a seamless tile's period, within a quarter of its
// mean nearest distance): without it the seam-closing move picks exactly that continuation and
// a seamless tile comes out repeated.
void patch_copy(const EmExemplar& exemplar, const geometry::Domain& domain,
                const OrientationField& orientation, double alpha, core::Random& random,
                InitialOutput& out, bool diverse = true);

}  // namespace shapeproc::methods
