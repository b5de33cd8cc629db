#include "libshapeproc/model/model_edits.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::model {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void check_factor(const char* edit, double factor) {
  if (!(factor > 0) || !std::isfinite(factor))
    throw core::ArgumentError(
        edit, "the factor must be positive and finite, got " + std::to_string(factor));
}

AxisParameters& axis_of(ShapeProcessModel& model, std::size_t pair, std::size_t axis) {
  if (pair >= model.interactions.size())
    throw core::ArgumentError("edit", "no interaction " + std::to_string(pair));
  auto& axes = model.interactions[pair].axes;
  if (axis >= axes.size())
    throw core::ArgumentError(
        "edit", "interaction " + std::to_string(pair) + " has no axis " + std::to_string(axis));
  return axes[axis];
}

// The model valid after an edit, or the edit refused.
void check_valid(const ShapeProcessModel& model, const char* edit) {
  try {
    validate(model);
  } catch (const std::invalid_argument& e) {
    throw core::ArgumentError(edit, std::string("the edited model is invalid: ") + e.what());
  }
}

}  // namespace

void make_isotropic(ShapeProcessModel& model) {
  for (PairInteraction& pair : model.interactions) {
    AxisParameters one = pair.axes.front();
    for (std::size_t a = 1; a < pair.axes.size(); ++a) {
      if (pair.axes[a].thresholds.size() != one.thresholds.size())
        throw core::ArgumentError("isotropic",
                                  "the axes of a pair have different numbers of bands");
      for (std::size_t k = 0; k < one.thresholds.size(); ++k)
        one.thresholds[k] += pair.axes[a].thresholds[k];
      for (std::size_t k = 0; k < one.gammas.size(); ++k) one.gammas[k] += pair.axes[a].gammas[k];
    }
    const double axes = static_cast<double>(pair.axes.size());
    for (double& t : one.thresholds) t /= axes;
    for (double& g : one.gammas) g /= axes;
    one.direction = geometry::Vec3::UnitX();
    one.gamma_standard_errors.assign(one.gammas.size(), kNaN);
    one.status.assign(one.gammas.size(), ParameterStatus::fixed);
    one.observed_pairs.clear();
    pair.axes = {one};
  }
  model.measurement.directions = 1;
}

void scale_intensities(ShapeProcessModel& model, double factor) {
  check_factor("scale-beta", factor);
  for (const CategoryParameters& c : model.categories)
    if (!std::isfinite(c.beta * factor))
      throw core::ArgumentError(
          "scale-beta", "category '" + c.name + "': beta " + core::format_general(c.beta, 6) +
                            " times " + core::format_general(factor, 6) + " is not finite");
  for (CategoryParameters& c : model.categories) {
    c.beta *= factor;
    c.beta_standard_error *= factor;
  }
}

void scale_thresholds(ShapeProcessModel& model, double factor) {
  check_factor("scale-thresholds", factor);
  for (PairInteraction& pair : model.interactions)
    for (AxisParameters& axis : pair.axes)
      for (double& t : axis.thresholds) t *= factor;
  check_valid(model, "scale-thresholds");
}

void set_intensity(ShapeProcessModel& model, std::size_t category, double beta) {
  if (category >= model.categories.size())
    throw core::ArgumentError("beta", "no category " + std::to_string(category));
  CategoryParameters& c = model.categories[category];
  c.beta = beta;
  c.beta_standard_error = kNaN;
  c.beta_status = ParameterStatus::fixed;
  check_valid(model, "beta");
}

void set_class_weight(ShapeProcessModel& model, std::size_t shape_class, double weight) {
  if (shape_class >= model.shape_classes.size())
    throw core::ArgumentError("class", "no shape class " + std::to_string(shape_class));
  if (!(weight > 0) || !std::isfinite(weight))
    throw core::ArgumentError(
        "class", "the weight must be positive and finite, got " + core::format_general(weight, 6));
  model.shape_classes[shape_class].weight = weight;
  check_valid(model, "class");
}

void set_gamma(ShapeProcessModel& model, std::size_t pair, std::size_t axis, std::size_t band,
               double gamma) {
  AxisParameters& a = axis_of(model, pair, axis);
  if (band >= a.gammas.size())
    throw core::ArgumentError("gamma", "the axis has no band " + std::to_string(band + 1));
  a.gammas[band] = gamma;
  if (band < a.status.size()) a.status[band] = ParameterStatus::fixed;
  if (band < a.gamma_standard_errors.size()) a.gamma_standard_errors[band] = kNaN;
  check_valid(model, "gamma");
}

void set_threshold(ShapeProcessModel& model, std::size_t pair, std::size_t axis, std::size_t index,
                   double value) {
  AxisParameters& a = axis_of(model, pair, axis);
  if (index >= a.thresholds.size())
    throw core::ArgumentError("threshold", "the axis has no threshold " + std::to_string(index));
  a.thresholds[index] = value;
}

}  // namespace shapeproc::model
