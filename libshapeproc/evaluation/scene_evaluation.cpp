#include "libshapeproc/evaluation/scene_evaluation.hpp"

#include <stdexcept>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/random.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"

namespace shapeproc::evaluation {

EvaluatedScene read_evaluated_scene(const std::string& file, io::ReaderOptions reader,
                                    BoundaryChoice boundary) {
  EvaluatedScene e;
  e.file = file;
  e.record = io::read_synthesis_record(file);
  // A shapeproc output is read as written (its elements are its groups): tiles are exemplars.
  if (e.record) reader.tile = false;
  reader.empty_outputs = true;  // a chain that ended empty is judged, not refused
  e.scene = io::read_scene(file, reader);
  // A synthesised output's window is its domain box, which its record holds: mesh files have no
  // window, and their elements' bounds (wrapped across a torus) are not it.
  if (e.record && static_cast<int>(e.record->size.size()) == e.scene.dimension) {
    geometry::Vec3 size = geometry::Vec3::Zero();
    for (int axis = 0; axis < e.scene.dimension; ++axis)
      size[axis] = e.record->size[static_cast<std::size_t>(axis)];
    e.scene.window = geometry::Box3(geometry::Vec3::Zero(), size);
  }
  if (boundary == BoundaryChoice::torus) {
    e.boundary = geometry::Boundary::torus;
  } else if (boundary == BoundaryChoice::automatic && e.record) {
    e.boundary = e.record->boundary;
  } else if (boundary == BoundaryChoice::automatic && reader.tile) {
    e.boundary = geometry::Boundary::torus;  // a seamless tile is one period of a torus
  }
  if (e.scene.elements.empty() && !e.record)
    throw core::InputError(file, 0, "the scene has no elements to measure");
  return e;
}

EvaluatedScene read_exemplar(const std::string& file, const io::ReaderOptions& reader,
                             const MetricOptions& options) {
  EvaluatedScene e = read_evaluated_scene(
      file, reader,
      options.boundary == BoundaryChoice::torus ? BoundaryChoice::automatic : options.boundary);
  if (e.scene.elements.empty())
    throw core::InputError(file, 0, "the exemplar has no elements to compare with");
  return e;
}

metrics::StatisticsOptions statistics_options(const EvaluatedScene& scene,
                                              const MetricOptions& options, double range) {
  if (!(options.range >= 0)) throw core::ArgumentError("evaluate", "the range must be positive");
  if (!(options.neighbourhood >= 0))
    throw core::ArgumentError("evaluate", "the neighbourhood must be positive");
  if (!(options.proxy_tolerance > 0 && options.proxy_tolerance < 1))
    throw core::ArgumentError("evaluate", "the proxy tolerance must be in (0, 1)");
  metrics::StatisticsOptions o;
  o.measurement.direction = options.direction;
  o.measurement.directions =
      geometry::directions_or_default(options.directions, scene.scene.dimension);
  o.measurement.periodic = scene.boundary == geometry::Boundary::torus;
  o.measurement.proxy.tolerance = options.proxy_tolerance;
  try {
    geometry::DirectionBins bins(scene.scene.dimension, o.measurement.directions);
  } catch (const std::invalid_argument& e) {
    throw core::UsageError(std::string("directions: ") + e.what());
  }
  o.edge = options.edge;
  o.range = range > 0 ? range : options.range;
  return o;
}

Evaluation evaluate(const EvaluatedScene& scene, const MetricOptions& options,
                    const EvaluatedScene* reference,
                    const metrics::SceneStatistics* reference_statistics,
                    const geometry::Scene* drawing) {
  Evaluation e;
  if (reference && reference->scene.dimension != scene.scene.dimension) {
    throw core::UsageError(scene.file + " is " + std::to_string(scene.scene.dimension) + "D but " +
                           reference->file + " is " + std::to_string(reference->scene.dimension) +
                           "D");
  }
  if (scene.scene.elements.empty())
    throw core::InputError(
        scene.file, 0, "the output holds no element (its chain ended empty): nothing to measure");
  const double range = reference_statistics ? reference_statistics->range : 0.0;
  e.statistics = metrics::compute_statistics(scene.scene, statistics_options(scene, options, range),
                                             core::Random(1));
  if (reference && reference_statistics) {
    e.comparison = metrics::compare(e.statistics, *reference_statistics);
    e.neighbourhood = metrics::average_neighbourhood_distance(
        scene.scene, scene.boundary, reference->scene, reference->boundary, options.neighbourhood);
    e.novelty = metrics::measure_novelty(drawing ? *drawing : reference->scene, scene.scene,
                                         scene.boundary);
  }
  return e;
}

}  // namespace shapeproc::evaluation
