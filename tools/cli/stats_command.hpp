// Shared by `shapeproc stats` and `shapeproc report`: reading a scene to evaluate (with its torus
// or open boundary), the metric options on the command line, and the metrics as JSON.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/metrics/neighbourhood_distance.hpp"
#include "libshapeproc/metrics/novelty.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/synthesis/synthesis_record.hpp"
#include "tools/cli/common.hpp"

namespace shapeproc::cli {

struct EvaluatedScene {
  std::string file;
  geometry::Scene scene;
  geometry::Boundary boundary = geometry::Boundary::open;
  std::optional<synthesis::SynthesisRecord> record;  // a synthesised output's record, else none
};

// Reads `file`; the boundary is `boundary` (torus|open), or with "auto" the one recorded in a
// synthesised output's record (open for anything else).
EvaluatedScene read_evaluated_scene(const std::string& file, const ReaderFlags& reader,
                                    const std::string& boundary);

struct MetricFlags;
// The exemplar side of a comparison: open, unless its own record says torus (`--boundary`
// names the outputs' boundary, not the exemplar's).
EvaluatedScene read_exemplar(const std::string& file, const ReaderFlags& reader,
                             const MetricFlags& flags);

struct MetricFlags {
  std::string boundary = "auto";
  std::string edge = "auto";
  double range = 0.0;
  double neighbourhood = 0.0;
  int directions = 0;
  std::string direction = "gravitation";
  double proxy_tolerance = metrics::StatisticsOptions::default_measurement().proxy.tolerance;

  void add_to(CLI::App& command);
  // Options for one scene: torus or open, direction bins for its dimension. Throws UsageError.
  metrics::StatisticsOptions options(const EvaluatedScene& scene, double range) const;
  nlohmann::json to_json() const;
};

struct Evaluation {
  metrics::SceneStatistics statistics;
  std::optional<metrics::Comparison> comparison;
  std::optional<metrics::NeighbourhoodDistance> neighbourhood;
  std::optional<metrics::Novelty> novelty;  // against a reference
};

// Statistics of `scene`; against a reference, at the reference's range and compared with it.
// Novelty is measured against `drawing` when given (a tile the reference repeats), else against
// the reference's scene.
Evaluation evaluate(const EvaluatedScene& scene, const MetricFlags& flags,
                    const EvaluatedScene* reference = nullptr,
                    const metrics::SceneStatistics* reference_statistics = nullptr,
                    const geometry::Scene* drawing = nullptr);

nlohmann::json evaluation_json(const EvaluatedScene& scene, const Evaluation& evaluation);

}  // namespace shapeproc::cli
