#include "libshapeproc/methods/ijiri2008/ring_matching.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "libshapeproc/core/constants.hpp"

namespace shapeproc::methods {

namespace {

std::size_t paired(const ReferenceRing& reference, int shift, std::size_t i) {
  return (static_cast<std::size_t>(shift) + i) % reference.offset.size();
}

}  // namespace

std::vector<int> partial_ring_order(const std::vector<TargetNeighbour>& target) {
  std::vector<int> order(target.size());
  std::iota(order.begin(), order.end(), 0);
  const auto angle = [&](int i) {
    const Vec3& d = target[static_cast<std::size_t>(i)].offset;
    return std::atan2(d.y(), d.x());
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return angle(a) < angle(b); });
  if (order.size() < 2) return order;
  // Start after the widest gap between consecutive neighbours.
  std::size_t start = 0;
  double widest = -1.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const double from = angle(order[k]);
    double to = angle(order[(k + 1) % order.size()]);
    if (k + 1 == order.size()) to += 2.0 * core::kPi;
    if (to - from > widest) {
      widest = to - from;
      start = (k + 1) % order.size();
    }
  }
  std::rotate(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(start), order.end());
  return order;
}

double best_rotation(const std::vector<TargetNeighbour>& target, const ReferenceRing& reference,
                     int shift) {
  double cross = 0.0, dot = 0.0;
  for (std::size_t i = 0; i < target.size(); ++i) {
    const Vec3& r = reference.offset[paired(reference, shift, i)];
    const Vec3& t = target[i].offset;
    cross += r.x() * t.y() - r.y() * t.x();
    dot += r.x() * t.x() + r.y() * t.y();
  }
  return cross == 0.0 && dot == 0.0 ? 0.0 : std::atan2(cross, dot);
}

double matching_error(const std::vector<TargetNeighbour>& target, const ReferenceRing& reference,
                      int shift, double angle, const MatchWeights& weights) {
  const double c = std::cos(angle), s = std::sin(angle);
  double error = 0.0;
  for (std::size_t i = 0; i < target.size(); ++i) {
    const std::size_t j = paired(reference, shift, i);
    const Vec3& r = reference.offset[j];
    const TargetNeighbour& t = target[i];
    const double dx = t.offset.x() - (c * r.x() - s * r.y());
    const double dy = t.offset.y() - (s * r.x() + c * r.y());
    error += weights.distance * std::sqrt(dx * dx + dy * dy) / weights.unit;
    if (t.symbol >= 0 && t.symbol != reference.neighbour_symbol[j]) error += weights.symbol;
    if (t.sub_id == reference.element) error += weights.sub_id;
  }
  return error;
}

RingMatch best_match(const std::vector<TargetNeighbour>& target,
                     const std::vector<ReferenceRing>& references,
                     const std::vector<int>& candidates, RotationMode mode, double field_angle,
                     const MatchWeights& weights, core::Random& random, const MatchFilter& accept) {
  RingMatch best;
  int ties = 0;
  for (const int index : candidates) {
    const ReferenceRing& reference = references[static_cast<std::size_t>(index)];
    if (reference.offset.size() < target.size()) continue;
    const auto shifts = static_cast<int>(reference.offset.size());
    for (int shift = 0; shift < shifts; ++shift) {
      double angle = 0.0;
      if (mode == RotationMode::best) angle = best_rotation(target, reference, shift);
      if (mode == RotationMode::flow_field) angle = field_angle;
      const double error = matching_error(target, reference, shift, angle, weights);
      if (error > best.error) continue;
      if (accept && !accept(reference, angle)) continue;
      if (error < best.error) {
        best = {error, index, shift, angle};
        ties = 1;
      } else if (error == best.error && random.index(static_cast<std::uint64_t>(++ties)) == 0) {
        best = {error, index, shift, angle};
      }
    }
  }
  return best;
}

}  // namespace shapeproc::methods
