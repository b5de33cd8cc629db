// The pair measurements as CSV (`shapeproc measure`): one row per pair,
// i,j,distance,ox,oy[,oz],axis (the direction's components and the axis bin), numbers written
// exactly.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/io/scene_writers.hpp"

namespace shapeproc::io {

// The header line and one row per pair; `dimension` 3 adds the direction's z.
void write_pairs_csv(std::ostream& out, int dimension,
                     const std::vector<geometry::PairRecord>& pairs);

// The same into `file`, with `provenance` in the sidecar FILE.json, both written atomically.
void write_pairs_csv(const std::filesystem::path& file, int dimension,
                     const std::vector<geometry::PairRecord>& pairs, const Provenance& provenance);

}  // namespace shapeproc::io
