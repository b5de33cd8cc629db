// A self-contained HTML report comparing an exemplar with synthesised outputs (docs/report.md):
// each output's verdicts (evaluation/verdicts.hpp) and a one-line summary at the top,
// pictures at one scale with colliding elements in red, the interaction function, per-axis
// distance CDFs, G(r) and g(r), a metrics table and timings. No network: charts are inline SVG,
// pictures are PNGs beside index.html (rendered with Cairo).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "libshapeproc/evaluation/envelope.hpp"
#include "libshapeproc/evaluation/verdicts.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/metrics/neighbourhood_distance.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::report {

struct ReportScene {
  std::string label;  // the file name as the user gave it
  const geometry::Scene* scene = nullptr;
  const metrics::SceneStatistics* statistics = nullptr;
  const metrics::Comparison* comparison = nullptr;                // outputs only
  const metrics::NeighbourhoodDistance* neighbourhood = nullptr;  // outputs only
  std::string note;  // how it was made (seed, steps, boundary), when known
  const std::vector<evaluation::Verdict>* verdicts = nullptr;  // outputs only, optional
};

// One sufficient statistic of a maximum-likelihood fit: the exemplar's value against the fitted
// model's mean on the exemplar's window (fit/fit_maximum_likelihood.hpp).
struct GoodnessRow {
  std::string statistic;
  double exemplar = 0.0, model = 0.0, standard_error = 0.0, z = 0.0;
  bool penalised = false;  // held down by the fit's attraction prior
};

struct Report {
  ReportScene exemplar;
  std::vector<ReportScene> outputs;
  const model::ShapeProcessModel* model = nullptr;  // optional
  std::string model_label;
  std::string command;                                  // the command that wrote the report
  std::vector<std::pair<std::string, double>> timings;  // stage, seconds
  std::vector<GoodnessRow> goodness;  // the model's goodness of fit, when it has one
  std::string goodness_note;          // how the fit ended ("converged in 12 iterations")
  std::vector<evaluation::EnvelopeCurve> envelopes;  // the model's, on the exemplar's window
  int envelope_samples = 0;
};

// Writes `directory`/index.html and the pictures exemplar.png, output-1.png, … (and
// interaction.svg with a model). Creates the directory; every file is written atomically.
// Throws std::invalid_argument when a scene or its statistics are missing.
void write_report(const Report& report, const std::filesystem::path& directory);

// The pixels per unit length at which the report draws its scenes: the exemplar's longer side at
// most 420 px and the largest output's at most 840 px, one scale for all.
double picture_scale(const Report& report);

}  // namespace shapeproc::report
