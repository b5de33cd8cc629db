#include "libshapeproc/fit/category_layers.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

#include "libshapeproc/core/format.hpp"
#include "libshapeproc/fit/fit_defaults.hpp"
#include "libshapeproc/fit/quantile.hpp"

namespace shapeproc::fit {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Per category, the median bounding radius of its elements' shapes (0 for points).
std::vector<double> median_radii(const geometry::Scene& exemplar,
                                 const geometry::PairMeasurer& measurer) {
  return category_medians(exemplar,
                          [&](const geometry::Element& e) { return measurer.radius(e.shape); });
}

// nearest[i][a]: the shape distance from element i to the nearest element of category a among
// the measured pairs (∞ when none is within the measurer's cut-off).
std::vector<std::vector<double>> nearest_by_category(
    const geometry::Scene& exemplar, const std::vector<geometry::PairRecord>& pairs) {
  std::vector<std::vector<double>> nearest(
      exemplar.elements.size(), std::vector<double>(exemplar.categories.size(), kInfinity));
  for (const geometry::PairRecord& p : pairs) {
    const auto i = static_cast<std::size_t>(p.i), j = static_cast<std::size_t>(p.j);
    const auto ci = static_cast<std::size_t>(exemplar.elements[i].category);
    const auto cj = static_cast<std::size_t>(exemplar.elements[j].category);
    nearest[i][cj] = std::min(nearest[i][cj], p.measurement.distance);
    nearest[j][ci] = std::min(nearest[j][ci], p.measurement.distance);
  }
  return nearest;
}

// Splits every axis of the pair (a, b) at `distance` (a band with γ 1, to be fitted), unless it
// is a threshold already; an axis whose range ends at or below it is extended to it. False when
// some axis cannot take it (at or below its hard core).
bool split_at(model::ShapeProcessModel& model, int a, int b, double distance) {
  const int index = model.interaction_index(a, b);
  if (index < 0) return false;
  std::vector<model::AxisParameters>& axes =
      model.interactions[static_cast<std::size_t>(index)].axes;
  for (const model::AxisParameters& axis : axes)
    if (axis.thresholds.empty() || !(distance > axis.thresholds.front())) return false;
  for (model::AxisParameters& axis : axes) {
    const auto at = std::lower_bound(axis.thresholds.begin(), axis.thresholds.end(), distance);
    if (at != axis.thresholds.end() && *at == distance) continue;
    // The new band: below `distance` when it splits one, above the last threshold when it
    // extends the range.
    const auto band = at == axis.thresholds.end()
                          ? axis.gammas.size()
                          : static_cast<std::size_t>(at - axis.thresholds.begin() - 1);
    axis.thresholds.insert(at, distance);
    axis.gammas.insert(axis.gammas.begin() + static_cast<std::ptrdiff_t>(band), 1.0);
    axis.gamma_standard_errors.insert(
        axis.gamma_standard_errors.begin() + static_cast<std::ptrdiff_t>(band),
        std::numeric_limits<double>::quiet_NaN());
    axis.status.insert(axis.status.begin() + static_cast<std::ptrdiff_t>(band),
                       model::ParameterStatus::free);
    axis.observed_pairs.insert(axis.observed_pairs.begin() + static_cast<std::ptrdiff_t>(band), 0);
  }
  return true;
}

}  // namespace

std::vector<LayerDependence> layer_dependences(const geometry::Scene& exemplar,
                                               const std::vector<geometry::PairRecord>& pairs,
                                               const geometry::PairMeasurer& measurer,
                                               double share) {
  std::vector<LayerDependence> out;
  const std::size_t categories = exemplar.categories.size();
  if (categories < 2 || share > 1.0) return out;
  const std::vector<double> radius = median_radii(exemplar, measurer);
  const std::vector<std::vector<double>> nearest = nearest_by_category(exemplar, pairs);
  const std::vector<std::size_t> counts = geometry::category_counts(exemplar);
  for (std::size_t c = 0; c < categories; ++c) {
    for (std::size_t a = 0; a < categories; ++a) {
      // Shapes: a larger base that the elements overlap. Points: a base with fewer points, which
      // each point lies within half the base's spacing of.
      const bool points = radius[a] == 0.0 && radius[c] == 0.0;
      if (a == c || (points ? counts[a] >= counts[c] : !(radius[a] > radius[c]))) continue;
      const double contact =
          points ? kFitDefaults.point_contact *
                       std::pow(exemplar.window_measure() / static_cast<double>(counts[a]),
                                1.0 / exemplar.dimension)
                 : 0.0;
      double on = 0.0, count = 0.0, farthest = -kInfinity;
      for (std::size_t i = 0; i < exemplar.elements.size(); ++i) {
        if (static_cast<std::size_t>(exemplar.elements[i].category) != c) continue;
        count += 1.0;
        on += nearest[i][a] < contact ? 1.0 : 0.0;
        farthest = std::max(farthest, nearest[i][a]);
      }
      // Points only on the evidence of all of them (independent points would put about half
      // within that distance), and then anchored: a point's layer is nothing else.
      const double needed = points ? 1.0 : share;
      // Shapes far smaller than another category's come after it whether they overlap it or
      // not (trees before the grass around them), as Ecormier-Nocca et al. place larger discs
      // first: a large element is rarely born into a field of small ones.
      const bool smaller = !points && radius[a] >= kFitDefaults.layer_size_ratio * radius[c];
      if (count > 0 && (on / count >= needed || smaller))
        out.push_back({static_cast<int>(c), static_cast<int>(a), on / count, farthest, contact});
    }
  }
  // A category of points near several sparser ones lies above the sparsest only, its host (the
  // centres of a clustered pattern's clusters rather than a class clustered with it).
  const auto host = [&](const LayerDependence& d) {
    if (d.contact <= 0) return true;
    return std::none_of(out.begin(), out.end(), [&](const LayerDependence& other) {
      const std::size_t a = static_cast<std::size_t>(other.base),
                        b = static_cast<std::size_t>(d.base);
      return other.category == d.category && other.contact > 0 &&
             (counts[a] < counts[b] || (counts[a] == counts[b] && a < b));
    });
  };
  std::vector<LayerDependence> hosts;
  std::copy_if(out.begin(), out.end(), std::back_inserter(hosts), host);
  return hosts;
}

std::vector<std::string> assign_layers(model::ShapeProcessModel& model,
                                       const geometry::Scene& exemplar,
                                       const std::vector<geometry::PairRecord>& pairs,
                                       const geometry::PairMeasurer& measurer, double share) {
  const std::vector<LayerDependence> found = layer_dependences(exemplar, pairs, measurer, share);
  std::vector<std::string> notes;
  if (found.empty()) return notes;
  // Bases are strictly larger (or, of points, fewer), so the dependences have no cycle: each
  // pass settles one more layer.
  for (model::CategoryParameters& c : model.categories) c.layer = 0;
  for (std::size_t pass = 0; pass < model.categories.size(); ++pass)
    for (const LayerDependence& d : found)
      model.categories[static_cast<std::size_t>(d.category)].layer =
          std::max(model.categories[static_cast<std::size_t>(d.category)].layer,
                   model.categories[static_cast<std::size_t>(d.base)].layer + 1);
  const std::vector<double> radius = median_radii(exemplar, measurer);
  for (const LayerDependence& d : found) {
    model::CategoryParameters& c = model.categories[static_cast<std::size_t>(d.category)];
    std::string note =
        "layer " + std::to_string(c.layer) + ": '" + c.name + "' placed after '" +
        model.categories[static_cast<std::size_t>(d.base)].name + "' (" +
        core::format_general(d.share, 2) +
        (d.contact > 0
             ? " of its points lie within " + core::format_general(d.contact, 3) + " of one)"
             : " of its elements overlap or lie inside one, and they "
               "are " +
                   core::format_general(radius[static_cast<std::size_t>(d.base)] /
                                            radius[static_cast<std::size_t>(d.category)],
                                        2) +
                   " times larger)");
    // Every element on a base, or off one by less than the slack: anchored there. The reach is a
    // hair past the farthest, so that its band holds every element.
    const double slack =
        d.contact > 0 ? d.contact
                      : kFitDefaults.anchor_slack * radius[static_cast<std::size_t>(d.category)];
    const double reach =
        d.farthest <= 0 ? 0.0 : d.farthest + 1e-6 * std::max(1.0, std::abs(d.farthest));
    if (c.anchor < 0 && d.farthest <= slack && split_at(model, d.category, d.base, reach)) {
      c.anchor = d.base;
      c.anchor_reach = reach;
      note += "; every one lies within " + core::format_general(reach, 3) +
              " of one, so its intensity is 0 farther off";
    }
    notes.push_back(std::move(note));
  }
  return notes;
}

}  // namespace shapeproc::fit
