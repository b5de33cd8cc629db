#include <algorithm>
#include <cmath>
#include <vector>

#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/fit/detail/quadrature_cell_internal.hpp"
#include "libshapeproc/geometry/domain.hpp"

namespace shapeproc::fit {

using geometry::Vec3;
using model::Interaction;

namespace {

// A place where the statistics change inside the cell: with probability `fraction` the
// neighbour's band is `other_band` (on `other_axis`) instead of the centre's.
struct Cut {
  int neighbour;  // index into the neighbour list
  double fraction;
  int other_band, other_axis;
};

struct Neighbour {
  int category;
  int band, axis;
};

// The axis of a pair seen from a cell's centre, and, where the cell may straddle the boundary
// of its sector (2D, the axis not settled by the boxes), the axis across that boundary and the
// distance to it (`margin`, −1 when there is none).
struct PairAxis {
  int axis;
  int other_axis = -1;
  double margin = -1.0;
};

PairAxis axis_in_cell(const geometry::PairMeasurer& measurer, int shape, int other_shape,
                      const Vec3& offset, double corner, int dimension) {
  PairAxis out{measurer.axis_from_boxes(shape, other_shape, offset, corner)};
  if (out.axis >= 0) return out;
  const Vec3 direction = measurer.direction(shape, other_shape, offset);
  out.axis = measurer.bins().axis_of(direction);
  if (dimension != 2 || measurer.bins().directions() <= 1) return out;
  const double step = 2 * core::kPi / measurer.bins().directions();
  const double angle = std::atan2(direction.y(), direction.x());
  const double sector = std::round(angle / step);
  const long neighbour_sector = static_cast<long>(sector) + (angle > sector * step ? 1 : -1);
  const long half = measurer.bins().directions() / 2;
  out.other_axis = static_cast<int>(((neighbour_sector % half) + half) % half);
  // The angle to the sector boundary becomes a distance in the plane at the rate of a direction
  // between centres, 1/|offset|; the gravitation direction turns at a similar rate, and
  // measuring its own rate would cost one more direction per near pair.
  out.margin = (step / 2 - std::abs(angle - sector * step)) * offset.norm();
  return out;
}

// The distance from `d` to the threshold between `d` and `outside` where the band of the pair
// (a, b) on `axis` changes, by bisection on the band function (bands are monotone in the
// distance).
double crossing_distance(const Interaction& interaction, int a, int b, int axis, double d,
                         double outside) {
  const int band = interaction.band(a, b, axis, d);
  double inside = d;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (inside + outside);
    if (interaction.band(a, b, axis, mid) == band)
      inside = mid;
    else
      outside = mid;
  }
  return std::abs(0.5 * (inside + outside) - d);
}

// The cell's parts: every combination of the first 5 cuts (32 parts at most; further ones keep
// the centre's value), each with its share of the cell and the counts of its neighbours' bands;
// a part where some neighbour is in its hard core is left out.
std::vector<CellPart> combined_parts(const Interaction& interaction, int category,
                                     const std::vector<Neighbour>& neighbours,
                                     const std::vector<Cut>& cuts) {
  std::vector<CellPart> parts;
  const std::size_t used = std::min<std::size_t>(cuts.size(), 5);
  for (std::size_t mask = 0; mask < (std::size_t{1} << used); ++mask) {
    double fraction = 1.0;
    std::vector<Neighbour> state = neighbours;
    for (std::size_t c = 0; c < used; ++c) {
      const Cut& cut = cuts[c];
      if (mask & (std::size_t{1} << c)) {
        fraction *= cut.fraction;
        state[static_cast<std::size_t>(cut.neighbour)].band = cut.other_band;
        state[static_cast<std::size_t>(cut.neighbour)].axis = cut.other_axis;
      } else {
        fraction *= 1.0 - cut.fraction;
      }
    }
    if (fraction <= 0.0) continue;
    model::InteractionCounts counts;
    bool forbidden = false;
    for (const Neighbour& n : state) {
      if (n.band == Interaction::kHardCore) {
        forbidden = true;
        break;
      }
      if (n.band >= 0) counts.add(interaction.parameter(category, n.category, n.axis, n.band));
    }
    if (!forbidden) parts.push_back({fraction, std::move(counts.counts)});
  }
  return parts;
}

}  // namespace

// 3D: each boundary cuts the ball of the cell's measure at its estimated distance.
std::vector<CellPart> integrate_cell_ball(const CellContext& context,
                                          const geometry::Element& dummy, const Vec3& size,
                                          bool* uniform) {
  double measure = 1.0;
  for (int axis = 0; axis < context.dimension; ++axis) measure *= size[axis];
  const double side = std::pow(measure, 1.0 / context.dimension);
  const Interaction& interaction = *context.interaction;
  const geometry::PairMeasurer& measurer = *context.measurer;
  const double cell_measure = context.dimension == 2 ? side * side : side * side * side;
  const double radius = cell_radius(context.dimension, cell_measure);
  // Every point of the cell lies within `corner` of its centre.
  const double corner = 0.5 * side * std::sqrt(static_cast<double>(context.dimension));
  bool near_boundary = false;
  std::vector<Neighbour> neighbours;
  std::vector<Cut> cuts;
  bool hard_core = false;
  context.grid->for_each_candidate(dummy.position, [&](int k) {
    if (hard_core) return;
    const geometry::Element& other = (*context.data)[static_cast<std::size_t>(k)];
    if (!interaction.sees(dummy.category, other.category)) return;
    const double reach = interaction.max_range(dummy.category, other.category);
    const Vec3 offset = geometry::minimum_image(other.position - dummy.position, context.period);
    if (offset.norm() - measurer.radius(dummy.shape) - measurer.radius(other.shape) >=
        reach + corner)
      return;
    auto [lo, hi] = measurer.distance_bounds(dummy.shape, other.shape, offset);
    if (lo >= reach + corner) return;
    const PairAxis pair_axis =
        axis_in_cell(measurer, dummy.shape, other.shape, offset, corner, context.dimension);
    const int axis = pair_axis.axis, other_axis = pair_axis.other_axis;
    const double angular_margin = pair_axis.margin;
    // Thresholds of this axis near [lo, hi] decide whether the exact distance is needed.
    double d = lo;
    bool exact = false;
    auto threshold_near = [&](double low, double high) {
      const int band_low = interaction.band(dummy.category, other.category, axis, low);
      const int band_high = interaction.band(dummy.category, other.category, axis, high);
      return band_low != band_high;
    };
    // With an uncertain axis the other axis's thresholds matter too: measure exactly then.
    if (angular_margin >= 0 || threshold_near(std::max(0.0, lo - corner), hi + corner)) {
      d = measurer.distance(dummy.shape, other.shape, offset, reach + corner);
      exact = true;
    }
    const int band = interaction.band(dummy.category, other.category, axis, d);
    const int index = static_cast<int>(neighbours.size());
    neighbours.push_back({other.category, band, axis});
    bool neighbour_near = false;
    if (exact) {
      // The nearest threshold on either side within the cell.
      const int below =
          interaction.band(dummy.category, other.category, axis, std::max(0.0, d - corner));
      const int above = interaction.band(dummy.category, other.category, axis, d + corner);
      if (below != band || above != band) {
        neighbour_near = true;
        const bool downward = below != band;
        const double x = crossing_distance(interaction, dummy.category, other.category, axis, d,
                                           downward ? std::max(0.0, d - corner) : d + corner);
        const int other_band = downward ? below : above;
        // Only the nearest crossing on that side is modelled; a second one within the cell is rare.
        if (x < radius)
          cuts.push_back(
              {index, cut_fraction(context.dimension, cell_measure, x), other_band, axis});
      }
    }
    if (angular_margin >= 0 && d < reach + corner) {
      const double x = angular_margin;  // already a distance
      if (x < corner) neighbour_near = true;
      if (x < radius) {
        const int other_band = interaction.band(dummy.category, other.category, other_axis, d);
        // Another axis means other parameters even in the same band.
        if (other_band != band || other_band >= 0) {
          cuts.push_back(
              {index, cut_fraction(context.dimension, cell_measure, x), other_band, other_axis});
        }
      }
    }
    near_boundary = near_boundary || neighbour_near;
    if (band == Interaction::kHardCore) {
      bool rescued = false;
      for (const Cut& cut : cuts)
        rescued = rescued || (cut.neighbour == index && cut.other_band != Interaction::kHardCore);
      // Deep inside a hard core (no boundary of this neighbour within the cell) the whole cell is
      // forbidden, whatever the others do.
      if (!rescued && !neighbour_near) {
        hard_core = true;
        near_boundary = false;
      } else if (!rescued) {
        hard_core = true;
      }
    }
  });
  if (uniform) *uniform = !near_boundary;
  if (hard_core) return {};
  return combined_parts(interaction, dummy.category, neighbours, cuts);
}

}  // namespace shapeproc::fit
