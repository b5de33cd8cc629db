#include "libshapeproc/fit/model_assembly.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

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

std::string fit_record_json(const geometry::Scene& exemplar, const FitOptions& options,
                            const FitResult& result, int cells_along, const MpleResult& mple) {
  const int dimension = exemplar.dimension;
  const bool fixed_thresholds = !options.thresholds.empty();
  const nlohmann::json fit = {
      {"window",
       {{"min", std::vector<double>(exemplar.window.min().data(),
                                    exemplar.window.min().data() + dimension)},
        {"max", std::vector<double>(exemplar.window.max().data(),
                                    exemplar.window.max().data() + dimension)}}},
      {"elements", exemplar.elements.size()},
      {"edge", edge_name(options)},
      {"quantiles", fixed_thresholds ? nlohmann::json() : nlohmann::json(options.quantiles)},
      {"thresholds", fixed_thresholds ? nlohmann::json(options.thresholds) : nlohmann::json()},
      {"quadrature",
       {{"method", result.quadrature_lines ? "lines" : "cells"},
        {"cells", result.quadrature_cells},
        {"cells_along_longest_side", cells_along},
        {"shapes_per_location", options.shapes_per_location},
        {"refinement", options.refinement},
        {"points", result.quadrature_points},
        {"data_weight", options.data_weight}}},
      {"data_points", result.data_points},
      {"log_pseudo_likelihood", result.log_pseudo_likelihood},
      {"optimiser",
       {{"method", "NLopt LD_LBFGS, then Newton"},
        {"evaluations", mple.evaluations},
        {"newton_steps", mple.newton_steps}}},
      {"notes", result.notes},
      {"seconds",
       {{"proxies", result.seconds.proxies},
        {"measurements", result.seconds.measurements},
        {"quadrature", result.seconds.quadrature},
        {"optimisation", result.seconds.optimisation}}},
      {"version", SHAPEPROC_VERSION}};
  return fit.dump();
}

}  // namespace shapeproc::fit
