// Parallel sampling of one output by spatial domain decomposition (docs/sample.md, "Parallel
// sampling of one output"). The domain is cut into cells at least the model's reach long
// (cell_layout.hpp), coloured so that cells of one colour never interact. A sweep shifts the cells
// by a random offset and visits the colours in turn; the cells of one colour are updated at once
// on several threads, each by a birth-death chain confined to its cell (births in it, deaths of
// its elements, shifts that stay in it) with the elements around it held fixed. Each visit is a
// Metropolis-Hastings update of the cell given the rest, so every sweep keeps the target
// distribution, whatever the threads (as in parallel samplers of marked point processes for large
// scenes, e.g. Verdié & Lafarge 2014).
//
// The burn-in starts near the expected count: a pilot chain on a small torus gives the density,
// and a first sweep fills each cell by random sequential insertion under the hard core to that
// density. The number of steps of a visit is fixed for the run from the pilot's density (so it
// does not depend on the chain's state). Each visit's generator is seeded from the run's seed,
// the sweep, the colour and the cell: same seed, same output, with any number of threads.
#pragma once

#include "libshapeproc/core/random.hpp"
#include "libshapeproc/geometry/domain.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"
#include "libshapeproc/synthesis/synthesizer.hpp"

namespace shapeproc::sample {

struct ChainTables;
struct ChainRegion;

// The side of the decomposition's cells: at least the reach, and large enough to hold about
// `kElementsPerCell` elements at the pilot's density (so that building a visit's state, about
// one measurement per element of the cell and its ring, costs little beside its steps).
double cell_side(double reach, double density, int dimension);

// Whether the domain can be decomposed for a model of this reach at all (cells of the reach).
bool decomposable(const geometry::Domain& domain, double reach);

// One output sampled by decomposition. `options` as for the whole-domain chain (iterations,
// max_iterations, shift moves, start, trace_every, threads); fixed elements, a free region and
// observations are not supported (core::ArgumentError).
SampleResult sample_by_cells(const model::ShapeProcessModel& model, const ChainTables& tables,
                             const ChainRegion& whole, const SamplerOptions& options,
                             core::Random& random, const synthesis::ChainControl& control);

}  // namespace shapeproc::sample
