// One edit of a model as the studio's page makes it (a γ bar dragged, a threshold moved, a slider
// set, a button pressed), typed, applied through model/model_edits.hpp (the edits `shapeproc edit`
// makes) and described as `edit` records it in a model's history.
#pragma once

#include <cstddef>
#include <string>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::studio {

enum class EditKind {
  gamma,             // γ of band `index` (0-based) of `axis` of `pair` set to `value`
  threshold,         // δ_index of `axis` of `pair` set to `value`
  beta,              // β of category `index` set to `value`
  class_weight,      // shape class `index`'s share of its category's β set to `value`
  isotropic,         // every pair's axes averaged into one (model::make_isotropic)
  scale_thresholds,  // every threshold multiplied by `value`
};

struct ModelEdit {
  EditKind kind = EditKind::gamma;
  std::size_t pair = 0, axis = 0, index = 0;
  bool every_axis = false;  // gamma and threshold: the band or threshold of every axis of the pair
  double value = 0.0;
};

// The edited model. Throws core::ArgumentError naming what is wrong (an index out of range, a
// value not finite or out of its domain, thresholds out of order); `model` is never changed.
model::ShapeProcessModel apply_edit(const model::ShapeProcessModel& model, const ModelEdit& edit);

// The edit as a model's history records it, in `shapeproc edit`'s terms: "gamma 0:2:1=3",
// "threshold 0:*:1=12.5", "beta red=0.002", "class 1=0.4", "isotropic", "scale-thresholds 1.2".
std::string describe(const ModelEdit& edit, const model::ShapeProcessModel& model);

}  // namespace shapeproc::studio
