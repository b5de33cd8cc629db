// Drawing the interaction function (paper Fig. 4): per category pair, a polar plot whose sectors
// are the canonical directions (both halves of each axis) and whose rings are the distance bands,
// coloured by γ (black: hard core; red: γ < 1, repulsion; white: γ = 1; blue: γ > 1, attraction).
// 3D models are drawn as one bar per axis.
#pragma once

#include <filesystem>
#include <string>

#include "libshapeproc/model/shape_process_model.hpp"

namespace shapeproc::render {

std::string interaction_plot_svg(const model::ShapeProcessModel& model);
void write_interaction_plot(const model::ShapeProcessModel& model,
                            const std::filesystem::path& file);

}  // namespace shapeproc::render
