#include "libshapeproc/fit/detail/model_assembly.hpp"

#include <cmath>
#include <limits>

namespace shapeproc::fit {

using model::Interaction;

void assign_estimates(model::ShapeProcessModel& model, const Interaction& interaction,
                      const MpleResult& mple) {
  for (int p = 0; p < interaction.parameter_count(); ++p) {
    const double theta = mple.theta[static_cast<std::size_t>(p)];
    const double se = mple.standard_errors[static_cast<std::size_t>(p)];
    const Interaction::Location where = interaction.locate(p);
    if (where.pair < 0) {
      model::CategoryParameters& c = model.categories[static_cast<std::size_t>(where.axis)];
      c.beta = std::exp(theta);
      c.beta_status = mple.status[static_cast<std::size_t>(p)];
      c.beta_standard_error = c.beta_status == model::ParameterStatus::free
                                  ? c.beta * se
                                  : std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    model::AxisParameters& axis = model.interactions[static_cast<std::size_t>(where.pair)]
                                      .axes[static_cast<std::size_t>(where.axis)];
    const std::size_t k = static_cast<std::size_t>(where.band);
    axis.status[k] = mple.status[static_cast<std::size_t>(p)];
    axis.gammas[k] = std::exp(theta);  // exp(−∞) = 0 on the boundary
    axis.gamma_standard_errors[k] = axis.status[k] == model::ParameterStatus::free
                                        ? axis.gammas[k] * se
                                        : std::numeric_limits<double>::quiet_NaN();
  }
}

model::FitRecord pseudo_likelihood_record(const geometry::Scene& exemplar,
                                          const FitOptions& options, const FitResult& result,
                                          int cells_along, const MpleResult& mple) {
  const auto dimension = static_cast<std::ptrdiff_t>(exemplar.dimension);
  model::FitRecord r;
  r.window_min.assign(exemplar.window.min().data(), exemplar.window.min().data() + dimension);
  r.window_max.assign(exemplar.window.max().data(), exemplar.window.max().data() + dimension);
  r.elements = static_cast<long long>(exemplar.elements.size());
  r.edge = edge_name(options);
  if (options.thresholds.empty())
    r.quantiles = options.quantiles;
  else
    r.thresholds = options.thresholds;
  r.quadrature = {result.quadrature_lines,     result.quadrature_cells, cells_along,
                  options.shapes_per_location, options.refinement,      result.quadrature_points,
                  options.data_weight};
  r.data_points = result.data_points;
  r.log_pseudo_likelihood = result.log_pseudo_likelihood;
  r.optimiser = "NLopt LD_LBFGS, then Newton";
  r.evaluations = mple.evaluations;
  r.newton_steps = mple.newton_steps;
  r.notes = result.notes;
  r.seconds = {result.seconds.proxies, result.seconds.measurements, result.seconds.quadrature,
               result.seconds.optimisation};
  r.version = SHAPEPROC_VERSION;
  return r;
}

}  // namespace shapeproc::fit
