// One output sampled across the ranks of an MPI communicator (docs/sample.md, "Sampling across
// processes"): the decomposed sampler (sample/domain_decomposition.hpp), each rank visiting the
// cells of its block (mpi_cell_partition.hpp). Every visit's seed comes from the run's seed, the
// sweep, the colour and the cell, and each cell lists its elements as one process would, so the
// output is the same for any number of ranks and threads, and the same as `sample --decompose
// on` gives on one machine. Only sampling is distributed: the model is fitted beforehand, and
// every rank reads it whole. A mask or an intensity map is read by every rank too.
#pragma once

#include <mpi.h>

#include <cstdint>

#include "libshapeproc/core/resource_budget.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/sample/birth_death_sampler.hpp"

namespace shapeproc::distributed {

// Starts MPI for this process if nothing has (threads may run, only this one calls MPI), and ends
// it on destruction if it started it.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  MPI_Comm world() const { return MPI_COMM_WORLD; }

 private:
  bool started_ = false;
};

struct DistributedSample {
  // This rank's part, as ShapeProcessSampler::describe gives it: its scene holds the elements of
  // this rank's cells, in cell order; its record and counters (steps, moves, sweeps) are the
  // whole run's.
  synthesis::SynthesisResult result;
  long long elements = 0;    // in the whole output
  long long bytes_sent = 0;  // between all ranks: elements moving and border cells
  int rank = 0, ranks = 1;
};

// Each rank's share of the output (elements and bytes), checked against `budget`.
core::ResourceEstimate rank_share(const model::ShapeProcessModel& model,
                                  const geometry::Domain& domain, int ranks);

// The output of `model` on `domain`, sampled as `sample` samples it (fit::output_sampler with
// decomposition on) from core::Random(seed). Every rank of `communicator` calls it with the same
// arguments. Throws core::UsageError when a rank's share exceeds `budget`, and
// core::ArgumentError when the decomposed sampler cannot take the model (a packed exemplar's
// compressing burn-in, saturated bands, layers) or the domain (too small for its reach, or fewer
// rows of cells than ranks); every rank throws alike, before any exchange.
DistributedSample sample_distributed(const model::ShapeProcessModel& model,
                                     const geometry::Domain& domain,
                                     const fit::OutputSampling& sampling, std::uint64_t seed,
                                     MPI_Comm communicator, const core::ResourceBudget& budget = {},
                                     const synthesis::ChainControl& control = {});

}  // namespace shapeproc::distributed
