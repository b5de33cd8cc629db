// The verdicts of a preview against the exemplar (evaluation/verdicts.hpp: density, shape mix,
// overlaps, touching, order, spacing, the model's statistics and novelty), measured as `compare`
// measures them: the exemplar once, each preview against it.
#pragma once

#include <memory>
#include <vector>

#include "libshapeproc/evaluation/verdicts.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::studio {

class PreviewJudge {
 public:
  // `tile`: the exemplar is one period of a seamless repeat (measured on its torus, as a repeat
  // of itself where it holds few elements; novelty against the tile itself).
  PreviewJudge(const geometry::Scene& exemplar, bool tile);
  ~PreviewJudge();
  PreviewJudge(const PreviewJudge&) = delete;
  PreviewJudge& operator=(const PreviewJudge&) = delete;

  // The verdicts of `output` (sampled on a torus) against the exemplar, the model's statistics
  // with `model` (the edited model: its pairs per band against the exemplar's). An empty output
  // has none.
  std::vector<evaluation::Verdict> judge(const geometry::Scene& output,
                                         const model::ShapeProcessModel* model) const;

 private:
  struct Exemplar;
  std::unique_ptr<const Exemplar> exemplar_;
};

}  // namespace shapeproc::studio
