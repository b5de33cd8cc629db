#include "libshapeproc/fit/point_counts.hpp"

#include <algorithm>
#include <utility>

#include "libshapeproc/core/assert.hpp"
#include "libshapeproc/model/saturation.hpp"

namespace shapeproc::fit {

namespace {

double largest_radius(const geometry::Scene& exemplar, const geometry::PairMeasurer& measurer) {
  double out = 0.0;
  for (std::size_t s = 0; s < exemplar.shapes.size(); ++s)
    out = std::max(out, measurer.radius(static_cast<int>(s)));
  return out;
}

}  // namespace

PointCounter::PointCounter(const geometry::Scene& exemplar, bool periodic,
                           const geometry::PairMeasurer& measurer,
                           const model::Interaction& interaction,
                           const ExemplarStatistics* statistics)
    : data_(exemplar.elements),
      measurer_(measurer),
      interaction_(interaction),
      statistics_(statistics),
      reach_(interaction.range() + 2 * largest_radius(exemplar, measurer)),
      grid_(exemplar.window, exemplar.dimension, std::max(reach_, 1e-12), periodic) {
  SHAPEPROC_ASSERT(statistics || !interaction.saturated(),
                   "a saturated model's counts read the exemplar's own counts");
  for (std::size_t k = 0; k < data_.size(); ++k)
    grid_.insert(static_cast<int>(k), data_[k].position);
}

bool PointCounter::counts(const geometry::Element& xi, model::InteractionCounts& counts) const {
  counts = {};
  bool allowed = true;
  std::vector<std::pair<int, int>> neighbours;  // (element, θ index) of saturated bands
  grid_.for_each_candidate_within(xi.position, reach_, [&](int j) {
    if (!allowed) return;
    const geometry::Element& other = data_[static_cast<std::size_t>(j)];
    const model::PairEffect effect = model::pair_effect(interaction_, measurer_, xi, other);
    if (effect.band == model::Interaction::kHardCore) allowed = false;
    if (effect.band < 0) return;
    const int parameter =
        interaction_.parameter(xi.category, other.category, effect.axis, effect.band);
    if (interaction_.saturation(parameter) > 0)
      neighbours.emplace_back(j, parameter);
    else
      counts.add(parameter);
  });
  if (!allowed) return false;
  if (!neighbours.empty()) {
    const model::InteractionCounts saturated =
        model::saturated_counts(interaction_, neighbours, [&](int j, int parameter) {
          return statistics_->own_saturated[static_cast<std::size_t>(j)].count_of(parameter);
        });
    for (const auto& [parameter, count] : saturated.counts) counts.add(parameter, count);
  }
  return interaction_.anchored(xi.category, counts.counts);
}

std::vector<CellPart> sampled_cell(const PointCounter& counter, const geometry::Element& xi,
                                   const geometry::Vec3& sizes, int dimension, int k) {
  std::vector<CellPart> parts;
  int points = 1;
  for (int axis = 0; axis < dimension; ++axis) points *= k;
  const double fraction = 1.0 / points;
  geometry::Element at = xi;
  model::InteractionCounts counts;
  for (int index = 0; index < points; ++index) {
    int rest = index;
    for (int axis = 0; axis < dimension; ++axis) {
      at.position[axis] = xi.position[axis] + ((rest % k + 0.5) / k - 0.5) * sizes[axis];
      rest /= k;
    }
    if (!counter.counts(at, counts)) continue;
    parts.push_back({fraction, std::move(counts.counts)});
  }
  return parts;
}

}  // namespace shapeproc::fit
