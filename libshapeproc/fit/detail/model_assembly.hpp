// The last step of the fit: the estimates θ̂ written into the model (β = exp θ_c, γ = exp θ_p,
// standard errors by the delta method, statuses), and the fit's record in the model file.
#pragma once

#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/fit/pseudo_likelihood.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::fit {

void assign_estimates(model::ShapeProcessModel& model, const model::Interaction& interaction,
                      const MpleResult& mple);

// The pseudo-likelihood fit's record: window, options, quadrature, optimiser, notes and times.
model::FitRecord pseudo_likelihood_record(const geometry::Scene& exemplar,
                                          const FitOptions& options, const FitResult& result,
                                          int cells_along, const MpleResult& mple);

}  // namespace shapeproc::fit
