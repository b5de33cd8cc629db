// The neighbourhood EM's starting output (Ma et al. 2011, §4.1).
// - Patch copy (the default): whole elements copied patch by patch (compare/patch_copy.hpp).
// - Random element copy ("white noise"): as many elements as the exemplar's density gives the
//   domain, each a random exemplar element at a uniform random place.
// - Incremental add (Jodoin et al. 2002, Ijiri et al. 2008): from one element at the domain's
//   centre, elements are added at the exemplar offsets of their sources' neighbours, a random
//   frontier element at a time, where no element is nearer than half the exemplar's smallest
//   nearest distance.
// Elements whose reference position falls outside the domain (its box and mask) are not placed.
#pragma once

#include <string>

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/methods/common/em_exemplar.hpp"
#include "libshapeproc/methods/common/orientation_field.hpp"
#include "libshapeproc/methods/common/output_samples.hpp"

namespace shapeproc::methods {

enum class Initialisation { patch_copy, random_copy, incremental_add };
const char* to_string(Initialisation initialisation);
Initialisation parse_initialisation(const std::string& text);  // throws core::ArgumentError

// The first output, and for each of its samples the exemplar sample it was copied from.
struct InitialOutput {
  OutputSamples output;
  std::vector<int> copied_from;  // per output sample

  // Appends a copy of exemplar element `source` at `position`, turned by `radians`.
  void add(const EmExemplar& exemplar, int source, const Vec3& position, double radians);
};

// `alpha`: the attribute weight of eq. 1 (squared length units), for the patches' seams.
// `diverse`: patch copy's diversity (patch_copy.hpp).
InitialOutput initialise(const EmExemplar& exemplar, const geometry::Domain& domain,
                         const OrientationField& orientation, Initialisation rule, double alpha,
                         core::Random& random, bool diverse = true);

// The smallest distance between two exemplar elements (minimum image on a torus), at most d̄.
double smallest_gap(const EmExemplar& exemplar);

// The elements the domain should hold at the exemplar's density (its box, or the mask's inside).
double expected_elements(const EmExemplar& exemplar, const geometry::Domain& domain);

}  // namespace shapeproc::methods
