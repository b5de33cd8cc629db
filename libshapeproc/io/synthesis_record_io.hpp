// A synthesised output's record in its provenance (io::Provenance): written with the output by
// write_scene, read back by `stats --boundary auto`, the report and the comparison. The JSON
// object is {"tool", "version", "command", "arguments", "synthesis": {the record's fields}}.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "libshapeproc/io/scene_writers.hpp"
#include "libshapeproc/synthesis/synthesis_record.hpp"

namespace shapeproc::io {

// The provenance of a synthesised output (its `seconds` are not written: the same seed gives the
// same bytes).
Provenance synthesis_provenance(const synthesis::SynthesisRecord& record);

// The record carried by a provenance text, or nullopt when the text is not a synthesis record
// (another command's provenance, or none). Throws core::InputError naming `source` when the
// record is there but malformed.
std::optional<synthesis::SynthesisRecord> parse_synthesis_record(const std::string& provenance,
                                                                 const std::string& source);

// The record inside a shapeproc output file, or nullopt.
std::optional<synthesis::SynthesisRecord> read_synthesis_record(const std::filesystem::path& file);

}  // namespace shapeproc::io
