// The attribute half of the assignment step (Ma et al. 2011, §4.3, eq. 5): each output element
// takes the attributes q (shape, category, shape class) of one exemplar element chosen by vote.
// The votes are the exemplar elements whose samples its samples were paired with in the search;
// the chosen q is the vote with the least summed distance to all votes,
//     q(so) = argmin_{q(si)} Σ_{si'} |q(si) − q(si')|²,
// and the element copies the most voted exemplar element with that q (ties: the current source,
// then the lowest index). Only exemplar elements with the element's sample count can win, so
// that its samples keep their ids.
#pragma once

#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/neighbourhood_search.hpp"
#include "libshapeproc/methods/common/output_samples.hpp"

namespace shapeproc::methods {

// The exemplar element each output element should copy after the vote.
std::vector<int> vote_attributes(const EmExemplar& exemplar, const OutputSamples& output,
                                 const SearchResult& search);

}  // namespace shapeproc::methods
