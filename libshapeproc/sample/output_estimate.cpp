#include "libshapeproc/sample/output_estimate.hpp"

#include <algorithm>

#include "libshapeproc/core/format.hpp"

namespace shapeproc::sample {

core::ResourceEstimate estimate_output(const model::ShapeProcessModel& model,
                                       const geometry::Domain& domain,
                                       std::optional<double> exemplar_density, int chains_at_once) {
  const double measure = domain.measure();
  const std::string unit = model.dimension == 3 ? "volume" : "area";
  core::ResourceEstimate estimate;
  if (exemplar_density) {
    estimate.elements = *exemplar_density * measure;
    estimate.basis = "the exemplar's " + core::format_general(*exemplar_density, 3) +
                     " elements per unit " + unit + " times the domain's " + unit + " " +
                     core::format_general(measure, 3);
  } else {
    double beta = 0;
    for (const model::CategoryParameters& c : model.categories) beta += c.beta;
    estimate.elements = beta * measure;
    estimate.basis = "the model's beta " + core::format_general(beta, 3) + " per unit " + unit +
                     " times the domain's " + unit + " " + core::format_general(measure, 3);
  }
  estimate.bytes = estimate.elements * kBytesPerElement * std::max(1, chains_at_once);
  return estimate;
}

}  // namespace shapeproc::sample
