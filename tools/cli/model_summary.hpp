// The readable summaries of a model that `fit`, `show` and `synthesize` print.
#pragma once

#include <ostream>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::cli {

void print_model_summary(const model::ShapeProcessModel& model, std::ostream& out);
// Two or three lines for `synthesize`: categories with β, interaction bands and range, the fit's
// notes (unbounded estimates); `shapeproc show MODEL` prints the whole summary.
void print_model_brief(const model::ShapeProcessModel& model, std::ostream& out);

}  // namespace shapeproc::cli
