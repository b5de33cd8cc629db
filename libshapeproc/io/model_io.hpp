// The model file (docs/model-format.md): JSON that users read and edit.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::io {

// Reads and validates a model file. Throws InputError ("FILE:LINE: ..." for JSON syntax,
// "FILE: interaction[0].axes[1].gammas[0]: ..." for bad values).
model::ShapeProcessModel read_model(const std::filesystem::path& file);
model::ShapeProcessModel parse_model(std::string_view text, const std::string& file_name);

// The model as JSON text (2-space indentation), and written atomically to a file.
std::string model_to_json(const model::ShapeProcessModel& model);

// The density (elements per unit area or volume) of the exemplar the model was fitted to, from
// its `fit` record; nullopt when the model has none, or was edited since (its `fit.edits`).
std::optional<double> recorded_exemplar_density(const model::ShapeProcessModel& model);
void write_model(const model::ShapeProcessModel& model, const std::filesystem::path& file);

}  // namespace shapeproc::io
