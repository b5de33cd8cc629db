#include "libshapeproc/studio/model_edit.hpp"

#include <cmath>
#include <stdexcept>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/model/model_edits.hpp"

namespace shapeproc::studio {

namespace {

void check_finite(const ModelEdit& edit, const char* what) {
  if (!std::isfinite(edit.value))
    throw core::ArgumentError(what, "the value must be a finite number");
}

// The axes of `pair` an edit names: one, or every one.
std::pair<std::size_t, std::size_t> axes_of(const model::ShapeProcessModel& model,
                                            const ModelEdit& edit, const char* what) {
  if (edit.pair >= model.interactions.size())
    throw core::ArgumentError(what, "no interaction " + std::to_string(edit.pair));
  const std::size_t axes = model.interactions[edit.pair].axes.size();
  if (edit.every_axis) return {0, axes};
  if (edit.axis >= axes)
    throw core::ArgumentError(what, "interaction " + std::to_string(edit.pair) + " has no axis " +
                                        std::to_string(edit.axis));
  return {edit.axis, edit.axis + 1};
}

}  // namespace

model::ShapeProcessModel apply_edit(const model::ShapeProcessModel& model, const ModelEdit& edit) {
  model::ShapeProcessModel m = model;
  switch (edit.kind) {
    case EditKind::gamma: {
      check_finite(edit, "gamma");
      const auto [first, last] = axes_of(m, edit, "gamma");
      for (std::size_t a = first; a < last; ++a)
        model::set_gamma(m, edit.pair, a, edit.index, edit.value);
      break;
    }
    case EditKind::threshold: {
      check_finite(edit, "threshold");
      const auto [first, last] = axes_of(m, edit, "threshold");
      for (std::size_t a = first; a < last; ++a)
        model::set_threshold(m, edit.pair, a, edit.index, edit.value);
      break;
    }
    case EditKind::beta:
      check_finite(edit, "beta");
      if (!(edit.value > 0)) throw core::ArgumentError("beta", "beta must be positive");
      model::set_intensity(m, edit.index, edit.value);
      break;
    case EditKind::class_weight:
      model::set_class_weight(m, edit.index, edit.value);
      break;
    case EditKind::isotropic:
      model::make_isotropic(m);
      break;
    case EditKind::scale_thresholds:
      model::scale_thresholds(m, edit.value);
      break;
  }
  try {
    model::validate(m);
  } catch (const std::invalid_argument& e) {
    throw core::ArgumentError("edit", std::string("the edited model is invalid: ") + e.what());
  }
  return m;
}

std::string describe(const ModelEdit& edit, const model::ShapeProcessModel& model) {
  const std::string value = core::format_number(edit.value);
  const std::string axis = edit.every_axis ? "*" : std::to_string(edit.axis);
  switch (edit.kind) {
    case EditKind::gamma:
      return "gamma " + std::to_string(edit.pair) + ":" + axis + ":" +
             std::to_string(edit.index + 1) + "=" + value;
    case EditKind::threshold:
      return "threshold " + std::to_string(edit.pair) + ":" + axis + ":" +
             std::to_string(edit.index) + "=" + value;
    case EditKind::beta:
      return "beta " +
             (edit.index < model.categories.size() ? model.categories[edit.index].name
                                                   : std::to_string(edit.index)) +
             "=" + value;
    case EditKind::class_weight:
      return "class " + std::to_string(edit.index) + "=" + value;
    case EditKind::isotropic:
      return "isotropic";
    case EditKind::scale_thresholds:
      return "scale-thresholds " + value;
  }
  return {};
}

}  // namespace shapeproc::studio
