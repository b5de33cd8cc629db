// The model file's "neighbour_offsets" object (docs/model-format.md): a model's
// model::NeighbourOffsets as JSON, and back.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::io {

// {"share": s, "radii": [r, ...], "offsets": [[from, to, x, y(, z), weight], ...]} ("share" may be
// left out: 0).
nlohmann::json neighbour_offsets_json(const model::NeighbourOffsets& offsets, int dimension);

// The offsets an object holds; a malformed one is a core::InputError naming `file_name` and the
// field. Ranges (kinds, weights, radii) are model::validate's.
model::NeighbourOffsets parse_neighbour_offsets(const nlohmann::json& object, int dimension,
                                                const std::string& file_name);

}  // namespace shapeproc::io
