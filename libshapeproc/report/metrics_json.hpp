// The metrics as JSON: what `stats --json` prints and `report` writes into metrics.json (every
// measure of a scene, and against an exemplar its distances, neighbourhood distance and novelty).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "libshapeproc/evaluation/scene_evaluation.hpp"

namespace shapeproc::report {

nlohmann::json evaluation_json(const evaluation::EvaluatedScene& scene,
                               const evaluation::Evaluation& evaluation);

// The options the metrics were taken with, by the names `stats` and `report` give them.
nlohmann::json metric_options_json(const evaluation::MetricOptions& options);

}  // namespace shapeproc::report
