// An exemplar or an output as it is judged: read with its boundary (a synthesised output's own,
// a seamless tile's torus, else open), measured (docs/metrics.md), and, against an exemplar,
// compared with it: distances between their distributions, the neighbourhood distance and
// novelty. What `shapeproc stats` prints and `report` and `compare` tabulate.
#pragma once

#include <optional>
#include <string>

#include "libshapeproc/geometry/directions.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/metrics/neighbourhood_distance.hpp"
#include "libshapeproc/metrics/novelty.hpp"
#include "libshapeproc/metrics/scene_statistics.hpp"
#include "libshapeproc/synthesis/synthesis_record.hpp"

namespace shapeproc::evaluation {

// Which boundary a scene is measured with: automatic (a synthesised output's own, a seamless
// tile's torus, else open), or the one given.
enum class BoundaryChoice { automatic, torus, open };

struct MetricOptions {
  BoundaryChoice boundary = BoundaryChoice::automatic;
  metrics::EdgeTreatment edge = metrics::EdgeTreatment::automatic;  // of open windows
  double range = 0.0;          // 0: the exemplar's mean spacing
  double neighbourhood = 0.0;  // 0: twice the exemplar's mean spacing
  int directions = 0;          // 0: the dimension's default
  geometry::DirectionKind direction = geometry::DirectionKind::gravitation;
  double proxy_tolerance = metrics::StatisticsOptions::default_measurement().proxy.tolerance;
};

struct EvaluatedScene {
  std::string file;
  geometry::Scene scene;
  geometry::Boundary boundary = geometry::Boundary::open;
  std::optional<synthesis::SynthesisRecord> record;  // a synthesised output's record, else none
};

// Reads `file` with `reader` (a synthesised output as written: its elements are its groups, and
// its window is its domain's box); the boundary is `boundary`'s. A synthesised output may be
// empty (a chain that ended with no element); throws core::InputError for any other scene
// without elements.
EvaluatedScene read_evaluated_scene(const std::string& file, io::ReaderOptions reader,
                                    BoundaryChoice boundary);

// The exemplar side of a comparison: open, unless its own record or --tile says torus (a torus
// boundary in the options names the outputs', not the exemplar's).
EvaluatedScene read_exemplar(const std::string& file, const io::ReaderOptions& reader,
                             const MetricOptions& options);

// The measurement options for `scene`: its torus or open window, the direction bins of its
// dimension, and `range` when positive (else the options'). Throws core::ArgumentError for
// options out of their domain, core::UsageError for a direction count the dimension has no bins
// for.
metrics::StatisticsOptions statistics_options(const EvaluatedScene& scene,
                                              const MetricOptions& options, double range);

struct Evaluation {
  metrics::SceneStatistics statistics;
  std::optional<metrics::Comparison> comparison;
  std::optional<metrics::NeighbourhoodDistance> neighbourhood;
  std::optional<metrics::Novelty> novelty;  // against a reference
};

// Statistics of `scene`; against a reference, at the reference's range and compared with it.
// Novelty is measured against `drawing` when given (a tile the reference repeats), else against
// the reference's scene. Throws core::UsageError for a reference of another dimension.
Evaluation evaluate(const EvaluatedScene& scene, const MetricOptions& options,
                    const EvaluatedScene* reference = nullptr,
                    const metrics::SceneStatistics* reference_statistics = nullptr,
                    const geometry::Scene* drawing = nullptr);

}  // namespace shapeproc::evaluation
