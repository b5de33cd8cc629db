// The readable summary of a model that `fit` and `show` print.
#pragma once

#include <ostream>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::cli {

void print_model_summary(const model::ShapeProcessModel& model, std::ostream& out);

}  // namespace shapeproc::cli
