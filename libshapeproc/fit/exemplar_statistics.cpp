#include "libshapeproc/fit/exemplar_statistics.hpp"

#include <sstream>

#include "libshapeproc/core/check.hpp"
#include "libshapeproc/model/saturation.hpp"

namespace shapeproc::fit {

using geometry::Element;
using model::Interaction;

namespace {
constexpr double kBorderTolerance = 1e-9;  // of the window's longest side

// Each element's own counts in the saturated bands, and its statistic there,
// t(z_n | z \ z_n) (model/saturation.hpp): a neighbour's own count without z_n is its count in z
// less one.
void add_saturated_counts(const Interaction& interaction,
                          const std::vector<std::vector<std::pair<int, int>>>& saturated,
                          ExemplarStatistics& s) {
  s.own_saturated.resize(saturated.size());
  for (std::size_t k = 0; k < saturated.size(); ++k)
    for (const auto& [j, parameter] : saturated[k]) s.own_saturated[k].add(parameter);
  for (std::size_t k = 0; k < saturated.size(); ++k) {
    const model::InteractionCounts counts =
        model::saturated_counts(interaction, saturated[k], [&](int j, int parameter) {
          return s.own_saturated[static_cast<std::size_t>(j)].count_of(parameter) - 1;
        });
    for (const auto& [parameter, count] : counts.counts) s.per_element[k].add(parameter, count);
  }
}

}  // namespace

FitRegion fit_region(const geometry::Scene& exemplar, geometry::EdgeTreatment edge, double range) {
  FitRegion region{exemplar.window, exemplar.dimension};
  if (edge != geometry::EdgeTreatment::border) return region;
  region.tolerance = kBorderTolerance * exemplar.window.sizes().head(exemplar.dimension).maxCoeff();
  for (int axis = 0; axis < exemplar.dimension; ++axis) {
    region.box.min()[axis] += range;
    region.box.max()[axis] -= range;
    core::check(region.box.max()[axis] > region.box.min()[axis], "fit",
                "the border edge treatment leaves no window (the interaction range " +
                    core::describe(range) +
                    " is at least half the window); use no edge treatment or a periodic one");
  }
  return region;
}

ExemplarStatistics exemplar_statistics(const geometry::Scene& exemplar,
                                       const std::vector<geometry::PairRecord>& pairs,
                                       const Interaction& interaction, const FitRegion& region,
                                       model::ShapeProcessModel& model) {
  const std::size_t n = exemplar.elements.size();
  ExemplarStatistics s;
  s.per_element.resize(n);
  // Per element, its neighbours in saturated bands: (element, θ index).
  std::vector<std::vector<std::pair<int, int>>> saturated(interaction.saturated() ? n : 0);
  for (const geometry::PairRecord& p : pairs) {
    const Element& a = exemplar.elements[static_cast<std::size_t>(p.i)];
    const Element& b = exemplar.elements[static_cast<std::size_t>(p.j)];
    const int band =
        interaction.band(a.category, b.category, p.measurement.axis, p.measurement.distance);
    if (band == Interaction::kHardCore) {
      std::ostringstream text;
      text << "elements " << p.i << " and " << p.j << " (categories '"
           << model.categories[static_cast<std::size_t>(a.category)].name << "' and '"
           << model.categories[static_cast<std::size_t>(b.category)].name << "') are "
           << p.measurement.distance << " apart (below 0: overlapping by that depth), below the "
           << "first threshold given, "
           << interaction.thresholds(a.category, b.category, p.measurement.axis).front()
           << ": give thresholds that start at or below " << p.measurement.distance
           << ", or let the quantiles choose them";
      throw core::ArgumentError("fit", text.str());
    }
    if (band < 0) continue;
    const int parameter = interaction.parameter(a.category, b.category, p.measurement.axis, band);
    if (interaction.saturation(parameter) > 0) {
      // Within one layer: both sides see each other.
      saturated[static_cast<std::size_t>(p.i)].emplace_back(p.j, parameter);
      saturated[static_cast<std::size_t>(p.j)].emplace_back(p.i, parameter);
    } else {
      // Each side counts the pair when its intensity sees the other (both, within a layer).
      if (interaction.sees(a.category, b.category))
        s.per_element[static_cast<std::size_t>(p.i)].add(parameter);
      if (interaction.sees(b.category, a.category))
        s.per_element[static_cast<std::size_t>(p.j)].add(parameter);
    }
    const Interaction::Location where = interaction.locate(parameter);
    ++model.interactions[static_cast<std::size_t>(where.pair)]
          .axes[static_cast<std::size_t>(where.axis)]
          .observed_pairs[static_cast<std::size_t>(where.band)];
  }
  add_saturated_counts(interaction, saturated, s);
  const std::size_t categories = model.categories.size();
  s.data_sum.assign(static_cast<std::size_t>(interaction.parameter_count()), 0.0);
  s.per_category.assign(categories, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Element& e = exemplar.elements[k];
    if (!region.contains(e.position)) continue;
    ++s.data_points;
    ++s.per_category[static_cast<std::size_t>(e.category)];
    s.data_sum[static_cast<std::size_t>(e.category)] += 1.0;
    for (const auto& [parameter, count] : s.per_element[k].counts)
      s.data_sum[static_cast<std::size_t>(parameter)] += count;
  }
  for (std::size_t c = 0; c < categories; ++c) {
    core::check(s.per_category[c] > 0, "fit",
                "the border edge treatment keeps no element of category '" +
                    model.categories[c].name + "' (none lies " +
                    core::describe(interaction.range()) + " inside the window)");
  }
  return s;
}

}  // namespace shapeproc::fit
