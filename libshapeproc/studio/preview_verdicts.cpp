#include "libshapeproc/studio/preview_verdicts.hpp"

#include "libshapeproc/evaluation/scene_evaluation.hpp"
#include "libshapeproc/geometry/tile_repeat.hpp"

namespace shapeproc::studio {

struct PreviewJudge::Exemplar {
  evaluation::EvaluatedScene measured;  // the exemplar, repeated where a small tile
  geometry::Scene drawing;              // as drawn, for novelty
  evaluation::Evaluation evaluation;
  evaluation::MetricOptions options;
};

PreviewJudge::PreviewJudge(const geometry::Scene& exemplar, bool tile) {
  auto e = std::make_unique<Exemplar>();
  e->drawing = exemplar;
  e->measured.file = "exemplar";
  e->measured.scene = exemplar;
  e->measured.boundary = tile ? geometry::Boundary::torus : geometry::Boundary::open;
  if (tile) {
    const int times = geometry::tile_repeats(exemplar.elements.size());
    if (times > 1) e->measured.scene = geometry::repeat_tile(exemplar, times);
  }
  e->evaluation = evaluation::evaluate(e->measured, e->options);
  exemplar_ = std::move(e);
}

PreviewJudge::~PreviewJudge() = default;

std::vector<evaluation::Verdict> PreviewJudge::judge(const geometry::Scene& output,
                                                     const model::ShapeProcessModel* model) const {
  if (output.elements.empty()) return {};
  evaluation::EvaluatedScene scene;
  scene.file = "preview";
  scene.scene = output;
  scene.boundary = geometry::Boundary::torus;
  const Exemplar& e = *exemplar_;
  const evaluation::Evaluation measured =
      evaluation::evaluate(scene, e.options, &e.measured, &e.evaluation.statistics, &e.drawing);
  const evaluation::ExemplarMeasures exemplar = evaluation::measure_exemplar(
      e.measured.scene, e.measured.boundary, e.evaluation.statistics, model);
  evaluation::Judged judged =
      evaluation::measure_for_verdicts(exemplar, output, scene.boundary, measured.statistics,
                                       *measured.comparison, &*measured.neighbourhood);
  judged.novelty = measured.novelty;
  return evaluation::judge(judged);
}

}  // namespace shapeproc::studio
