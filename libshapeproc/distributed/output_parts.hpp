// A distributed output on disk (docs/sample.md, "Sampling across processes"). Each rank writes
// its own elements as a CSV part, in the placements format `sample -o out.csv` writes
// (io::write_csv), so no rank ever holds more than its block. Rank 0 then writes a manifest that
// lists the parts in order with their element counts and the run's record. A merge streams the
// parts, in that order, into one CSV and its JSON sidecar: byte for byte the file `sample
// --decompose on` writes with the same seed, whatever the number of ranks.
//
// CSV because every reader of the project and most tools read it, and because parts in rank order
// concatenate into the whole: a format for large point sets would need a writer that every rank
// shares, for no gain at these sizes (about 40 bytes an element, 4 GB for 10^8).
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "libshapeproc/distributed/distributed_sampling.hpp"
#include "libshapeproc/io/scene_writers.hpp"

namespace shapeproc::distributed {

struct OutputFiles {
  std::vector<std::string> parts;  // in rank order
  std::string manifest;
};

// The files of an output written to `output` (a .csv) by `ranks` ranks: out.csv gives
// out-part-1-of-3.csv, … and out.parts.json.
OutputFiles output_files(const std::string& output, int ranks);

// Writes this rank's part; on rank 0, once every part is written, the manifest. With `merge`,
// rank 0 then joins the parts into `output` (with `output`.json holding `provenance`) and
// removes the parts and the manifest. Every rank of `communicator` calls it. A rank that fails to
// write makes every rank throw (core::InputError naming the file), and nothing half-written is
// left in place. Returns the files the run leaves.
std::vector<std::string> write_output(const DistributedSample& sample, const std::string& output,
                                      const io::Provenance& provenance, bool merge,
                                      MPI_Comm communicator);

}  // namespace shapeproc::distributed
