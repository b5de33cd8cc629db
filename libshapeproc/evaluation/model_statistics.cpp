#include "libshapeproc/evaluation/model_statistics.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <cmath>

#include "libshapeproc/geometry/pair_measurements.hpp"
#include "libshapeproc/model/interaction.hpp"

namespace shapeproc::evaluation {

PairCounts pair_counts(const geometry::Scene& scene, geometry::Boundary boundary,
                       const model::ShapeProcessModel& model) {
  const model::Interaction interaction(model);
  PairCounts c;
  c.pairs.assign(static_cast<std::size_t>(interaction.parameter_count()), 0.0);
  std::vector<geometry::Element> elements;
  for (geometry::Element e : scene.elements) {
    const std::string& name = scene.categories[static_cast<std::size_t>(e.category)].name;
    int category = -1;
    for (std::size_t m = 0; m < model.categories.size(); ++m)
      if (model.categories[m].name == name) category = static_cast<int>(m);
    if (category < 0) continue;
    e.category = category;
    elements.push_back(e);
  }
  c.elements = static_cast<int>(elements.size());
  if (elements.size() < 2) return c;
  const geometry::PairMeasurer measurer(
      scene, model.measurement_options(boundary == geometry::Boundary::torus));
  for (const geometry::PairRecord& p : measurer.all_pairs(elements, interaction.range())) {
    const geometry::Element& a = elements[static_cast<std::size_t>(p.i)];
    const geometry::Element& b = elements[static_cast<std::size_t>(p.j)];
    const int band =
        interaction.band(a.category, b.category, p.measurement.axis, p.measurement.distance);
    if (band == model::Interaction::kHardCore) ++c.hard_core;
    if (band < 0) continue;
    c.pairs[static_cast<std::size_t>(
        interaction.parameter(a.category, b.category, p.measurement.axis, band))] += 1.0;
  }
  return c;
}

ModelStatistics model_statistics(const geometry::Scene& exemplar,
                                 geometry::Boundary exemplar_boundary,
                                 const geometry::Scene& output, geometry::Boundary output_boundary,
                                 const model::ShapeProcessModel& model) {
  return model_statistics(pair_counts(exemplar, exemplar_boundary, model),
                          pair_counts(output, output_boundary, model), model);
}

ModelStatistics model_statistics(const PairCounts& ex, const PairCounts& out,
                                 const model::ShapeProcessModel& model) {
  const model::Interaction interaction(model);
  const std::vector<std::string> all_names = model::statistic_names(model);
  ModelStatistics s;
  s.exemplar_hard_core = ex.hard_core;
  s.output_hard_core = out.hard_core;
  if (ex.elements == 0 || out.elements == 0) return s;
  const double n_ex = ex.elements, n_out = out.elements;
  double worst = -1.0;
  for (int k = static_cast<int>(model.categories.size()); k < interaction.parameter_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    s.names.push_back(i < all_names.size() ? all_names[i] : "statistic " + std::to_string(k));
    s.exemplar.push_back(ex.pairs[i] / n_ex);
    s.output.push_back(out.pairs[i] / n_out);
    // Poisson counts; at least one pair's worth of error, so that an empty band is not exact.
    const double se = std::sqrt(std::max(ex.pairs[i], 1.0) / (n_ex * n_ex) +
                                std::max(out.pairs[i], 1.0) / (n_out * n_out));
    s.z.push_back((s.output.back() - s.exemplar.back()) / se);
    if (std::abs(s.z.back()) > worst) {
      worst = std::abs(s.z.back());
      s.worst = static_cast<int>(s.z.size()) - 1;
    }
  }
  if (!s.z.empty())
    s.critical = std::sqrt(2.0) * boost::math::erfc_inv(0.01 / static_cast<double>(s.z.size()));
  return s;
}

}  // namespace shapeproc::evaluation
