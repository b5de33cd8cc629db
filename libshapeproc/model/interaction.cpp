#include "libshapeproc/model/interaction.hpp"

#include <algorithm>
#include <cmath>

namespace shapeproc::model {

namespace {
// The cut-off that measures a pair whose range ends at or below 0 (a hard core alone): any
// positive distance is beyond it.
constexpr double kContactCutoff = 1e-9;
}  // namespace

double Interaction::anchor_reach_of(int a, int b) const {
  if (anchor_[static_cast<std::size_t>(a)] == b) return anchor_reach_[static_cast<std::size_t>(a)];
  if (anchor_[static_cast<std::size_t>(b)] == a) return anchor_reach_[static_cast<std::size_t>(b)];
  return -std::numeric_limits<double>::infinity();
}

Interaction::Interaction(const ShapeProcessModel& model)
    : categories_(static_cast<int>(model.categories.size())) {
  pair_index_.assign(static_cast<std::size_t>(categories_) * static_cast<std::size_t>(categories_),
                     -1);
  parameters_ = categories_;
  for (int c = 0; c < categories_; ++c) {
    locations_.push_back({-1, c, -1});
    theta_.push_back(std::log(model.categories[static_cast<std::size_t>(c)].beta));
    layer_.push_back(model.categories[static_cast<std::size_t>(c)].layer);
    anchor_.push_back(model.categories[static_cast<std::size_t>(c)].anchor);
    anchor_reach_.push_back(model.categories[static_cast<std::size_t>(c)].anchor_reach);
  }
  anchor_band_.assign(static_cast<std::size_t>(categories_), 0);
  saturation_.assign(static_cast<std::size_t>(categories_), 0);
  for (std::size_t p = 0; p < model.interactions.size(); ++p) {
    const PairInteraction& source = model.interactions[p];
    Pair pair;
    pair.min_hard_core = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < source.axes.size(); ++i) {
      const AxisParameters& a = source.axes[i];
      Axis axis;
      axis.thresholds = a.thresholds;
      for (double g : a.gammas) axis.log_gammas.push_back(std::log(g));  // log 0 = −∞
      theta_.insert(theta_.end(), axis.log_gammas.begin(), axis.log_gammas.end());
      axis.first_parameter = parameters_;
      for (std::size_t k = 0; k < a.gammas.size(); ++k) {
        locations_.push_back({static_cast<int>(p), static_cast<int>(i), static_cast<int>(k)});
        saturation_.push_back(a.saturation(k));
        saturated_ = saturated_ || a.saturation(k) > 0;
      }
      // An anchor pair's bands that end at or below the reach: an element in one is on its base.
      const double reach = anchor_reach_of(source.first, source.second);
      for (std::size_t k = 0; k < a.gammas.size(); ++k)
        anchor_band_.push_back(k + 1 < a.thresholds.size() && a.thresholds[k + 1] <= reach);
      parameters_ += static_cast<int>(a.gammas.size());
      pair.min_hard_core = std::min(pair.min_hard_core, a.thresholds.front());
      pair.max_hard_core = std::max(pair.max_hard_core, a.thresholds.front());
      pair.breakpoints.insert(pair.breakpoints.end(), a.thresholds.begin(), a.thresholds.end());
      pair.max_range = std::max(pair.max_range, a.thresholds.back());
      pair.axes.push_back(std::move(axis));
    }
    if (source.axes.empty()) pair.min_hard_core = 0.0;
    // An anchor pair's distances are measured to the side of its reach (the sampler's test).
    if (const double reach = anchor_reach_of(source.first, source.second); std::isfinite(reach))
      pair.breakpoints.push_back(reach);
    std::sort(pair.breakpoints.begin(), pair.breakpoints.end());
    pair.breakpoints.erase(std::unique(pair.breakpoints.begin(), pair.breakpoints.end()),
                           pair.breakpoints.end());
    range_ = std::max(range_, pair.max_range);
    pair_index_[static_cast<std::size_t>(source.first) * static_cast<std::size_t>(categories_) +
                static_cast<std::size_t>(source.second)] = static_cast<int>(pairs_.size());
    pair_index_[static_cast<std::size_t>(source.second) * static_cast<std::size_t>(categories_) +
                static_cast<std::size_t>(source.first)] = static_cast<int>(pairs_.size());
    pairs_.push_back(std::move(pair));
  }
  classes_ = static_cast<int>(model.shape_classes.size());
  if (classes_ > 0)
    for (const ModelShape& shape : model.shapes) class_of_shape_.push_back(shape.shape_class);
}

int Interaction::band(int ca, int cb, int axis, double distance) const {
  const int p = pair_of(ca, cb);
  if (p < 0) return kBeyond;
  const std::vector<double>& d = axis_of(p, axis).thresholds;
  if (distance < d.front()) return kHardCore;
  if (distance >= d.back()) return kBeyond;
  // γ_k on [δ_{k−1}, δ_k): the first threshold strictly above the distance ends the band.
  const auto above = std::upper_bound(d.begin(), d.end(), distance);
  return static_cast<int>(above - d.begin()) - 1;
}

int Interaction::parameter(int ca, int cb, int axis, int band) const {
  return axis_of(pair_of(ca, cb), axis).first_parameter + band;
}

double Interaction::log_gamma(int ca, int cb, int axis, int band) const {
  if (band == kBeyond) return 0.0;
  if (band == kHardCore) return -std::numeric_limits<double>::infinity();
  return axis_of(pair_of(ca, cb), axis).log_gammas[static_cast<std::size_t>(band)];
}

PairEffect pair_distance_effect(const Interaction& interaction,
                                const geometry::PairMeasurer& measurer, const geometry::Element& xi,
                                const geometry::Element& neighbour) {
  PairEffect effect;
  if (!interaction.sees(xi.category, neighbour.category)) return effect;
  const double reach = interaction.max_range(xi.category, neighbour.category);
  const double hard_core = interaction.min_hard_core(xi.category, neighbour.category);
  // A pair with a hard core only (no band) may have its range at 0 or below: it is measured up to
  // a positive cut-off all the same, to tell a violation from contact.
  if (!(reach > 0) && !(hard_core < 0 || reach == 0.0)) return effect;
  const double cutoff = reach > 0 ? reach : kContactCutoff;
  const geometry::Measurement m = measurer.measure_distance(
      xi, neighbour, cutoff, &interaction.breakpoints(xi.category, neighbour.category));
  effect.distance = m.distance;
  effect.offset = m.offset;
  if (m.distance < hard_core) {
    effect.band = Interaction::kHardCore;
    return effect;
  }
  if (m.distance >= reach) return effect;
  effect.axis_pending = true;
  return effect;
}

void decide_axis(const Interaction& interaction, const geometry::PairMeasurer& measurer,
                 const geometry::Element& xi, const geometry::Element& neighbour,
                 PairEffect& effect) {
  if (!effect.axis_pending) return;
  if (interaction.isotropic(xi.category, neighbour.category)) {
    effect.band = interaction.band(xi.category, neighbour.category, 0, effect.distance);
    effect.axis_pending = false;
    return;
  }
  const int known = measurer.axis_from_boxes(xi.shape, neighbour.shape, effect.offset);
  effect.axis = known >= 0 ? known : measurer.axis(xi.shape, neighbour.shape, effect.offset);
  effect.band = interaction.band(xi.category, neighbour.category, effect.axis, effect.distance);
  effect.axis_pending = false;
}

PairEffect pair_effect(const Interaction& interaction, const geometry::PairMeasurer& measurer,
                       const geometry::Element& xi, const geometry::Element& neighbour) {
  PairEffect effect = pair_distance_effect(interaction, measurer, xi, neighbour);
  decide_axis(interaction, measurer, xi, neighbour, effect);
  return effect;
}

bool Interaction::anchored(int category, const std::vector<std::pair<int, int>>& counts) const {
  if (anchor(category) < 0) return true;
  for (const auto& [parameter, count] : counts)
    if (count > 0 && anchor_band(parameter)) return true;
  return false;
}

void InteractionCounts::add(int parameter, int count) {
  if (count == 0) return;
  const auto it = std::lower_bound(counts.begin(), counts.end(), std::make_pair(parameter, 0),
                                   [](const auto& a, const auto& b) { return a.first < b.first; });
  if (it != counts.end() && it->first == parameter) {
    it->second += count;
  } else {
    counts.insert(it, {parameter, count});
  }
}

int InteractionCounts::count_of(int parameter) const {
  const auto it = std::lower_bound(counts.begin(), counts.end(), std::make_pair(parameter, 0),
                                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return it != counts.end() && it->first == parameter ? it->second : 0;
}

double InteractionCounts::dot(const std::vector<double>& theta) const {
  if (hard_core) return -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (const auto& [parameter, count] : counts)
    sum += theta[static_cast<std::size_t>(parameter)] * count;
  return sum;
}

}  // namespace shapeproc::model
