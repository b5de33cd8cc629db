// shapeproc sample MODEL --distributed: one output sampled across MPI ranks
// (distributed/distributed_sampling.hpp), run under mpirun. Each rank writes its part of the
// CSV; rank 0 writes the manifest, or with --merge joins the parts into one CSV.
#pragma once

#include <CLI/CLI.hpp>
#include <ostream>
#include <string>

#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/synthesis/synthesis_record.hpp"
#include "tools/cli/flags.hpp"

namespace shapeproc::cli {

struct DistributedFlags {
  bool distributed = false;
  bool merge = false;

  void add_to(CLI::App& command);
  // What can be refused before MPI starts: an output that is not a .csv, a picture, a trace,
  // several chains, --decompose off, --merge without --distributed, or a build without MPI.
  // Throws core::UsageError.
  void check(const SampleFlags& sample, const std::string& output) const;
};

// Samples `model` across the ranks of MPI_COMM_WORLD into `output`'s parts (or `output` itself
// with --merge). Rank 0 prints what `sample` prints; the others print nothing. Returns the exit
// code.
int run_distributed(const SampleFlags& sample, const DistributedFlags& flags,
                    const model::ShapeProcessModel& model, const std::string& output,
                    synthesis::SynthesisRecord record, std::ostream& out);

}  // namespace shapeproc::cli
