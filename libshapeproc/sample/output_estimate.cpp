#include "libshapeproc/sample/output_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "libshapeproc/core/format.hpp"

namespace shapeproc::sample {

namespace {

std::string unit_of(int dimension) { return dimension == 3 ? "volume" : "area"; }

core::ResourceEstimate with_bytes(core::ResourceEstimate estimate, int chains_at_once) {
  estimate.bytes = estimate.elements * kBytesPerElement * std::max(1, chains_at_once);
  return estimate;
}

}  // namespace

core::ResourceEstimate estimate_output(double exemplar_density, const geometry::Domain& domain,
                                       int dimension, int chains_at_once) {
  const double measure = domain.measure();
  const std::string unit = unit_of(dimension);
  core::ResourceEstimate estimate;
  estimate.elements = exemplar_density * measure;
  estimate.basis = "the exemplar's " + core::format_general(exemplar_density, 3) +
                   " elements per unit " + unit + " times the domain's " + unit + " " +
                   core::format_general(measure, 3);
  return with_bytes(estimate, chains_at_once);
}

core::ResourceEstimate estimate_output(const model::ShapeProcessModel& model,
                                       const geometry::Domain& domain,
                                       std::optional<double> exemplar_density, int chains_at_once) {
  if (exemplar_density)
    return estimate_output(*exemplar_density, domain, model.dimension, chains_at_once);
  const double measure = domain.measure();
  const std::string unit = unit_of(model.dimension);
  double beta = 0;
  for (const model::CategoryParameters& c : model.categories) beta += c.beta;
  core::ResourceEstimate estimate;
  estimate.elements = beta * measure;
  estimate.basis = "the model's beta " + core::format_general(beta, 3) + " per unit " + unit +
                   " times the domain's " + unit + " " + core::format_general(measure, 3);
  return with_bytes(estimate, chains_at_once);
}

}  // namespace shapeproc::sample
