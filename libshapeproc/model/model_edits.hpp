// Edits of a model (Landes et al. 2013, §7.3): a new pattern from a learned one. Each edit keeps
// the model valid or throws core::ArgumentError naming what is wrong; parameters set by hand become
// fixed, without a standard error. `shapeproc edit` parses its options into these calls.
#pragma once

#include <cstddef>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::model {

// One axis per category pair: its thresholds and γ the means over the pair's axes (γ
// arithmetically, so that a strongly inhibiting band stays one), and one canonical direction.
// Throws where a pair's axes have different numbers of bands.
void make_isotropic(ShapeProcessModel& model);

// Every β (and its standard error) multiplied by `factor` > 0; throws where a β would not stay
// finite.
void scale_intensities(ShapeProcessModel& model, double factor);

// Every threshold multiplied by `factor` > 0 (the pattern's distances scaled); throws where one
// would not stay finite.
void scale_thresholds(ShapeProcessModel& model, double factor);

// β of `category` set to `beta` >= 0.
void set_intensity(ShapeProcessModel& model, std::size_t category, double beta);

// γ of band `band` (0-based) of axis `axis` of interaction `pair` set to `gamma` >= 0.
void set_gamma(ShapeProcessModel& model, std::size_t pair, std::size_t axis, std::size_t band,
               double gamma);

// The share `weight` > 0 (finite) of shape class `shape_class` in its category's β.
void set_class_weight(ShapeProcessModel& model, std::size_t shape_class, double weight);

// Threshold δ_index of axis `axis` of interaction `pair` set to `value`; the thresholds must stay
// finite, >= 0 and in order (validate).
void set_threshold(ShapeProcessModel& model, std::size_t pair, std::size_t axis, std::size_t index,
                   double value);

}  // namespace shapeproc::model
