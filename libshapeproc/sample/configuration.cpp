#include "libshapeproc/sample/configuration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libshapeproc/core/assert.hpp"
#include "libshapeproc/model/saturation.hpp"

namespace shapeproc::sample {

Configuration::Configuration(const model::Interaction& interaction,
                             const geometry::PairMeasurer& measurer, const OverlapGuard* guard,
                             const geometry::Domain& domain, double reach,
                             const geometry::Box3& grid_box, const Vec3& period)
    : interaction_(interaction),
      measurer_(measurer),
      guard_(guard && guard->active() ? guard : nullptr),
      grid_(grid_box.isEmpty() ? domain.box() : grid_box, domain.dimension(), reach,
            period.isZero()
                ? std::array<bool, 3>{domain.periodic(), domain.periodic(), domain.periodic()}
                : std::array<bool, 3>{period.x() > 0, period.y() > 0, period.z() > 0}),
      period_(period.isZero() ? domain.period() : period) {
  statistics_.assign(static_cast<std::size_t>(interaction.statistic_count()), 0.0);
  shape_distances_ = measurer.options().distance == geometry::DistanceKind::shape;
}

double Configuration::log_interaction(const Element& xi, int skip, std::vector<Link>& links) const {
  near_.clear();
  links.clear();
  // A model without interaction: nothing to measure (the grid, of one cell, would offer every
  // element).
  if (!(interaction_.range() > 0.0)) return 0.0;
  // Candidates nearest first (by the minimum-image distance of reference positions), so that a
  // hard core, most likely with the nearest, rejects after few measurements.
  candidates_.clear();
  grid_.for_each_candidate(xi.position, [&](int slot) {
    if (slot == skip) return;
    const Element& other = elements_[static_cast<std::size_t>(slot)];
    if (!interaction_.sees(xi.category, other.category)) return;
    const Vec3 t = geometry::minimum_image(other.position - xi.position, period_);
    // Shape distances are at least the reference positions' distance minus both radii (t is
    // the nearest image in every coordinate, so no other image is nearer).
    const double squared = t.squaredNorm();
    const double far = interaction_.max_range(xi.category, other.category) +
                       measurer_.radius(xi.shape) + measurer_.radius(other.shape);
    if (!shape_distances_) {
      candidates_.push_back({0.0, squared, slot});
      return;
    }
    if (squared >= far * far) return;
    // (Not dropped on the gap: on a small torus another image of the pair may be nearer.)
    candidates_.push_back({measurer_.box_gap_squared(xi.shape, other.shape, t), squared, slot});
  });
  std::sort(candidates_.begin(), candidates_.end());
  bool forbidden = false;
  for (const Candidate& candidate : candidates_) {
    const int slot = candidate.slot;
    model::PairEffect effect = model::pair_distance_effect(
        interaction_, measurer_, xi, elements_[static_cast<std::size_t>(slot)]);
    if (effect.band == model::Interaction::kHardCore ||
        (guard_ && effect.axis_pending &&
         guard_->overlaps(xi, elements_[static_cast<std::size_t>(slot)], effect.offset,
                          effect.distance))) {
      forbidden = true;
      break;
    }
    if (!effect.axis_pending) continue;
    // A distance some axis holds in its hard core: its axis now, so that a violation rejects
    // before the remaining neighbours are measured (the axis is needed anyway otherwise).
    const Element& other = elements_[static_cast<std::size_t>(slot)];
    if (effect.distance < interaction_.max_hard_core(xi.category, other.category)) {
      model::decide_axis(interaction_, measurer_, xi, other, effect);
      if (effect.band == model::Interaction::kHardCore) {
        forbidden = true;
        break;
      }
    }
    near_.emplace_back(slot, effect);
  }
  if (forbidden) return -std::numeric_limits<double>::infinity();
  // An anchored category lives on its base only: some base lies closer than the reach (an
  // anchor pair's distances are measured to the reach's side).
  if (const int anchor = interaction_.anchor(xi.category); anchor >= 0) {
    const double reach = interaction_.anchor_reach(xi.category);
    const bool on_base = std::any_of(near_.begin(), near_.end(), [&](const auto& near) {
      return elements_[static_cast<std::size_t>(near.first)].category == anchor &&
             near.second.distance < reach;
    });
    if (!on_base) return -std::numeric_limits<double>::infinity();
  }
  double total = 0.0;
  for (auto& [slot, effect] : near_) {
    const Element& other = elements_[static_cast<std::size_t>(slot)];
    model::decide_axis(interaction_, measurer_, xi, other, effect);
    if (effect.band == model::Interaction::kHardCore)
      return -std::numeric_limits<double>::infinity();
    if (effect.band >= 0) {
      const int parameter =
          interaction_.parameter(xi.category, other.category, effect.axis, effect.band);
      const double value = interaction_.log_gamma_of(parameter);
      links.push_back({slot, parameter, value});
      total += value;
    }
  }
  return interaction_.saturated() ? linked_sum(links, skip) : total;
}

int Configuration::links_in(int slot, int parameter, int skip) const {
  int count = 0;
  for (const Link& l : links_[static_cast<std::size_t>(slot)])
    count += l.parameter == parameter && l.slot != skip;
  return count;
}

model::InteractionCounts Configuration::saturated_change(const std::vector<Link>& links,
                                                         int skip) const {
  saturated_.clear();
  for (const Link& l : links)
    if (interaction_.saturation(l.parameter) > 0) saturated_.emplace_back(l.slot, l.parameter);
  if (saturated_.empty()) return {};
  return model::saturated_counts(interaction_, saturated_, [&](int neighbour, int parameter) {
    return links_in(neighbour, parameter, skip);
  });
}

double Configuration::linked_sum(const std::vector<Link>& links, int skip) const {
  double total = 0.0;
  for (const Link& l : links)
    if (interaction_.saturation(l.parameter) == 0) total += l.log_gamma;
  for (const auto& [parameter, count] : saturated_change(links, skip).counts)
    total += interaction_.log_gamma_of(parameter) * count;
  return total;
}

void Configuration::add_saturated_statistics(int slot, const std::vector<Link>& links,
                                             double sign) {
  for (const auto& [parameter, count] : saturated_change(links, slot).counts)
    statistics_[static_cast<std::size_t>(parameter)] += sign * count;
}

void Configuration::add(const Element& e, double local, const std::vector<Link>& links) {
  int slot;
  if (!free_.empty()) {
    slot = free_.back();
    free_.pop_back();
    elements_[static_cast<std::size_t>(slot)] = e;
  } else {
    slot = static_cast<int>(elements_.size());
    elements_.push_back(e);
    links_.emplace_back();
    local_.push_back(0.0);
  }
  position_in_alive_.resize(elements_.size(), -1);
  position_in_alive_[static_cast<std::size_t>(slot)] = static_cast<int>(alive_.size());
  alive_.push_back(slot);
  grid_.insert(slot, e.position);
  statistics_[static_cast<std::size_t>(e.category)] += 1.0;
  if (const int k = interaction_.class_statistic(e.shape); k >= 0)
    statistics_[static_cast<std::size_t>(k)] += 1.0;
  link(slot, local, links);
}

void Configuration::remove(int slot) {
  grid_.remove(slot, elements_[static_cast<std::size_t>(slot)].position);
  const Element& gone = elements_[static_cast<std::size_t>(slot)];
  statistics_[static_cast<std::size_t>(gone.category)] -= 1.0;
  if (const int k = interaction_.class_statistic(gone.shape); k >= 0)
    statistics_[static_cast<std::size_t>(k)] -= 1.0;
  unlink(slot);
  const int rank = position_in_alive_[static_cast<std::size_t>(slot)];
  SHAPEPROC_ASSERT(rank >= 0, "only a live element is removed");
  const int last = alive_.back();
  alive_[static_cast<std::size_t>(rank)] = last;
  position_in_alive_[static_cast<std::size_t>(last)] = rank;
  alive_.pop_back();
  position_in_alive_[static_cast<std::size_t>(slot)] = -1;
  free_.push_back(slot);
}

void Configuration::move(int slot, const Vec3& position, double local,
                         const std::vector<Link>& links) {
  Element& e = elements_[static_cast<std::size_t>(slot)];
  grid_.remove(slot, e.position);
  e.position = position;
  grid_.insert(slot, position);
  unlink(slot);
  link(slot, local, links);
}

void Configuration::statistics_in(const geometry::Box3& region, std::vector<double>& out) const {
  out.assign(statistics_.size(), 0.0);
  // A pair interacting across the torus's seam is not a pair of the window: its elements lie at
  // opposite edges.
  const auto wraps = [&](const Vec3& a, const Vec3& b) {
    const Vec3 direct = b - a;
    return geometry::minimum_image(direct, period_) != direct;
  };
  const auto inside = [&](int slot) {
    return region.contains(elements_[static_cast<std::size_t>(slot)].position);
  };
  for (const int slot : alive_) {
    if (!inside(slot)) continue;
    const Element& e = elements_[static_cast<std::size_t>(slot)];
    out[static_cast<std::size_t>(e.category)] += 1.0;
    if (const int k = interaction_.class_statistic(e.shape); k >= 0)
      out[static_cast<std::size_t>(k)] += 1.0;
    model::InteractionCounts own;  // a saturated band's links of this element: its count t_i
    for (const Link& l : links_[static_cast<std::size_t>(slot)]) {
      if (!inside(l.slot) || wraps(e.position, at(l.slot).position)) continue;
      if (interaction_.saturation(l.parameter) > 0)
        own.add(l.parameter);
      else if (l.slot > slot)
        out[static_cast<std::size_t>(l.parameter)] += 1.0;
    }
    for (const auto& [parameter, count] : own.counts)
      out[static_cast<std::size_t>(parameter)] +=
          std::min(interaction_.saturation(parameter), count);
  }
}

std::vector<Element> Configuration::elements() const {
  std::vector<Element> out;
  std::vector<int> slots = alive_;
  std::sort(slots.begin(), slots.end());  // a deterministic order
  for (int slot : slots) out.push_back(elements_[static_cast<std::size_t>(slot)]);
  return out;
}

void Configuration::link(int slot, double local, const std::vector<Link>& links) {
  local_[static_cast<std::size_t>(slot)] = local;
  links_[static_cast<std::size_t>(slot)] = links;
  for (const Link& l : links) {
    links_[static_cast<std::size_t>(l.slot)].push_back({slot, l.parameter, l.log_gamma});
    if (interaction_.saturation(l.parameter) == 0)
      statistics_[static_cast<std::size_t>(l.parameter)] += 1.0;
  }
  if (interaction_.saturated()) add_saturated_statistics(slot, links, 1.0);
}

void Configuration::unlink(int slot) {
  if (interaction_.saturated())
    add_saturated_statistics(slot, links_[static_cast<std::size_t>(slot)], -1.0);
  for (const Link& l : links_[static_cast<std::size_t>(slot)]) {
    std::vector<Link>& back = links_[static_cast<std::size_t>(l.slot)];
    const auto it =
        std::find_if(back.begin(), back.end(), [&](const Link& b) { return b.slot == slot; });
    SHAPEPROC_ASSERT(it != back.end(), "links are symmetric");
    *it = back.back();
    back.pop_back();
    if (interaction_.saturation(l.parameter) == 0)
      statistics_[static_cast<std::size_t>(l.parameter)] -= 1.0;
  }
  links_[static_cast<std::size_t>(slot)].clear();
}

}  // namespace shapeproc::sample
