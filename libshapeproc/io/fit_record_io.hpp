// The model file's "fit" object (docs/model-format.md): a model::FitRecord as JSON, and back.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "libshapeproc/model/fit_record.hpp"

namespace shapeproc::io {

nlohmann::json fit_record_json(const model::FitRecord& record);

// The record a "fit" object holds. A field that is missing or of another type keeps its default
// (the object is provenance that a person may have edited by hand): only the fit's own writer
// guarantees every field.
model::FitRecord parse_fit_record(const nlohmann::json& fit);

}  // namespace shapeproc::io
